// swn_bench_gen: builds the meshes and the cases of the Surface Winding Numbers benchmark.
//
//   swn_bench_gen --suite quick|full|large --out CASES_DIR [--mesh-cache DIR] [--cgal-data DIR] [--shard I/N]
//                 [--gaps per-curve|global] [--straighten on|off]
//   swn_bench_gen --info MESH...        genus, borders, components and size of mesh files
//
// A case is: a mesh (OFF, written once per mesh into the mesh cache), a curve file in the swn tool's
// `# swn halfedges` format, the ground-truth labels (one integer per face, in the mesh's face order),
// the planted nonbounding chain (same format) and meta.json. Everything derives from fixed seeds.
//
// Ground truth: the faces are labelled by thresholding a smooth random field (a sum of a few random
// Gaussians in 3D, widths 10-30 % of the bounding-box diagonal) at the face centroid, at one or two
// levels; the region curve is the jump of these labels, J(gt): on an interior edge e with
// h = halfedge(e), chain(e) = gt(face(h)) - gt(face(opposite(h))) (the library's convention: crossing
// from right to left, W rises by the chain value). On surfaces that are not disks or spheres, a random
// nonempty subset of a homology basis of H1(M, border) is added with random signs: the greedy basis of
// Erickson and Whittlesey (shortest-path tree from a random root, maximum spanning cotree on the dual,
// border loops capped by virtual cones) for the handles, and shortest arcs between border loops.
// Corruption: random runs along the curve (each 1-4 % of the total curve length) are deleted until
// 0, 5, 15 or 30 % of the curve length is gone; the levels are nested (the same deletion order).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Complex_2_in_triangulation_3.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/make_surface_mesh.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Random.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include "swn_io/read_mesh.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <numeric>
#include <queue>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index VI;
typedef Mesh::Halfedge_index HI;
typedef Mesh::Edge_index EI;
typedef Mesh::Face_index FI;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

