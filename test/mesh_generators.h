// Test mesh generators for the Surface Winding Numbers oracle tests.
//
// Every generator returns a triangle soup (points + index triples) whose triangles are
// oriented counter-clockwise when seen from the outside (closed surfaces) or from +z
// (planar meshes).  Besides the geometry, a soup remembers for each vertex and each face
// its *unjittered* parameter coordinates in grid units, so that tests can select regions
// (inside / outside of a loop, bands, sectors ...) combinatorially, independently of the
// random jitter and of the random choice of diagonals.
//
// Grid conventions (all indices are soup vertex indices, 0-based):
//   disk    (n x n cells on [0,1]^2)     vertex (i,j) = point (i/n, j/n), i,j in [0,n];
//                                        face param = cell centre (i+1/2, j+1/2).
//   torus   (nu x nv, R, r)              vertex (i,j): u = 2 pi i/nu around the axis, v = 2 pi j/nv
//                                        around the tube; P = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v).
//                                        (u,v) is positively oriented w.r.t. the outward normal, so
//                                        a path with increasing v (a meridian) has the cells of smaller u on its left.
//   annulus (nr x nt, radii 0.5 .. 1)    vertex (k,t): radius 0.5 + 0.5 k/nr, angle 2 pi t/nt; (k,t) is
//                                        positively oriented w.r.t. +z.
//   sphere  (UV, nlat bands x nlon)      vertex 0 = north pole, ring p = 1..nlat-1 has nlon vertices,
//                                        last vertex = south pole. A ring walked with increasing
//                                        longitude has the northern cap on its left.
//
// Meshes are built with CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh into any
// FaceListGraph (Surface_mesh, Polyhedron_3); Built_mesh keeps the soup index <-> descriptor maps.

#ifndef SWN_TEST_MESH_GENERATORS_H
#define SWN_TEST_MESH_GENERATORS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace swn_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Index = std::size_t;
using Triangle = std::array<Index, 3>;
using Param = std::array<double, 2>;

constexpr double kPi = 3.14159265358979323846;

// ------------------------------------------------------------------------------------------
// Soup
// ------------------------------------------------------------------------------------------

struct Soup
{
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  std::vector<Param> vparam;      // unjittered parameter coordinates of each vertex (grid units)
  std::vector<Param> fparam;      // unjittered parameter centre of each face (grid units)
  std::vector<int> fcomponent;    // component id of each face (0 unless built by combine())

  std::size_t num_vertices() const { return points.size(); }
  std::size_t num_faces() const { return triangles.size(); }

  std::vector<std::vector<Index>> polygons() const
  {
    std::vector<std::vector<Index>> p;
    p.reserve(triangles.size());
    for(const Triangle& t : triangles) p.push_back({t[0], t[1], t[2]});
    return p;
  }
};

inline void add_triangle(Soup& s, Index a, Index b, Index c, const Param& centre)
{
  s.triangles.push_back({a, b, c});
  s.fparam.push_back(centre);
  s.fcomponent.push_back(0);
}

// Splits the quad (a,b,c,d), given counter-clockwise, into two CCW triangles along one of
// its two diagonals.
inline void add_quad(Soup& s, Index a, Index b, Index c, Index d, bool diagonal_ac, const Param& centre)
{
  if(diagonal_ac) { add_triangle(s, a, b, c, centre); add_triangle(s, a, c, d, centre); }
  else            { add_triangle(s, a, b, d, centre); add_triangle(s, b, c, d, centre); }
}

// The random numbers of a generator, from one engine: the jitter, uniform in [-1, 1], and the
// diagonal of each quad (the order of the draws is part of every generated mesh).
struct Generator_random
{
  explicit Generator_random(unsigned seed) : rng(seed) {}
  double jitter() { return U(rng); }
  // the diagonal (a, c) of the next quad: at random, or always
  bool diagonal_ac(bool random_diagonals) { return random_diagonals ? coin(rng) : true; }

  std::mt19937 rng;
  std::uniform_real_distribution<double> U{-1., 1.};
  std::bernoulli_distribution coin{0.5};
};

