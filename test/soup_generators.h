// Test mesh generators for the Surface Winding Numbers oracle tests (soups; mesh_generators.h adds
// soup-level chains and the FaceListGraph built from a soup).
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

#ifndef SWN_TEST_SOUP_GENERATORS_H
#define SWN_TEST_SOUP_GENERATORS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

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

} // namespace swn_test

#endif // SWN_TEST_SOUP_GENERATORS_H