namespace {

// ------------------------------------------------------------------------------------------------
// Deterministic seeds (std::mt19937_64 and std:: distributions are implementation-defined only for
// the distributions; we use our own uniform helpers so that the cases do not depend on the libstdc++
// version).
std::uint64_t hash_string(const std::string& s, std::uint64_t h = 1469598103934665603ull)
{
  for(unsigned char c : s) { h ^= c; h *= 1099511628211ull; }
  return h;
}

struct Rng
{
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double uniform() { return double(g() >> 11) * (1.0 / 9007199254740992.0); }   // [0,1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  std::size_t index(std::size_t n) { return std::size_t(uniform() * double(n)) % n; }
  bool coin(double p = 0.5) { return uniform() < p; }
};

// ------------------------------------------------------------------------------------------------
// Mesh specifications

struct Mesh_spec
{
  std::string name;      // unique, used for the cache file and the case ids
  std::string kind;      // blob, chain, ring, file
  int param = 0;         // blob: shape seed; chain/ring: number of tori
  std::string file;      // kind == file: model file name in the CGAL data directory
  std::string cut;       // "", "plane" (keep z < cut_level), "holes" (punch small disks)
  int holes = 0;
  std::size_t target_vertices = 10000;
  int region_seeds = 2;  // cases per gap level
};

struct Suite
{
  std::vector<Mesh_spec> meshes;
  std::vector<double> gaps;
};

Suite make_suite(const std::string& name)
{
  Suite s;
  auto add = [&](std::string n, std::string kind, int param, std::string cut, int holes, std::size_t nv, int seeds,
                 std::string file = "") {
    Mesh_spec m;
    m.name = n; m.kind = kind; m.param = param; m.cut = cut; m.holes = holes;
    m.target_vertices = nv; m.region_seeds = seeds; m.file = file;
    s.meshes.push_back(m);
  };
  if(name == "quick")
  {
    s.gaps = {0.0, 0.15};
    add("q_blob", "blob", 0, "", 0, 3000, 2);
    add("q_disk", "blob", 1, "plane", 0, 3000, 1);
    add("q_torus", "chain", 1, "", 0, 3000, 2);
    add("q_chain2", "chain", 2, "", 0, 4000, 2);
    add("q_chain2_holes", "chain", 2, "holes", 2, 4000, 1);
    add("q_plate3", "chain", 3, "plane", 0, 4000, 1);
  }
  else if(name == "full" || name == "ablation")
  {
    // "full": 380 cases (3 random regions per mesh, 2 on the largest ones, 4 gap levels);
    // "ablation": the same 28 meshes of 10k-115k vertices without the larger extra ones, 2 regions
    // per mesh (216 cases), to compare generator settings quickly.
    const bool full = name == "full";
    const int k = full ? 3 : 2;
    s.gaps = {0.0, 0.05, 0.15, 0.30};
    // simply connected (spheres and disks)
    add("blob0", "blob", 0, "", 0, 10000, k);
    add("blob1", "blob", 1, "", 0, 20000, k);
    add("blob2", "blob", 2, "", 0, 30000, k);
    add("blob3", "blob", 3, "", 0, 60000, full ? 2 : 1);
    add("blob4", "blob", 4, "", 0, 100000, full ? 2 : 1);
    add("disk0", "blob", 5, "plane", 0, 12000, k);
    add("disk1", "blob", 6, "plane", 0, 25000, k);
    add("bunny", "file", 0, "", 0, 12000, k, "bunny00.off");
    add("cow_sc", "file", 0, "", 0, 12000, k, "cow.off");
    add("hand", "file", 0, "", 0, 20000, k, "hand.off");
    add("mushroom", "file", 0, "", 0, 10000, k, "mushroom.off");
    if(full)
    {
      add("armadillo", "file", 0, "", 0, 30000, k, "armadillo.off");
      add("bull", "file", 0, "", 0, 15000, k, "bull.off");
    }
    // with handles (genus > 0, or several border loops)
    add("elephant", "file", 0, "", 0, 15000, k, "elephant.off");
    add("pig", "file", 0, "", 0, 15000, k, "pig.off");
    add("torus", "chain", 1, "", 0, 10000, k);
    add("chain2", "chain", 2, "", 0, 12000, k);
    add("chain3", "chain", 3, "", 0, 15000, k);
    add("chain4", "chain", 4, "", 0, 15000, k);
    add("chain5", "chain", 5, "", 0, 18000, k);
    add("ring5", "ring", 5, "", 0, 20000, k);
    add("chain3_holes", "chain", 3, "holes", 3, 12000, k);
    add("plate4", "chain", 4, "plane", 0, 12000, k);
    add("refined_elephant", "file", 0, "", 0, 15000, k, "refined_elephant.off");
    add("eight", "file", 0, "", 0, 10000, k, "eight.off");
    add("3torus", "file", 0, "", 0, 12000, k, "3torus.off");
    add("knot", "file", 0, "", 0, 12000, k, "knot1.off");
    add("anchor", "file", 0, "", 0, 10000, k, "anchor.off");
    add("femur", "file", 0, "", 0, 12000, k, "femur.off");
    add("turbine", "file", 0, "", 0, 12000, k, "turbine.off");
    if(full)
    {
      add("chain3_50k", "chain", 3, "", 0, 50000, 2);
      add("refined_elephant_45k", "file", 0, "", 0, 45000, 2, "refined_elephant.off");
      add("turbine_40k", "file", 0, "", 0, 40000, 2, "turbine.off");
      add("chain6_80k", "chain", 6, "", 0, 80000, 1);
    }
  }
  else if(name == "large")
  {
    // issue 5's large-mesh target: about 1M faces with genus 10 (one case, 5 % gaps); not part of
    // `benchmark/run`, used by benchmark/scaling.sh
    s.gaps = {0.05};
    add("chain10_500k", "chain", 10, "", 0, 500000, 1);
  }
  else
    throw std::runtime_error("unknown suite " + name);
  return s;
}

// ------------------------------------------------------------------------------------------------
// Implicit surfaces

typedef CGAL::Surface_mesh_default_triangulation_3 Tr;
typedef CGAL::Complex_2_in_triangulation_3<Tr> C2t3;
typedef Tr::Geom_traits GT;
typedef GT::Sphere_3 Sphere_3;
typedef GT::Point_3 GPoint;
typedef GT::FT FT;
typedef std::function<FT(GPoint)> Function;
typedef CGAL::Implicit_surface_3<GT, Function> Surface_3;

Mesh mesh_implicit(const Function& f, const GPoint& inside, double radius, double facet_size)
{
  Tr tr;
  C2t3 c2t3(tr);
  Surface_3 surface(f, Sphere_3(inside, radius * radius), 1e-6);
  CGAL::Surface_mesh_default_criteria_3<Tr> criteria(25., facet_size, facet_size * 0.1);
  CGAL::make_surface_mesh(c2t3, surface, criteria, CGAL::Manifold_tag());
  Mesh m;
  CGAL::facets_in_complex_2_to_triangle_mesh(c2t3, m);
  return m;
}

double torus_sdf(double x, double y, double z, double R, double r)
{
  const double q = std::sqrt(x * x + y * y) - R;
  return std::sqrt(q * q + z * z) - r;
}

// A blob: star-shaped around the origin with a smooth random radius (genus 0).
Mesh make_blob(int seed, double facet)
{
  Rng rng(hash_string("blob", seed));
  std::array<double, 12> a;
  for(double& x : a) x = rng.uniform(0, 6.283185307179586);
  const double sx = rng.uniform(1.0, 1.8), sy = rng.uniform(0.8, 1.2);
  Function f = [=](const GPoint& p) {
    const double x = p.x() / sx, y = p.y() / sy, z = p.z();
    const double n = std::sqrt(x * x + y * y + z * z);
    if(n < 1e-12) return FT(-1);
    const double ux = x / n, uy = y / n, uz = z / n;
    const double rho = 1 + 0.18 * std::sin(3 * ux + a[0]) * std::sin(2 * uy + a[1]) * std::cos(2 * uz + a[2]) +
                       0.12 * std::sin(4 * uz + a[3]) * std::cos(3 * ux + a[4]) + 0.08 * std::sin(5 * uy + a[5]);
    return FT(n - rho);
  };
  return mesh_implicit(f, GPoint(0, 0, 0), 3.0, facet);
}

// g tori of major radius 1 and minor radius 0.35 in a row (chain, genus g) or around a circle (ring,
// genus g + 1), smooth union (soft minimum).
Mesh make_tori(int g, bool ring, double facet)
{
  const double R = 1.0, r = 0.35, k = 0.06;
  std::vector<std::array<double, 3>> c;
  if(!ring)
    for(int i = 0; i < g; ++i) c.push_back({2.0 * R * (i - 0.5 * (g - 1)), 0.0, 0.0});
  else
  {
    const double big = R / std::sin(3.141592653589793 / g);   // neighbours touch at their tube circles
    for(int i = 0; i < g; ++i)
    {
      const double t = 2 * 3.141592653589793 * i / g;
      c.push_back({big * std::cos(t), big * std::sin(t), 0.0});
    }
  }
  Function f = [=](const GPoint& p) {
    double s = 0, mn = 1e300;
    std::vector<double> d(c.size());
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      d[i] = torus_sdf(p.x() - c[i][0], p.y() - c[i][1], p.z() - c[i][2], R, r);
      mn = std::min(mn, d[i]);
    }
    for(double di : d) s += std::exp(-(di - mn) / k);
    return FT(mn - k * std::log(s));
  };
  double extent = 0;
  for(auto& ci : c) extent = std::max(extent, std::sqrt(ci[0] * ci[0] + ci[1] * ci[1]));
  const GPoint inside(c[0][0] + R, c[0][1], c[0][2]);
  return mesh_implicit(f, inside, 2 * extent + 2 * (R + r) + 0.5, facet);
}

Mesh to_mesh(const Mesh& in) { return in; }

// Rebuilds a mesh from the faces kept by `keep`, keeps the largest connected component.
Mesh keep_faces(const Mesh& m, const std::function<bool(FI)>& keep)
{
  std::vector<Point> pts(m.points().begin(), m.points().end());
  std::vector<std::vector<std::size_t>> polys;
  for(FI f : m.faces())
    if(keep(f))
    {
      std::vector<std::size_t> p;
      for(VI v : CGAL::vertices_around_face(m.halfedge(f), m)) p.push_back(std::size_t(v));
      polys.push_back(p);
    }
  PMP::repair_polygon_soup(pts, polys);
  PMP::orient_polygon_soup(pts, polys);
  Mesh out;
  PMP::polygon_soup_to_polygon_mesh(pts, polys, out);
  PMP::keep_largest_connected_components(out, 1);
  out.collect_garbage();
  return out;
}

// ------------------------------------------------------------------------------------------------
// Topology

struct Topology
{
  long chi = 0;
  int border_loops = 0, genus = 0, components = 0;
  bool simply_connected() const { return components == 1 && ((chi == 2 && border_loops == 0) || (chi == 1 && border_loops == 1)); }
};

