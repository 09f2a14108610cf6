// Benchmark generator: the suites (which meshes, how many region draws, which gap levels) and the
// meshes (implicit surfaces meshed by CGAL, real models from CGAL's data set, cut and remeshed).

#ifndef SWN_BENCH_GEN_MESHES_H
#define SWN_BENCH_GEN_MESHES_H

#include "gen_common.h"

#include <CGAL/Complex_2_in_triangulation_3.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/make_surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Random.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <array>
#include <cmath>
#include <functional>
#include <iomanip>

namespace swn_bench {

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
  std::string regions = "field";          // field: thresholds of a random field; eigen: of a Laplacian eigenfunction
  bool loops_off_region_curves = false;   // planted loops share no edge with the region curves
};

inline Suite make_suite(const std::string& name)
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
  else if(name == "full" || name == "ablation" || name == "paper")
  {
    // "full": 380 cases (3 random regions per mesh, 2 on the largest ones, 4 gap levels);
    // "ablation": the same 28 meshes of 10k-115k vertices without the larger extra ones, 2 regions
    // per mesh (216 cases), to compare generator settings quickly.
    // "paper": the same meshes as "full" (so they share the mesh cache), regions from Laplacian
    // eigenfunctions, planted loops off the region curves, gap levels calibrated so that the error on
    // simply connected surfaces is comparable to the paper's (RESULTS.md, "The paper suite").
    const bool full = name != "ablation";
    const int k = full ? 3 : 2;
    s.gaps = {0.0, 0.05, 0.15, 0.30};
    if(name == "paper")
    {
      s.gaps = {0.05, 0.08, 0.10};
      s.regions = "eigen";
      s.loops_off_region_curves = true;
    }
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

inline Mesh mesh_implicit(const Function& f, const GPoint& inside, double radius, double facet_size)
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

inline double torus_sdf(double x, double y, double z, double R, double r)
{
  const double q = std::sqrt(x * x + y * y) - R;
  return std::sqrt(q * q + z * z) - r;
}

// A blob: star-shaped around the origin with a smooth random radius (genus 0).
inline Mesh make_blob(int seed, double facet)
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
inline Mesh make_tori(int g, bool ring, double facet)
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

// Rebuilds a mesh from the faces kept by `keep`, keeps the largest connected component.
inline Mesh keep_faces(const Mesh& m, const std::function<bool(FI)>& keep)
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

// Isotropic remeshing to about `target` vertices (keeps the topology).
inline Mesh remesh_to(const Mesh& in, std::size_t target)
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

inline double min_face_area(const Mesh& m)
{
  double mn = 1e300;
  for(FI f : m.faces()) mn = std::min(mn, PMP::face_area(f, m));
  return mn;
}

inline Mesh read_model(const std::string& file)
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

inline void write_off(const Mesh& m, const std::string& file)
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

inline Mesh build_mesh(const Mesh_spec& s, const std::string& cgal_data)
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

} // namespace swn_bench

#endif // SWN_BENCH_GEN_MESHES_H