// The ni x nj cells of a grid of vertices vid(i, j), each split into two triangles (add_quad, quad
// (i,j), (i+1,j), (i+1,j+1), (i,j+1), face centre (i + 1/2, j + 1/2)), walked row by row (j outer)
// or, with i_outer, column by column.
template <class Vid>
void add_grid_cells(Soup& s, int ni, int nj, bool i_outer, const Vid& vid, Generator_random& random, bool random_diagonals)
{
  for(int a = 0; a < (i_outer ? ni : nj); ++a)
    for(int b = 0; b < (i_outer ? nj : ni); ++b)
    {
      const int i = i_outer ? a : b, j = i_outer ? b : a;
      add_quad(s, vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1), random.diagonal_ac(random_diagonals),
               {i + 0.5, j + 0.5});
    }
}

// ------------------------------------------------------------------------------------------
// Disk: unit square, n x n cells, random diagonals, tangential jitter.
// `jitter` is the maximal displacement per coordinate as a fraction of the cell size; 0.2
// keeps every triangle positively oriented. Boundary vertices only slide along the boundary,
// corner vertices stay put.
// ------------------------------------------------------------------------------------------

inline Index disk_vid(int n, int i, int j) { return Index(j) * Index(n + 1) + Index(i); }

inline Soup make_disk(int n, unsigned seed = 1, double jitter = 0.2, bool random_diagonals = true)
{
  Soup s;
  Generator_random random(seed);
  const double h = 1. / n;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      double dx = jitter * random.jitter(), dy = jitter * random.jitter();
      if(i == 0 || i == n) dx = 0;
      if(j == 0 || j == n) dy = 0;
      s.points.emplace_back((i + dx) * h, (j + dy) * h, 0.);
      s.vparam.push_back({double(i), double(j)});
    }
  add_grid_cells(s, n, n, false, [n](int i, int j) { return disk_vid(n, i, j); }, random, random_diagonals);
  return s;
}

// CCW (seen from +z) axis-aligned rectangle loop with grid corners (i0,j0)-(i1,j1), i0<i1, j0<j1.
// Returned as a vertex cycle without repeating the first vertex.
inline std::vector<Index> disk_rect_loop(int n, int i0, int j0, int i1, int j1)
{
  std::vector<Index> l;
  for(int i = i0; i < i1; ++i) l.push_back(disk_vid(n, i, j0));
  for(int j = j0; j < j1; ++j) l.push_back(disk_vid(n, i1, j));
  for(int i = i1; i > i0; --i) l.push_back(disk_vid(n, i, j1));
  for(int j = j1; j > j0; --j) l.push_back(disk_vid(n, i0, j));
  return l;
}

// Vertical path along x = i from row j0 to row j1 (upwards if j0 < j1).
inline std::vector<Index> disk_vertical_path(int n, int i, int j0, int j1)
{
  std::vector<Index> p;
  const int step = j1 >= j0 ? 1 : -1;
  for(int j = j0;; j += step) { p.push_back(disk_vid(n, i, j)); if(j == j1) break; }
  return p;
}

// ------------------------------------------------------------------------------------------
// Torus of revolution, nu x nv cells, random diagonals, jitter in (u,v).
// ------------------------------------------------------------------------------------------

inline int wrap(int a, int m) { return ((a % m) + m) % m; }

inline Index torus_vid(int nu, int nv, int i, int j) { return Index(wrap(j, nv)) * Index(nu) + Index(wrap(i, nu)); }

inline Soup make_torus(int nu, int nv, unsigned seed = 1, double jitter = 0.2, bool random_diagonals = true,
                       double R = 1.0, double r = 0.4)
{
  Soup s;
  Generator_random random(seed);
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
    {
      const double u = 2 * kPi * (i + jitter * random.jitter()) / nu;
      const double v = 2 * kPi * (j + jitter * random.jitter()) / nv;
      s.points.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
      s.vparam.push_back({double(i), double(j)});
    }
  add_grid_cells(s, nu, nv, false, [nu, nv](int i, int j) { return torus_vid(nu, nv, i, j); }, random, random_diagonals);
  return s;
}

// Meridian (loop around the tube) at u-index i, walked with increasing v: cells of smaller u on its left.
inline std::vector<Index> torus_meridian(int nu, int nv, int i)
{
  std::vector<Index> l;
  for(int j = 0; j < nv; ++j) l.push_back(torus_vid(nu, nv, i, j));
  return l;
}