std::vector<std::vector<HI>> border_loops(const Mesh& m)
{
  std::vector<std::vector<HI>> loops;
  std::vector<char> seen(m.number_of_halfedges(), 0);
  for(HI h : m.halfedges())
  {
    if(!m.is_border(h) || seen[std::size_t(h)]) continue;
    std::vector<HI> loop;
    HI x = h;
    do { seen[std::size_t(x)] = 1; loop.push_back(x); x = m.next(x); } while(x != h && !seen[std::size_t(x)]);
    loops.push_back(loop);
  }
  return loops;
}

Topology topology(const Mesh& m)
{
  Topology t;
  t.chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  t.border_loops = int(border_loops(m).size());
  auto fcc = m.property_map<FI, std::size_t>("f:tmp_cc");
  Mesh& mm = const_cast<Mesh&>(m);
  auto cc = mm.add_property_map<FI, std::size_t>("f:bench_cc", 0).first;
  t.components = int(PMP::connected_components(mm, cc));
  mm.remove_property_map(cc);
  (void)fcc;
  t.genus = int((2 * t.components - t.chi - t.border_loops) / 2);
  return t;
}

double mesh_area(const Mesh& m) { return PMP::area(m); }

// Isotropic remeshing to about `target` vertices (keeps the topology).
Mesh remesh_to(const Mesh& in, std::size_t target)
{
  const double A = mesh_area(in);
  double len = std::sqrt(2 * A / (std::sqrt(3.0) * double(target)));
  Mesh out;
  for(int attempt = 0; attempt < 3; ++attempt)
  {
    out = in;
    PMP::isotropic_remeshing(faces(out), len, out, PMP::parameters::number_of_iterations(4));
    out.collect_garbage();
    const double ratio = double(out.number_of_vertices()) / double(target);
    if(ratio > 0.85 && ratio < 1.18) break;
    len *= std::sqrt(ratio);
  }
  return out;
}

double min_face_area(const Mesh& m)
{
  double mn = 1e300;
  for(FI f : m.faces()) mn = std::min(mn, PMP::face_area(f, m));
  return mn;
}

Mesh read_model(const std::string& file)
{
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh(file, m) || m.is_empty())
  {
    // fall back to a polygon soup (some models are not valid polygon meshes as given)
    std::vector<Point> pts;
    std::vector<std::vector<std::size_t>> polys;
    if(!CGAL::IO::read_polygon_soup(file, pts, polys)) throw std::runtime_error("cannot read " + file);
    PMP::repair_polygon_soup(pts, polys);
    PMP::orient_polygon_soup(pts, polys);
    PMP::polygon_soup_to_polygon_mesh(pts, polys, m);
  }
  if(!CGAL::is_triangle_mesh(m)) PMP::triangulate_faces(m);
  PMP::keep_largest_connected_components(m, 1);
  m.collect_garbage();
  return m;
}

void write_off(const Mesh& m, const std::string& file)
{
  const std::string tmp = file + ".tmp";
  {
    std::ofstream os(tmp);
    os << std::setprecision(17);
    os << "OFF\n" << m.number_of_vertices() << ' ' << m.number_of_faces() << " 0\n";
    for(VI v : m.vertices()) os << m.point(v).x() << ' ' << m.point(v).y() << ' ' << m.point(v).z() << '\n';
    for(FI f : m.faces())
    {
      os << 3;
      for(VI v : CGAL::vertices_around_face(m.halfedge(f), m)) os << ' ' << std::size_t(v);
      os << '\n';
    }
    if(!os) throw std::runtime_error("cannot write " + tmp);
  }
  fs::rename(tmp, file);
}

Mesh build_mesh(const Mesh_spec& s, const std::string& cgal_data)
{
  // coarse implicit mesh (facet size from the target), then cut, then isotropic remeshing.
  // The surface mesher draws its initial points from CGAL's default random generator, seeded from
  // the clock: reseed it per mesh so that every mesh is the same in every run and every shard.
  CGAL::get_default_random() = CGAL::Random(unsigned(hash_string(s.name) & 0x7fffffff));
  Mesh m;
  if(s.kind == "blob") m = make_blob(s.param, 0.08);
  else if(s.kind == "chain") m = make_tori(s.param, false, 0.09);
  else if(s.kind == "ring") m = make_tori(s.param, true, 0.09);
  else if(s.kind == "file") m = read_model(cgal_data + "/" + s.file);
  else throw std::runtime_error("unknown mesh kind " + s.kind);
  if(m.is_empty()) throw std::runtime_error(s.name + ": empty mesh");

  if(s.cut == "plane")
  {
    // keep the faces below a horizontal plane: a disk for a blob, a plate with holes for tori
    double zmin = 1e300, zmax = -1e300;
    for(VI v : m.vertices()) { zmin = std::min(zmin, m.point(v).z()); zmax = std::max(zmax, m.point(v).z()); }
    const double level = s.kind == "blob" ? zmin + 0.7 * (zmax - zmin) : 0.5 * (zmin + zmax);
    m = keep_faces(m, [&](FI f) {
      double z = 0;
      for(VI v : CGAL::vertices_around_face(m.halfedge(f), m)) z += m.point(v).z();
      return z / 3 < level;
    });
  }
  else if(s.cut == "holes")
  {
    // punch small disks around random vertices far from each other
    Rng rng(hash_string(s.name + "/holes"));
    std::vector<Point> centers;
    const double radius = 0.15;
    for(int tries = 0; tries < 1000 && int(centers.size()) < s.holes; ++tries)
    {
      const Point p = m.point(VI(Mesh::size_type(rng.index(m.number_of_vertices()))));
      bool ok = true;
      for(const Point& c : centers) ok = ok && std::sqrt(CGAL::squared_distance(p, c)) > 1.0;
      if(ok) centers.push_back(p);
    }
    m = keep_faces(m, [&](FI f) {
      const Point c = CGAL::centroid(m.point(m.source(m.halfedge(f))), m.point(m.target(m.halfedge(f))),
                                     m.point(m.target(m.next(m.halfedge(f)))));
      for(const Point& q : centers)
        if(CGAL::squared_distance(c, q) < radius * radius) return false;
      return true;
    });
  }
  Mesh r = remesh_to(m, s.target_vertices);
  if(min_face_area(r) <= 0) throw std::runtime_error(s.name + ": remeshing left a zero-area face");
  return r;
}

// ------------------------------------------------------------------------------------------------
// Chains on the mesh (per edge index, along halfedge(e))

typedef std::vector<int> Chain;

// Positive along halfedge(e) for e enumerated by edges(m), i.e. along the even halfedge of the edge.
// (In CGAL 5.5, Edge_index(h) remembers h, so halfedge(edge(h)) == h: never compare with that.)
bool is_canonical(HI h) { return (std::size_t(h) & 1) == 0; }

void add_traversal(const Mesh& m, Chain& c, VI a, VI b, int value)
{
  const HI h = m.halfedge(a, b);
  if(h == Mesh::null_halfedge()) throw std::logic_error("not an edge");
  const EI e = m.edge(h);
  c[std::size_t(e)] += is_canonical(h) ? value : -value;
}

// Is the chain D (on interior edges) the jump J F of a face function F? (then D bounds, relative to
// the border: D is null-homologous in H1(M, border)). Border edges are ignored.
bool is_relative_boundary(const Mesh& m, const Chain& D)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<long> F(nf, 0);
  std::vector<char> seen(nf, 0);
  for(FI f0 : m.faces())
  {
    if(seen[std::size_t(f0)]) continue;
    seen[std::size_t(f0)] = 1;
    std::vector<FI> stack{f0};
    while(!stack.empty())
    {
      const FI f = stack.back();
      stack.pop_back();
      for(HI h : CGAL::halfedges_around_face(m.halfedge(f), m))
      {
        const HI o = m.opposite(h);
        if(m.is_border(o)) continue;
        const FI g = m.face(o);
        const EI e = m.edge(h);
        // left face of e is face(halfedge(e)); D = F(left) - F(right)
        const long d = D[std::size_t(e)];
        const long Fg = is_canonical(h) ? F[std::size_t(f)] - d : F[std::size_t(f)] + d;
        if(!seen[std::size_t(g)]) { seen[std::size_t(g)] = 1; F[std::size_t(g)] = Fg; stack.push_back(g); }
        else if(F[std::size_t(g)] != Fg) return false;
      }
    }
  }
  return true;
}

// Is the chain closed relative to the border (no endpoint off the border)?
bool is_closed(const Mesh& m, const Chain& c)
{
  std::vector<long> div(m.number_of_vertices(), 0);
  for(EI e : m.edges())
  {
    const HI h = m.halfedge(e);
    div[std::size_t(m.source(h))] -= c[std::size_t(e)];
    div[std::size_t(m.target(h))] += c[std::size_t(e)];
  }
  for(VI v : m.vertices())
    if(div[std::size_t(v)] != 0 && !m.is_border(v)) return false;
  return true;
}

// The chain of a cyclic vertex sequence (consecutive vertices adjacent).
Chain loop_chain(const Mesh& m, const std::vector<VI>& loop)
{
  Chain c(m.number_of_edges(), 0);
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(loop[i] != loop[(i + 1) % loop.size()]) add_traversal(m, c, loop[i], loop[(i + 1) % loop.size()], 1);
  return c;
}

// Straightens a loop (paper: FlipOut, then snapped back to edges): repeatedly replaces a stretch of
// the loop by the shortest edge path between its ends inside a thin corridor around the stretch
// (a few rings of faces, so the replacement is homotopic), until no stretch gets shorter. Border
// edges are never used. The caller checks that the result is homologous to the input.
std::vector<VI> straighten_loop(const Mesh& m, std::vector<VI> loop, const std::vector<double>& len, Rng& rng)
{
  const std::size_t nv = m.number_of_vertices();
  std::vector<int> stamp(nv, -1), dist_stamp(nv, -1), ring(nv, 0);
  std::vector<double> dist(nv);
  std::vector<HI> par(nv);
  int stamp_id = 0;
  auto edge_len = [&](VI a, VI b) { return len[std::size_t(m.edge(m.halfedge(a, b)))]; };
  for(int pass = 0; pass < 6; ++pass)
  {
    bool improved = false;
    const std::size_t n0 = loop.size();
    if(n0 < 6) break;
    std::rotate(loop.begin(), loop.begin() + std::ptrdiff_t(rng.index(n0)), loop.end());
    const std::size_t k = std::max<std::size_t>(3, std::min<std::size_t>(n0 / 3, 40));
    for(std::size_t start = 0; start + k < loop.size(); start += k / 2)
    {
      // corridor: vertices within 3 rings of the stretch loop[start..start+k]
      ++stamp_id;
      std::vector<VI> frontier;
      double old_len = 0;
      for(std::size_t i = start; i <= start + k; ++i)
      {
        if(stamp[std::size_t(loop[i])] != stamp_id) { stamp[std::size_t(loop[i])] = stamp_id; ring[std::size_t(loop[i])] = 0; frontier.push_back(loop[i]); }
        if(i > start) old_len += edge_len(loop[i - 1], loop[i]);
      }
      for(int r = 1; r <= 3; ++r)
      {
        std::vector<VI> next;
        for(VI x : frontier)
          for(VI y : CGAL::vertices_around_target(m.halfedge(x), m))
            if(stamp[std::size_t(y)] != stamp_id) { stamp[std::size_t(y)] = stamp_id; ring[std::size_t(y)] = r; next.push_back(y); }
        frontier.swap(next);
      }
      // Dijkstra from a to b inside the corridor, over interior edges
      const VI a = loop[start], b = loop[start + k];
      typedef std::pair<double, std::size_t> QE;
      std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
      dist_stamp[std::size_t(a)] = stamp_id;
      dist[std::size_t(a)] = 0;
      q.push({0., std::size_t(a)});
      bool reached = false;
      while(!q.empty())
      {
        auto [d, xi] = q.top();
        q.pop();
        if(d > dist[xi]) continue;
        if(xi == std::size_t(b)) { reached = true; break; }
        const VI x(static_cast<Mesh::size_type>(xi));
        for(HI h : CGAL::halfedges_around_source(x, m))
        {
          if(m.is_border(m.edge(h))) continue;
          const std::size_t y = std::size_t(m.target(h));
          if(stamp[y] != stamp_id) continue;
          const double nd = d + len[std::size_t(m.edge(h))];
          if(dist_stamp[y] != stamp_id || nd < dist[y]) { dist_stamp[y] = stamp_id; dist[y] = nd; par[y] = h; q.push({nd, y}); }
        }
      }
      if(!reached || dist[std::size_t(b)] >= old_len * (1 - 1e-9)) continue;
      std::vector<VI> path;
      for(VI x = b; x != a; x = m.source(par[std::size_t(x)])) path.push_back(x);
      path.push_back(a);
      std::reverse(path.begin(), path.end());   // a ... b
      std::vector<VI> nl(loop.begin(), loop.begin() + std::ptrdiff_t(start));
      nl.insert(nl.end(), path.begin(), path.end());
      nl.insert(nl.end(), loop.begin() + std::ptrdiff_t(start + k + 1), loop.end());
      loop.swap(nl);
      improved = true;
    }
    if(!improved) break;
  }
  return loop;
}