// Longitude (loop around the axis) at v-index j, walked with increasing u: cells of larger v on its left.
inline std::vector<Index> torus_longitude(int nu, int nv, int j)
{
  std::vector<Index> l;
  for(int i = 0; i < nu; ++i) l.push_back(torus_vid(nu, nv, i, j));
  return l;
}

// CCW (w.r.t. the outward normal) rectangle in the (u,v) grid, corners (i0,j0)-(i1,j1).
inline std::vector<Index> torus_rect_loop(int nu, int nv, int i0, int j0, int i1, int j1)
{
  std::vector<Index> l;
  for(int i = i0; i < i1; ++i) l.push_back(torus_vid(nu, nv, i, j0));
  for(int j = j0; j < j1; ++j) l.push_back(torus_vid(nu, nv, i1, j));
  for(int i = i1; i > i0; --i) l.push_back(torus_vid(nu, nv, i, j1));
  for(int j = j1; j > j0; --j) l.push_back(torus_vid(nu, nv, i0, j));
  return l;
}

// ------------------------------------------------------------------------------------------
// Planar annulus, radii 0.5 .. 1, nr radial x nt angular cells, jitter in (radius, angle);
// boundary vertices only move along their circle.
// ------------------------------------------------------------------------------------------

inline Index annulus_vid(int nr, int nt, int k, int t) { (void)nr; return Index(k) * Index(nt) + Index(wrap(t, nt)); }

inline Soup make_annulus(int nr, int nt, unsigned seed = 1, double jitter = 0.2, bool random_diagonals = true,
                         double r0 = 0.5, double r1 = 1.0)
{
  Soup s;
  Generator_random random(seed);
  for(int k = 0; k <= nr; ++k)
    for(int t = 0; t < nt; ++t)
    {
      double dk = jitter * random.jitter(), dt = jitter * random.jitter();
      if(k == 0 || k == nr) dk = 0;
      const double rho = r0 + (r1 - r0) * (k + dk) / nr;
      const double th = 2 * kPi * (t + dt) / nt;
      s.points.emplace_back(rho * std::cos(th), rho * std::sin(th), 0.);
      s.vparam.push_back({double(k), double(t)});
    }
  add_grid_cells(s, nr, nt, true, [nr, nt](int k, int t) { return annulus_vid(nr, nt, k, t); }, random, random_diagonals);
  return s;
}

// Radial path at angle index t from radius index k0 to k1 (outwards if k0 < k1).
inline std::vector<Index> annulus_radial_path(int nr, int nt, int t, int k0, int k1)
{
  std::vector<Index> p;
  const int step = k1 >= k0 ? 1 : -1;
  for(int k = k0;; k += step) { p.push_back(annulus_vid(nr, nt, k, t)); if(k == k1) break; }
  return p;
}

// Path along the circle of radius index k from angle index t0 to t1 (CCW if t0 < t1).
inline std::vector<Index> annulus_circle_path(int nr, int nt, int k, int t0, int t1)
{
  std::vector<Index> p;
  const int step = t1 >= t0 ? 1 : -1;
  for(int t = t0;; t += step) { p.push_back(annulus_vid(nr, nt, k, t)); if(t == t1) break; }
  return p;
}

// Full CCW circle of radius index k, as a vertex cycle starting at angle index t0.
inline std::vector<Index> annulus_circle_loop(int nr, int nt, int k, int t0 = 0)
{
  std::vector<Index> l;
  for(int t = 0; t < nt; ++t) l.push_back(annulus_vid(nr, nt, k, t0 + t));
  return l;
}

// ------------------------------------------------------------------------------------------
// UV sphere (unit radius), nlat latitude bands x nlon longitudes, jitter in (polar, azimuth)
// angles of the non-pole vertices; points stay on the sphere. Face param = (q + 1/2, p + 1/2)
// with q the longitude cell and p the latitude band (0 = northern cap).
// ------------------------------------------------------------------------------------------

inline Index sphere_vid(int nlat, int nlon, int p, int q)
{
  if(p <= 0) return 0;
  if(p >= nlat) return Index(1) + Index(nlat - 1) * Index(nlon);
  return Index(1) + Index(p - 1) * Index(nlon) + Index(wrap(q, nlon));
}