// Greedy homology basis (Erickson-Whittlesey 2005) of the surface with its border loops capped by
// virtual cones, plus shortest arcs between border loops: a basis of H1(M, border) made of chains on
// interior edges. Generators that would use a border edge are dropped.
struct Basis
{
  std::vector<Chain> loops;     // handle loops
  std::vector<std::vector<VI>> loop_vertices;   // the same, as cyclic vertex sequences
  std::vector<Chain> arcs;      // arcs from border loop j to border loop 0
  int dropped = 0;
};

Basis homology_basis(const Mesh& m, Rng& rng)
{
  Basis B;
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  std::vector<double> len(ne);
  for(EI e : m.edges()) len[std::size_t(e)] = std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  const auto loops = border_loops(m);

  // shortest-path tree over interior edges from a random root
  auto dijkstra = [&](const std::vector<VI>& sources, std::vector<double>& dist, std::vector<HI>& parent,
                      const std::vector<char>* stop_at, VI* reached) {
    dist.assign(nv, std::numeric_limits<double>::infinity());
    parent.assign(nv, Mesh::null_halfedge());
    typedef std::pair<double, std::size_t> QE;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
    for(VI s : sources) { dist[std::size_t(s)] = 0; q.push({0., std::size_t(s)}); }
    while(!q.empty())
    {
      auto [d, vi] = q.top();
      q.pop();
      if(d > dist[vi]) continue;
      const VI v(static_cast<Mesh::size_type>(vi));
      if(stop_at && (*stop_at)[vi]) { *reached = v; return; }
      for(HI h : CGAL::halfedges_around_source(v, m))   // h: v -> target(h)
      {
        if(m.is_border(m.edge(h))) continue;
        const std::size_t w = std::size_t(m.target(h));
        const double nd = d + len[std::size_t(m.edge(h))];
        if(nd < dist[w]) { dist[w] = nd; parent[w] = h; q.push({nd, w}); }
      }
    }
  };

  std::vector<double> dist;
  std::vector<HI> parent;
  VI root;
  do root = VI(Mesh::size_type(rng.index(nv))); while(m.is_border(root));
  dijkstra({root}, dist, parent, nullptr, nullptr);
  std::vector<char> in_tree(ne, 0);
  for(std::size_t v = 0; v < nv; ++v)
    if(parent[v] != Mesh::null_halfedge()) in_tree[std::size_t(m.edge(parent[v]))] = 1;

  // dual nodes: faces, then one cone face per border halfedge
  std::map<std::size_t, std::size_t> cone_face;   // border halfedge -> dual node
  std::size_t nnodes = nf;
  for(const auto& L : loops)
    for(HI h : L) cone_face[std::size_t(h)] = nnodes++;
  struct DualEdge { double w; std::size_t a, b; long edge; };   // edge < 0: cone edge
  std::vector<DualEdge> de;
  const double top = std::numeric_limits<double>::max();
  for(EI e : m.edges())
  {
    const HI h = m.halfedge(e), o = m.opposite(h);
    if(m.is_border(e))
    {
      const HI hb = m.is_border(h) ? h : o, hf = m.is_border(h) ? o : h;
      de.push_back({top, std::size_t(m.face(hf)), cone_face[std::size_t(hb)], long(std::size_t(e))});
      continue;
    }
    if(in_tree[std::size_t(e)]) continue;
    const double w = dist[std::size_t(m.source(h))] + len[std::size_t(e)] + dist[std::size_t(m.target(h))];
    de.push_back({std::isfinite(w) ? w : top, std::size_t(m.face(h)), std::size_t(m.face(o)), long(std::size_t(e))});
  }
  for(const auto& L : loops)   // cone edges between consecutive cone faces; the first one is the tree edge
    for(std::size_t i = 1; i < L.size(); ++i)
      de.push_back({top, cone_face[std::size_t(L[i - 1])], cone_face[std::size_t(L[i])], -1});
  std::stable_sort(de.begin(), de.end(), [](const DualEdge& x, const DualEdge& y) { return x.w > y.w; });
  std::vector<std::size_t> uf(nnodes);
  std::iota(uf.begin(), uf.end(), std::size_t(0));
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    while(uf[x] != x) { uf[x] = uf[uf[x]]; x = uf[x]; }
    return x;
  };
  std::vector<long> leftover;
  for(const DualEdge& d : de)
  {
    const std::size_t a = find(d.a), b = find(d.b);
    if(a != b) uf[std::max(a, b)] = std::min(a, b);
    else leftover.push_back(d.edge);
  }
  for(long le : leftover)
  {
    if(le < 0 || m.is_border(EI(Mesh::size_type(le)))) { ++B.dropped; continue; }
    const EI e(static_cast<Mesh::size_type>(le));
    const VI u = m.source(m.halfedge(e)), v = m.target(m.halfedge(e));
    if(!std::isfinite(dist[std::size_t(u)]) || !std::isfinite(dist[std::size_t(v)])) { ++B.dropped; continue; }
    // the loop LCA -> ... -> u -> v -> ... -> LCA as a cyclic vertex sequence
    std::vector<VI> up_u{u}, up_v{v};
    for(VI x = u; x != root; x = m.source(parent[std::size_t(x)])) up_u.push_back(m.source(parent[std::size_t(x)]));
    for(VI x = v; x != root; x = m.source(parent[std::size_t(x)])) up_v.push_back(m.source(parent[std::size_t(x)]));
    while(up_u.size() > 1 && up_v.size() > 1 && up_u[up_u.size() - 2] == up_v[up_v.size() - 2]) { up_u.pop_back(); up_v.pop_back(); }
    std::vector<VI> loop(up_u.rbegin(), up_u.rend());   // LCA ... u
    loop.insert(loop.end(), up_v.begin(), up_v.end() - 1);   // v ... (before LCA)
    Chain c = loop_chain(m, loop);
    if(!is_closed(m, c)) { std::cerr << "[gen] internal error: open basis loop\n"; ++B.dropped; continue; }
    B.loop_vertices.push_back(loop);
    B.loops.push_back(c);
  }

  // arcs from border loop j to border loop 0
  if(loops.size() >= 2)
  {
    std::vector<char> in_loop0(nv, 0);
    for(HI h : loops[0]) in_loop0[std::size_t(m.target(h))] = 1;
    for(std::size_t j = 1; j < loops.size(); ++j)
    {
      std::vector<VI> src;
      for(HI h : loops[j]) src.push_back(m.target(h));
      VI reached;
      std::vector<double> d2;
      std::vector<HI> p2;
      reached = Mesh::null_vertex();
      dijkstra(src, d2, p2, &in_loop0, &reached);
      if(reached == Mesh::null_vertex()) { ++B.dropped; continue; }
      Chain c(ne, 0);
      for(VI x = reached; p2[std::size_t(x)] != Mesh::null_halfedge(); x = m.source(p2[std::size_t(x)]))
        add_traversal(m, c, m.source(p2[std::size_t(x)]), x, 1);
      B.arcs.push_back(c);
    }
  }
  return B;
}