inline Soup make_uv_sphere(int nlat, int nlon, unsigned seed = 1, double jitter = 0.2, bool random_diagonals = true)
{
  Soup s;
  Generator_random random(seed);
  s.points.emplace_back(0., 0., 1.);
  s.vparam.push_back({0., 0.});
  for(int p = 1; p < nlat; ++p)
    for(int q = 0; q < nlon; ++q)
    {
      const double th = kPi * (p + jitter * random.jitter()) / nlat;
      const double ph = 2 * kPi * (q + jitter * random.jitter()) / nlon;
      s.points.emplace_back(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      s.vparam.push_back({double(q), double(p)});
    }
  s.points.emplace_back(0., 0., -1.);
  s.vparam.push_back({0., double(nlat)});
  const Index N = 0, S = s.points.size() - 1;
  for(int q = 0; q < nlon; ++q)
    add_triangle(s, N, sphere_vid(nlat, nlon, 1, q), sphere_vid(nlat, nlon, 1, q + 1), {q + 0.5, 0.5});
  for(int p = 1; p + 1 < nlat; ++p)
    for(int q = 0; q < nlon; ++q)
    {
      // CCW in the (east, north) frame: (p+1,q) -> (p+1,q+1) -> (p,q+1) -> (p,q)
      add_quad(s, sphere_vid(nlat, nlon, p + 1, q), sphere_vid(nlat, nlon, p + 1, q + 1),
               sphere_vid(nlat, nlon, p, q + 1), sphere_vid(nlat, nlon, p, q), random.diagonal_ac(random_diagonals),
               {q + 0.5, p + 0.5});
    }
  for(int q = 0; q < nlon; ++q)
    add_triangle(s, S, sphere_vid(nlat, nlon, nlat - 1, q + 1), sphere_vid(nlat, nlon, nlat - 1, q),
                 {q + 0.5, nlat - 0.5});
  return s;
}

// Latitude ring p (1 <= p < nlat) walked eastwards: the northern cap is on its left.
inline std::vector<Index> sphere_ring(int nlat, int nlon, int p)
{
  std::vector<Index> l;
  for(int q = 0; q < nlon; ++q) l.push_back(sphere_vid(nlat, nlon, p, q));
  return l;
}

// ------------------------------------------------------------------------------------------
// Soup transformations
// ------------------------------------------------------------------------------------------

// Disjoint union; the vertices of b are renumbered by + a.num_vertices() and translated.
// Face components: a keeps its ids, b's ids are shifted past a's maximum.
inline Soup combine(const Soup& a, const Soup& b, double tx = 0, double ty = 0, double tz = 0)
{
  Soup s = a;
  const Index off = a.points.size();
  int coff = 0;
  for(int c : a.fcomponent) coff = std::max(coff, c + 1);
  for(const Point_3& p : b.points) s.points.emplace_back(p.x() + tx, p.y() + ty, p.z() + tz);
  s.vparam.insert(s.vparam.end(), b.vparam.begin(), b.vparam.end());
  for(std::size_t f = 0; f < b.triangles.size(); ++f)
  {
    const Triangle& t = b.triangles[f];
    s.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    s.fparam.push_back(b.fparam[f]);
    s.fcomponent.push_back(b.fcomponent[f] + coff);
  }
  return s;
}

// Applies x -> scale * Rot(axis, angle) x + t to every point (a similarity).
inline Soup transformed(const Soup& in, double scale, std::array<double, 3> axis, double angle,
                        std::array<double, 3> t)
{
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
  const double c = std::cos(angle), s = std::sin(angle), C = 1 - c;
  const double Rm[3][3] = {{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
                           {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
                           {z * x * C - y * s, z * y * C + x * s, c + z * z * C}};
  Soup out = in;
  for(Point_3& p : out.points)
  {
    const double v[3] = {p.x(), p.y(), p.z()};
    double r[3];
    for(int i = 0; i < 3; ++i) r[i] = scale * (Rm[i][0] * v[0] + Rm[i][1] * v[1] + Rm[i][2] * v[2]) + t[i];
    p = Point_3(r[0], r[1], r[2]);
  }
  return out;
}

// The same surface with vertices and faces renumbered at random and every triangle's vertex
// list rotated (orientation kept). new_vertex[old] and new_face[old] give the new indices.
struct Permuted_soup
{
  Soup soup;
  std::vector<Index> new_vertex, new_face;
};

inline Permuted_soup permuted(const Soup& in, unsigned seed)
{
  std::mt19937 rng(seed);
  Permuted_soup p;
  const std::size_t nv = in.num_vertices(), nf = in.num_faces();
  std::vector<Index> old_of_new_v(nv), old_of_new_f(nf);
  for(Index i = 0; i < nv; ++i) old_of_new_v[i] = i;
  for(Index i = 0; i < nf; ++i) old_of_new_f[i] = i;
  std::shuffle(old_of_new_v.begin(), old_of_new_v.end(), rng);
  std::shuffle(old_of_new_f.begin(), old_of_new_f.end(), rng);
  p.new_vertex.resize(nv);
  p.new_face.resize(nf);
  for(Index i = 0; i < nv; ++i) p.new_vertex[old_of_new_v[i]] = i;
  for(Index i = 0; i < nf; ++i) p.new_face[old_of_new_f[i]] = i;
  for(Index i = 0; i < nv; ++i)
  {
    p.soup.points.push_back(in.points[old_of_new_v[i]]);
    p.soup.vparam.push_back(in.vparam[old_of_new_v[i]]);
  }
  std::uniform_int_distribution<int> rot(0, 2);
  for(Index i = 0; i < nf; ++i)
  {
    const Triangle& t = in.triangles[old_of_new_f[i]];
    const int r = rot(rng);
    p.soup.triangles.push_back({p.new_vertex[t[r]], p.new_vertex[t[(r + 1) % 3]], p.new_vertex[t[(r + 2) % 3]]});
    p.soup.fparam.push_back(in.fparam[old_of_new_f[i]]);
    p.soup.fcomponent.push_back(in.fcomponent[old_of_new_f[i]]);
  }
  return p;
}

inline double triangle_area(const Soup& s, std::size_t f)
{
  const Triangle& t = s.triangles[f];
  return std::sqrt(CGAL::to_double(CGAL::squared_area(s.points[t[0]], s.points[t[1]], s.points[t[2]])));
}

// Minimal signed area of the soup's triangles projected on the xy-plane (planar meshes): a
// positive value certifies that the jitter kept all triangles CCW.
inline double min_signed_xy_area(const Soup& s)
{
  double m = std::numeric_limits<double>::infinity();
  for(const Triangle& t : s.triangles)
  {
    const Point_3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    m = std::min(m, 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x())));
  }
  return m;
}

// Minimal ratio (normal . (centroid - centre)) / |normal| over all triangles of a surface that
// is star-shaped w.r.t. the origin (sphere); positive means all triangles face outwards.
inline double min_outward_ratio_sphere(const Soup& s)
{
  double m = std::numeric_limits<double>::infinity();
  for(const Triangle& t : s.triangles)
  {
    const Point_3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    Kernel::Vector_3 nrm = CGAL::cross_product(b - a, c - a);
    Kernel::Vector_3 cen = (a - CGAL::ORIGIN) + (b - CGAL::ORIGIN) + (c - CGAL::ORIGIN);
    m = std::min(m, (nrm * cen) / std::sqrt(nrm.squared_length() * cen.squared_length()));
  }
  return m;
}

// ------------------------------------------------------------------------------------------
// Soup-level chains: integer 1-chains keyed by the undirected soup edge {a,b}, a < b, with the
// value counted along a -> b. They are independent of the mesh data structure and of its
// edge orientation, so expected and computed chains can be compared directly.
// ------------------------------------------------------------------------------------------

using Edge_key = std::pair<Index, Index>;
using Soup_chain = std::map<Edge_key, int>;

inline Edge_key edge_key(Index a, Index b) { return a < b ? Edge_key(a, b) : Edge_key(b, a); }

inline void add_segment(Soup_chain& c, Index a, Index b, int m = 1)
{
  if(a == b) throw std::invalid_argument("add_segment: degenerate segment");
  int& v = c[edge_key(a, b)];
  v += (a < b) ? m : -m;
  if(v == 0) c.erase(edge_key(a, b));
}

// Open polyline p0 -> p1 -> ... -> p_{n-1}.
inline void add_path(Soup_chain& c, const std::vector<Index>& path, int m = 1)
{
  for(std::size_t k = 0; k + 1 < path.size(); ++k) add_segment(c, path[k], path[k + 1], m);
}

// Closed loop l0 -> l1 -> ... -> l_{n-1} -> l0 (first vertex not repeated).
inline void add_loop(Soup_chain& c, const std::vector<Index>& loop, int m = 1)
{
  for(std::size_t k = 0; k < loop.size(); ++k) add_segment(c, loop[k], loop[(k + 1) % loop.size()], m);
}

// The loop with `gap` consecutive edges removed, starting with the edge (l[start], l[start+1]):
// returned as the open path l[start+gap] -> ... -> l[start] (indices mod n).
inline std::vector<Index> loop_with_gap(const std::vector<Index>& loop, std::size_t start, std::size_t gap)
{
  const std::size_t n = loop.size();
  std::vector<Index> p;
  for(std::size_t k = 0; k + gap <= n; ++k) p.push_back(loop[(start + gap + k) % n]);
  return p;
}

// The path with `gap` consecutive edges removed, starting with edge (p[start], p[start+1]):
// returned as two open paths.
inline std::pair<std::vector<Index>, std::vector<Index>> path_with_gap(const std::vector<Index>& path,
                                                                       std::size_t start, std::size_t gap)
{
  std::vector<Index> a(path.begin(), path.begin() + start + 1);
  std::vector<Index> b(path.begin() + start + gap, path.end());
  return {a, b};
}

inline std::vector<Index> reversed(std::vector<Index> p) { std::reverse(p.begin(), p.end()); return p; }

inline Soup_chain scaled(const Soup_chain& c, int m)
{
  Soup_chain r;
  if(m == 0) return r;
  for(const auto& kv : c) r[kv.first] = kv.second * m;
  return r;
}

inline Soup_chain sum(const Soup_chain& a, const Soup_chain& b)
{
  Soup_chain r = a;
  for(const auto& kv : b)
  {
    int& v = r[kv.first];
    v += kv.second;
    if(v == 0) r.erase(kv.first);
  }
  return r;
}

inline Soup_chain difference(const Soup_chain& a, const Soup_chain& b) { return sum(a, scaled(b, -1)); }

// Boundary 0-chain: arrivals minus departures, per vertex (only nonzero entries).
inline std::map<Index, int> boundary(const Soup_chain& c)
{
  std::map<Index, int> d;
  for(const auto& kv : c) { d[kv.first.second] += kv.second; d[kv.first.first] -= kv.second; }
  for(auto it = d.begin(); it != d.end();) it = (it->second == 0) ? d.erase(it) : std::next(it);
  return d;
}

inline std::string to_string(const Soup_chain& c)
{
  std::string s = "{";
  for(const auto& kv : c)
    s += " (" + std::to_string(kv.first.first) + "->" + std::to_string(kv.first.second) + "):" + std::to_string(kv.second);
  return s + " }";
}

// ------------------------------------------------------------------------------------------
// Building a FaceListGraph from a soup, with soup index <-> descriptor maps.
// ------------------------------------------------------------------------------------------

template <class TM>
struct Built_mesh
{
  using GT = boost::graph_traits<TM>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  TM tm;
  Soup soup;
  std::vector<vertex_descriptor> vertex;                // soup vertex -> descriptor
  std::vector<face_descriptor> face;                    // soup triangle -> descriptor
  std::unordered_map<vertex_descriptor, Index> vindex;  // descriptor -> soup vertex
  std::unordered_map<face_descriptor, Index> findex;    // descriptor -> soup triangle
  bool vertex_order_preserved = false;                  // soup order == vertices(tm) order
  bool face_order_preserved = false;                    // soup order == faces(tm) order
  // Reference halfedge of each edge: halfedge(e, tm) for the descriptor e met while iterating
  // over edges(tm). (CGAL 5.5's Surface_mesh::Edge_index stores a halfedge, so
  // halfedge(edge(h, tm), tm) == h for both halfedges of an edge: only descriptors coming from
  // edges(tm) give the reference direction.)
  std::unordered_map<halfedge_descriptor, bool> is_reference;

  Built_mesh() = default;
  Built_mesh(const Built_mesh&) = delete;               // descriptors point into tm
  Built_mesh& operator=(const Built_mesh&) = delete;

  // The soup edge key of a mesh edge, and the sign that converts a value along halfedge(e)
  // into a value along key.first -> key.second.
  std::pair<Edge_key, int> key(edge_descriptor e) const
  {
    halfedge_descriptor h = reference_halfedge(e);
    const Index s = vindex.at(source(h, tm)), t = vindex.at(target(h, tm));
    return {edge_key(s, t), s < t ? 1 : -1};
  }

  halfedge_descriptor reference_halfedge(edge_descriptor e) const
  {
    halfedge_descriptor h = halfedge(e, tm);
    return is_reference.at(h) ? h : opposite(h, tm);
  }

  // +1 if h is the reference halfedge of its edge, -1 otherwise
  int sign(halfedge_descriptor h) const { return is_reference.at(h) ? 1 : -1; }

  halfedge_descriptor halfedge_of(Index a, Index b) const
  {
    auto r = halfedge(vertex.at(a), vertex.at(b), tm);   // halfedge a -> b
    if(!r.second) throw std::invalid_argument("soup vertices " + std::to_string(a) + " and " + std::to_string(b) + " are not adjacent");
    return r.first;
  }
};

// Builds `out` from `soup`. Throws std::runtime_error if the soup is not a valid polygon mesh
// or if the soup <-> mesh correspondence cannot be established.
template <class TM>
void build(const Soup& soup, Built_mesh<TM>& out)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using BM = Built_mesh<TM>;
  using vertex_descriptor = typename BM::vertex_descriptor;
  using face_descriptor = typename BM::face_descriptor;

  out.soup = soup;
  std::vector<std::vector<Index>> polys = soup.polygons();
  if(!PMP::is_polygon_soup_a_polygon_mesh(polys)) throw std::runtime_error("soup is not a polygon mesh");
  PMP::polygon_soup_to_polygon_mesh(soup.points, polys, out.tm);
  if(num_vertices(out.tm) != soup.points.size() || num_faces(out.tm) != soup.triangles.size())
    throw std::runtime_error("polygon_soup_to_polygon_mesh changed the element counts");

  auto vpm = get(CGAL::vertex_point, out.tm);
  // vertices: insertion order is expected to be preserved; verify on coordinates, fall back
  // to a coordinate lookup (all soup points are distinct in our generators) otherwise.
  out.vertex.clear();
  out.vertex_order_preserved = true;
  {
    Index i = 0;
    for(vertex_descriptor v : vertices(out.tm))
    {
      if(i >= soup.points.size() || get(vpm, v) != soup.points[i]) out.vertex_order_preserved = false;
      out.vertex.push_back(v);
      ++i;
    }
  }
  if(!out.vertex_order_preserved)
  {
    std::map<Point_3, Index> by_point;
    for(Index i = 0; i < soup.points.size(); ++i)
      if(!by_point.emplace(soup.points[i], i).second) throw std::runtime_error("duplicate soup points");
    std::vector<vertex_descriptor> vs(soup.points.size());
    for(vertex_descriptor v : vertices(out.tm)) vs.at(by_point.at(get(vpm, v))) = v;
    out.vertex = vs;
  }
  out.vindex.clear();
  for(Index i = 0; i < out.vertex.size(); ++i) out.vindex[out.vertex[i]] = i;

  out.is_reference.clear();
  for(auto e : edges(out.tm))
  {
    out.is_reference[halfedge(e, out.tm)] = true;
    out.is_reference[opposite(halfedge(e, out.tm), out.tm)] = false;
  }

  // faces: match on the cyclic vertex sequence (this also checks the orientation).
  std::map<std::array<Index, 3>, Index> by_cycle;
  auto canonical = [](std::array<Index, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  for(Index f = 0; f < soup.triangles.size(); ++f) by_cycle[canonical(soup.triangles[f])] = f;
  out.face.assign(soup.triangles.size(), face_descriptor());
  out.findex.clear();
  out.face_order_preserved = true;
  Index count = 0;
  for(face_descriptor f : faces(out.tm))
  {
    std::array<Index, 3> t;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, out.tm), out.tm))
    {
      if(k == 3) throw std::runtime_error("non-triangle face");
      t[k++] = out.vindex.at(v);
    }
    auto it = by_cycle.find(canonical(t));
    if(it == by_cycle.end()) throw std::runtime_error("mesh face not found in soup (orientation flipped?)");
    if(it->second != count) out.face_order_preserved = false;
    out.face[it->second] = f;
    out.findex[f] = it->second;
    ++count;
  }
  if(out.findex.size() != soup.triangles.size()) throw std::runtime_error("face correspondence incomplete");
}

} // namespace swn_test

#endif // SWN_TEST_MESH_GENERATORS_H