// ------------------------------------------------------------------------------------------------
// Cases

struct Case_files
{
  std::string id;
  std::string dir;
};

std::string json_escape(const std::string& s)
{
  std::string o;
  for(char c : s)
  {
    if(c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o;
}

void write_halfedge_chain(const Mesh& m, const Chain& c, const std::string& file)
{
  std::ofstream os(file);
  os << "# swn halfedges\n";
  for(EI e : m.edges())
  {
    const int v = c[std::size_t(e)];
    if(v == 0) continue;
    const HI h = m.halfedge(e);
    if(v > 0) os << "h " << std::size_t(m.source(h)) << ' ' << std::size_t(m.target(h)) << ' ' << v << '\n';
    else os << "h " << std::size_t(m.target(h)) << ' ' << std::size_t(m.source(h)) << ' ' << -v << '\n';
  }
  if(!os) throw std::runtime_error("cannot write " + file);
}

// Deletion order of curve edges: random runs along the curve. `subset` lists the curve edges where the
// runs start and stay (a connected component of the curve, or all of it); each run has a length
// uniform in [run_min, run_max] times the subset's length and grows alternately at both ends along
// curve edges that are not deleted yet. Returns (edge, cumulative deleted length / subset length),
// up to half of the subset.
std::vector<std::pair<std::size_t, double>> deletion_order(const Mesh& m, const std::vector<std::size_t>& subset,
                                                           const std::vector<double>& len,
                                                           const std::vector<std::vector<std::size_t>>& at,
                                                           double run_min, double run_max, Rng& rng)
{
  double total = 0;
  for(std::size_t e : subset) total += len[e];
  std::vector<std::pair<std::size_t, double>> order;
  std::map<std::size_t, char> deleted;
  std::set<std::size_t> in_subset(subset.begin(), subset.end());
  double cum = 0;
  std::size_t remaining = subset.size();
  while(remaining > 0 && cum < 0.5 * total)
  {
    std::size_t e0;
    do e0 = subset[rng.index(subset.size())]; while(deleted.count(e0));
    const double run = rng.uniform(run_min, run_max) * total;
    double got = 0;
    const EI ee0(static_cast<Mesh::size_type>(e0));
    std::size_t ends[2] = {std::size_t(m.vertex(ee0, 0)), std::size_t(m.vertex(ee0, 1))};
    auto del = [&](std::size_t e) {
      deleted[e] = 1;
      --remaining;
      got += len[e];
      cum += len[e];
      order.push_back({e, cum / total});
    };
    del(e0);
    int side = 0, stuck = 0;
    while(got < run && stuck < 2 && cum < 0.5 * total)
    {
      std::size_t& x = ends[side];
      std::vector<std::size_t> cand;
      for(std::size_t e : at[x])
        if(!deleted.count(e) && in_subset.count(e)) cand.push_back(e);
      if(cand.empty()) { ++stuck; side = 1 - side; continue; }
      const std::size_t e = cand[rng.index(cand.size())];
      const EI ee(static_cast<Mesh::size_type>(e));
      x = std::size_t(m.vertex(ee, 0)) == x ? std::size_t(m.vertex(ee, 1)) : std::size_t(m.vertex(ee, 0));
      del(e);
      stuck = 0;
      side = 1 - side;
    }
  }
  return order;
}

// Deletion plan of the whole curve: (edge, fraction) pairs; gap level L deletes the edges whose
// fraction is <= L. mode "per-curve": every connected component of the curve loses the fraction L of
// its own length (runs of 5-15 % of the component), so no curve disappears entirely; mode "global":
// runs of 1-4 % of the total curve length anywhere until L of the total is gone.
std::vector<std::pair<std::size_t, double>> deletion_plan(const Mesh& m, const Chain& c, const std::string& mode, Rng& rng,
                                                          double& total)
{
  const std::size_t ne = m.number_of_edges();
  std::vector<double> len(ne, 0);
  std::vector<std::size_t> curve;
  std::vector<std::vector<std::size_t>> at(m.number_of_vertices());
  total = 0;
  for(EI e : m.edges())
    if(c[std::size_t(e)] != 0)
    {
      len[std::size_t(e)] = std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
      total += len[std::size_t(e)];
      curve.push_back(std::size_t(e));
      at[std::size_t(m.vertex(e, 0))].push_back(std::size_t(e));
      at[std::size_t(m.vertex(e, 1))].push_back(std::size_t(e));
    }
  if(curve.empty()) return {};
  if(mode == "global") return deletion_order(m, curve, len, at, 0.01, 0.04, rng);
  // connected components of the curve (edges sharing a vertex)
  std::map<std::size_t, std::size_t> comp;
  std::vector<std::vector<std::size_t>> comps;
  for(std::size_t e0 : curve)
  {
    if(comp.count(e0)) continue;
    comps.emplace_back();
    std::vector<std::size_t> stack{e0};
    comp[e0] = comps.size() - 1;
    while(!stack.empty())
    {
      const std::size_t e = stack.back();
      stack.pop_back();
      comps.back().push_back(e);
      const EI ee(static_cast<Mesh::size_type>(e));
      for(int k = 0; k < 2; ++k)
        for(std::size_t f : at[std::size_t(m.vertex(ee, k))])
          if(!comp.count(f)) { comp[f] = comps.size() - 1; stack.push_back(f); }
    }
  }
  std::vector<std::pair<std::size_t, double>> plan;
  for(auto& cc : comps)
  {
    std::sort(cc.begin(), cc.end());
    const auto o = deletion_order(m, cc, len, at, 0.05, 0.15, rng);
    plan.insert(plan.end(), o.begin(), o.end());
  }
  return plan;
}

struct Options
{
  std::string suite = "quick", out, mesh_cache, cgal_data;
  std::string gap_mode = "per-curve";   // per-curve | global
  bool straighten = true;
  int shard = 0, nshards = 1;
};

void generate(const Options& o)
{
  const Suite suite = make_suite(o.suite);
  fs::create_directories(o.out);
  const std::string mesh_cache = o.mesh_cache.empty() ? o.out + "/meshes" : o.mesh_cache;
  fs::create_directories(mesh_cache);
  std::ofstream index(o.out + "/index.tsv");
  for(std::size_t mi = 0; mi < suite.meshes.size(); ++mi)
  {
    if(int(mi % std::size_t(o.nshards)) != o.shard) continue;
    const Mesh_spec& spec = suite.meshes[mi];
    const auto t0 = std::chrono::steady_clock::now();
    const std::string mesh_file = fs::absolute(mesh_cache + "/" + spec.name + "_" + std::to_string(spec.target_vertices) + ".off").string();
    Mesh m;
    if(!fs::exists(mesh_file))
    {
      if(spec.kind == "file" && o.cgal_data.empty())
      {
        std::cerr << "[gen] skipping " << spec.name << ": no --cgal-data directory\n";
        continue;
      }
      // Each mesh is built by a fresh process of this program, with address-space randomization off
      // when possible: CGAL's surface mesher orders some work by memory addresses, so a mesh built
      // after another one in the same process (or with another memory layout) can differ slightly.
      const std::string self = fs::read_symlink("/proc/self/exe").string();
      std::string cmd = "'" + self + "' --build-mesh '" + spec.name + "' --suite '" + o.suite + "' --cgal-data '" +
                        o.cgal_data + "' --mesh-out '" + mesh_file + "'";
      if(std::system("setarch \"$(uname -m)\" -R true >/dev/null 2>&1") == 0) cmd = "setarch \"$(uname -m)\" -R " + cmd;
      if(std::system(cmd.c_str()) != 0 || !fs::exists(mesh_file))
      {
        std::cerr << "[gen] skipping " << spec.name << ": the mesh could not be built\n";
        continue;
      }
    }
    CGAL::Surface_winding_numbers::IO::read_mesh(mesh_file, m);   // the exact mesh the solver will read
    const Topology topo = topology(m);
    const double t_mesh = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cerr << "[gen] " << spec.name << ": " << m.number_of_vertices() << " vertices, " << m.number_of_faces()
              << " faces, genus " << topo.genus << ", " << topo.border_loops << " border loop(s), "
              << topo.components << " component(s), " << t_mesh << " s\n";

    // face centroids and areas
    const std::size_t nf = m.number_of_faces();
    std::vector<Point> cen(nf);
    std::vector<double> area(nf);
    double total_area = 0;
    for(FI f : m.faces())
    {
      const HI h = m.halfedge(f);
      cen[std::size_t(f)] = CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
      area[std::size_t(f)] = PMP::face_area(f, m);
      total_area += area[std::size_t(f)];
    }
    std::vector<double> edge_len(m.number_of_edges());
    for(EI e : m.edges()) edge_len[std::size_t(e)] = std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
    const auto bb = CGAL::bounding_box(m.points().begin(), m.points().end());
    const double diag = std::sqrt(CGAL::squared_distance(bb.min(), bb.max()));

    for(int rs = 0; rs < spec.region_seeds; ++rs)
    {
      Rng rng(hash_string(spec.name + "/regions/" + std::to_string(rs)));
      // smooth random field: a few Gaussians centred on the surface
      std::vector<int> gt(nf, 0);
      for(int attempt = 0; attempt < 20; ++attempt)
      {
        const int K = 3 + int(rng.index(4));
        std::vector<Point> c;
        std::vector<double> s, a;
        for(int k = 0; k < K; ++k)
        {
          c.push_back(m.point(VI(Mesh::size_type(rng.index(m.number_of_vertices())))));
          s.push_back(rng.uniform(0.10, 0.30) * diag);
          a.push_back((rng.coin() ? 1 : -1) * rng.uniform(0.5, 1.5));
        }
        std::vector<double> val(nf);
        for(std::size_t f = 0; f < nf; ++f)
        {
          double x = 0;
          for(int k = 0; k < K; ++k) x += a[k] * std::exp(-CGAL::squared_distance(cen[f], c[k]) / (2 * s[k] * s[k]));
          val[f] = x;
        }
        // thresholds at area quantiles
        std::vector<std::size_t> ord(nf);
        std::iota(ord.begin(), ord.end(), std::size_t(0));
        std::sort(ord.begin(), ord.end(), [&](std::size_t x, std::size_t y) { return val[x] < val[y]; });
        auto quantile = [&](double q) {
          double acc = 0;
          for(std::size_t i : ord) { acc += area[i]; if(acc >= q * total_area) return val[i]; }
          return val[ord.back()];
        };
        const double q1 = rng.uniform(0.35, 0.7);
        const double th1 = quantile(q1);
        const bool two = rng.coin(0.4);
        const double th2 = two ? quantile(q1 + rng.uniform(0.3, 0.8) * (1 - q1)) : 1e300;
        for(std::size_t f = 0; f < nf; ++f) gt[f] = (val[f] > th1 ? 1 : 0) + (val[f] > th2 ? 1 : 0);
        double a1 = 0;
        for(std::size_t f = 0; f < nf; ++f) if(gt[f] > 0) a1 += area[f];
        if(a1 > 0.05 * total_area && a1 < 0.95 * total_area) break;
      }
      // region chain J(gt)
      Chain region(m.number_of_edges(), 0);
      for(EI e : m.edges())
      {
        if(m.is_border(e)) continue;
        const HI h = m.halfedge(e);
        region[std::size_t(e)] = gt[std::size_t(m.face(h))] - gt[std::size_t(m.face(m.opposite(h)))];
      }
      // planted nonbounding loops
      Chain planted(m.number_of_edges(), 0);
      int n_loops = 0, n_arcs = 0, basis_size = 0, dropped = 0, straightened = 0;
      bool planted_nontrivial = true;
      if(!topo.simply_connected())
      {
        Basis B = homology_basis(m, rng);
        basis_size = int(B.loops.size() + B.arcs.size());
        if(o.straighten)
          for(std::size_t i = 0; i < B.loops.size(); ++i)
          {
            const std::vector<VI> sl = straighten_loop(m, B.loop_vertices[i], edge_len, rng);
            const Chain c2 = loop_chain(m, sl);
            Chain d(c2.size());
            for(std::size_t e = 0; e < d.size(); ++e) d[e] = c2[e] - B.loops[i][e];
            if(is_closed(m, c2) && is_relative_boundary(m, d)) { B.loops[i] = c2; ++straightened; }
          }
        dropped = B.dropped;
        std::vector<std::pair<int, const Chain*>> all;
        for(const Chain& c : B.loops) all.push_back({0, &c});
        for(const Chain& c : B.arcs) all.push_back({1, &c});
        if(!all.empty())
        {
          const std::size_t k = 1 + rng.index(all.size());
          for(std::size_t i = all.size(); i > 1; --i) std::swap(all[i - 1], all[rng.index(i)]);
          for(std::size_t i = 0; i < k; ++i)
          {
            const int sgn = rng.coin() ? 1 : -1;
            for(std::size_t e = 0; e < planted.size(); ++e) planted[e] += sgn * (*all[i].second)[e];
            (all[i].first == 0 ? n_loops : n_arcs)++;
          }
          planted_nontrivial = !is_relative_boundary(m, planted);
        }
      }
      Chain full(m.number_of_edges(), 0);
      for(std::size_t e = 0; e < full.size(); ++e) full[e] = region[e] + planted[e];
      double curve_length = 0;
      Rng grng(hash_string(spec.name + "/gaps/" + std::to_string(rs)));
      const auto plan = deletion_plan(m, full, o.gap_mode, grng, curve_length);
      std::size_t curve_edges = 0, planted_edges = 0, planted_shared = 0, planted_cancelled = 0;
      for(int v : full) curve_edges += v != 0;
      for(std::size_t e = 0; e < planted.size(); ++e)
        if(planted[e] != 0)
        {
          ++planted_edges;
          planted_shared += region[e] != 0;
          planted_cancelled += full[e] == 0;
        }

      for(double gap : suite.gaps)
      {
        Chain c = full;
        double removed = 0;
        for(const auto& [e, frac] : plan)
          if(frac <= gap + 1e-12)
          {
            c[e] = 0;
            removed += std::sqrt(CGAL::squared_distance(m.point(m.vertex(EI(Mesh::size_type(e)), 0)),
                                                        m.point(m.vertex(EI(Mesh::size_type(e)), 1))));
          }
        std::ostringstream id;
        id << spec.name << "_r" << rs << "_g" << std::setw(2) << std::setfill('0') << int(std::lround(gap * 100));
        const std::string dir = fs::absolute(o.out + "/cases/" + id.str()).string();
        fs::create_directories(dir);
        write_halfedge_chain(m, c, dir + "/curve.txt");
        write_halfedge_chain(m, planted, dir + "/planted.txt");
        {
          std::ofstream os(dir + "/labels_gt.txt");
          for(int l : gt) os << l << '\n';
        }
        std::ofstream js(dir + "/meta.json");
        js << std::setprecision(10) << "{\"case\": \"" << id.str() << "\", \"mesh\": \"" << spec.name
           << "\", \"mesh_file\": \"" << json_escape(mesh_file) << "\", \"source\": \""
           << (spec.kind == "file" ? "cgal-data:" + spec.file : spec.kind + (spec.cut.empty() ? "" : "+" + spec.cut))
           << "\", \"vertices\": " << m.number_of_vertices() << ", \"faces\": " << nf
           << ", \"genus\": " << topo.genus << ", \"border_loops\": " << topo.border_loops
           << ", \"simply_connected\": " << (topo.simply_connected() ? "true" : "false")
           << ", \"region_seed\": " << rs << ", \"gap_level\": " << gap
           << ", \"gap_fraction\": " << (curve_length > 0 ? removed / curve_length : 0)
           << ", \"curve_edges_full\": " << curve_edges << ", \"curve_length\": " << curve_length
           << ", \"max_gt_label\": " << *std::max_element(gt.begin(), gt.end())
           << ", \"planted_loops\": " << n_loops << ", \"planted_arcs\": " << n_arcs
           << ", \"planted_edges\": " << planted_edges << ", \"basis_size\": " << basis_size
           << ", \"basis_dropped\": " << dropped << ", \"loops_straightened\": " << straightened
           << ", \"planted_shared_edges\": " << planted_shared << ", \"planted_cancelled_edges\": " << planted_cancelled
           << ", \"gap_mode\": \"" << o.gap_mode << "\", \"straighten\": " << (o.straighten ? "true" : "false")
           << ", \"planted_nontrivial\": " << (planted_nontrivial ? "true" : "false") << "}\n";
        index << id.str() << '\t' << dir << '\n';
      }
    }
  }
}

void info(const std::vector<std::string>& files)
{
  for(const std::string& f : files)
  {
    try
    {
      Mesh m = read_model(f);
      const Topology t = topology(m);
      std::cout << fs::path(f).filename().string() << ": V " << m.number_of_vertices() << " F " << m.number_of_faces()
                << " genus " << t.genus << " border_loops " << t.border_loops << " min_area " << min_face_area(m) << "\n";
    }
    catch(const std::exception& e) { std::cout << f << ": error " << e.what() << "\n"; }
  }
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  std::vector<std::string> info_files;
  bool info_mode = false;
  std::string build_mesh_name, mesh_out;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc) throw std::runtime_error("missing value after " + a);
      return argv[++i];
    };
    try
    {
      if(a == "--suite") o.suite = next();
      else if(a == "--out") o.out = next();
      else if(a == "--mesh-cache") o.mesh_cache = next();
      else if(a == "--cgal-data") o.cgal_data = next();
      else if(a == "--shard")
      {
        const std::string s = next();
        const auto slash = s.find('/');
        o.shard = std::stoi(s.substr(0, slash));
        o.nshards = std::stoi(s.substr(slash + 1));
        if(o.nshards < 1 || o.shard < 0 || o.shard >= o.nshards) throw std::runtime_error("bad --shard " + s);
      }
      else if(a == "--gaps") { o.gap_mode = next(); if(o.gap_mode != "per-curve" && o.gap_mode != "global") throw std::runtime_error("--gaps per-curve|global"); }
      else if(a == "--straighten") { const std::string v = next(); if(v != "on" && v != "off") throw std::runtime_error("--straighten on|off"); o.straighten = v == "on"; }
      else if(a == "--info") info_mode = true;
      else if(a == "--build-mesh") build_mesh_name = next();
      else if(a == "--mesh-out") mesh_out = next();
      else if(info_mode) info_files.push_back(a);
      else throw std::runtime_error("unknown argument " + a);
    }
    catch(const std::exception& e)
    {
      std::cerr << "swn_bench_gen: " << e.what() << "\n";
      return 2;
    }
  }
  try
  {
    if(info_mode) { info(info_files); return 0; }
    if(!build_mesh_name.empty())
    {
      // internal: build one mesh of the suite in this fresh process and write it (see generate())
      for(const Mesh_spec& spec : make_suite(o.suite).meshes)
        if(spec.name == build_mesh_name)
        {
          const Mesh m = build_mesh(spec, o.cgal_data);
          write_off(m, mesh_out);
          return 0;
        }
      throw std::runtime_error("no mesh " + build_mesh_name + " in suite " + o.suite);
    }
    if(o.out.empty()) throw std::runtime_error("--out is required");
    generate(o);
  }
  catch(const std::exception& e)
  {
    std::cerr << "swn_bench_gen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
