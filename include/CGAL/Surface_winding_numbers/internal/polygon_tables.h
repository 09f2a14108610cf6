// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Flat tables from polygons: a polygon soup, or a FaceGraph with faces of more than three sides.
// Every polygon is triangulated; the diagonals added inside a polygon are "virtual" edges (no curve
// runs along them, the residual function may not jump across them, and the outputs are reported per
// input polygon and per input edge).

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_POLYGON_TABLES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_POLYGON_TABLES_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Twice the signed area of triangle (a, b, c) projected along the normal n.
inline double projected_area(const double* a, const double* b, const double* c, const double* n)
{
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return n[0] * (u[1] * v[2] - u[2] * v[1]) + n[1] * (u[2] * v[0] - u[0] * v[2]) + n[2] * (u[0] * v[1] - u[1] * v[0]);
}

// Triangles of a polygon (corners given by their indices into `points`, xyz), in the polygon's
// orientation, as positions in the polygon. Triangles are returned as they are; a quadrilateral is
// cut along its shorter diagonal; larger polygons by ear clipping in the plane of their Newell normal
// (the ear of largest projected area that contains no other corner, so that collinear corners do
// not make flat triangles while a better ear exists). Never fails: a polygon whose projection
// degenerates is cut as a fan, and any flat triangle is reported later by the geometry check.
inline std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<double>& points,
                                                                   const std::vector<std::size_t>& corners)
{
  const std::size_t n = corners.size();
  std::vector<std::array<std::size_t, 3>> out;
  auto P = [&](std::size_t k) { return &points[3 * corners[k]]; };
  auto d2 = [&](std::size_t a, std::size_t b) {
    const double *p = P(a), *q = P(b);
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
  };
  if(n == 3) return {{0, 1, 2}};
  if(n == 4)
  {
    if(d2(0, 2) <= d2(1, 3)) return {{0, 1, 2}, {0, 2, 3}};
    return {{1, 2, 3}, {1, 3, 0}};
  }
  double normal[3] = {0, 0, 0};   // Newell
  for(std::size_t k = 0; k < n; ++k)
  {
    const double *p = P(k), *q = P((k + 1) % n);
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  std::vector<std::size_t> ring(n);
  for(std::size_t k = 0; k < n; ++k) ring[k] = k;
  while(ring.size() > 3)
  {
    const std::size_t r = ring.size();
    std::size_t best = npos;
    double best_area = 0;
    for(std::size_t i = 0; i < r; ++i)
    {
      const std::size_t a = ring[(i + r - 1) % r], b = ring[i], c = ring[(i + 1) % r];
      const double area = projected_area(P(a), P(b), P(c), normal);
      if(!(area > best_area)) continue;
      bool empty = true;   // no other corner inside the ear (or on its border)
      for(std::size_t j = 0; j < r && empty; ++j)
      {
        const std::size_t x = ring[j];
        if(x == a || x == b || x == c) continue;
        empty = !(projected_area(P(a), P(b), P(x), normal) >= 0 && projected_area(P(b), P(c), P(x), normal) >= 0 &&
                  projected_area(P(c), P(a), P(x), normal) >= 0);
      }
      if(empty) { best = i; best_area = area; }
    }
    if(best == npos)   // degenerate projection: a fan of what is left
    {
      for(std::size_t i = 1; i + 1 < r; ++i) out.push_back({ring[0], ring[i], ring[i + 1]});
      return out;
    }
    out.push_back({ring[(best + r - 1) % r], ring[best], ring[(best + 1) % r]});
    ring.erase(ring.begin() + std::ptrdiff_t(best));
  }
  out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

// Builds the tables of the triangulated polygons (each a list of indices into the nv points `xyz`).
// Edges are numbered in the order of their first appearance along the polygons, the input edges
// first (all of them, then the diagonals, which are marked in m.edge_virtual); m.face_polygon maps
// every triangle to its polygon, and m.input_face too, so that messages name polygons. Throws
// Invalid_input, naming the polygon, on fewer than three corners, a corner out of range, or a
// corner repeated in one polygon.
template <class PolygonRange>
Mesh_tables polygon_mesh_tables(std::vector<double> xyz, const PolygonRange& polygons)
{
  Mesh_tables m;
  m.nv = xyz.size() / 3;
  m.points = std::move(xyz);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_of;
  auto edge = [&](std::size_t a, std::size_t b) {
    const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
    const auto it = edge_of.emplace(key, m.ne);
    if(it.second)
    {
      m.ev.push_back(a);
      m.ev.push_back(b);
      ++m.ne;
    }
    return it.first->second;
  };
  std::vector<std::size_t> corners;
  std::size_t p = 0;
  bool polygons_with_diagonals = false;
  for(const auto& polygon : polygons)
  {
    corners.assign(polygon.begin(), polygon.end());
    const std::string which = "polygon " + std::to_string(p);
    if(corners.size() < 3)
      throw Invalid_input(which + " has " + std::to_string(corners.size()) + " vertices (at least 3 are needed)");
    for(std::size_t k = 0; k < corners.size(); ++k)
    {
      if(corners[k] >= m.nv)
        throw Invalid_input(which + ": vertex index " + std::to_string(corners[k]) + " is out of range (" +
                            std::to_string(m.nv) + " points)");
      for(std::size_t j = 0; j < k; ++j)
        if(corners[j] == corners[k])
          throw Invalid_input(which + " uses vertex " + std::to_string(corners[k]) + " twice");
    }
    for(std::size_t k = 0; k < corners.size(); ++k) edge(corners[k], corners[(k + 1) % corners.size()]);
    polygons_with_diagonals = polygons_with_diagonals || corners.size() > 3;
    ++p;
  }
  const std::size_t input_edges = m.ne;
  p = 0;
  m.polygon_begin.push_back(0);
  std::vector<double> best;   // area of the triangle chosen for each corner of the polygon
  for(const auto& polygon : polygons)
  {
    corners.assign(polygon.begin(), polygon.end());
    const std::size_t first = m.polygon_corner.size();
    m.polygon_corner.resize(first + corners.size(), npos);
    best.assign(corners.size(), -1.);
    for(const std::array<std::size_t, 3>& t : triangulate_polygon(m.points, corners))
    {
      const std::size_t f = m.face_polygon.size();
      for(int k = 0; k < 3; ++k)
      {
        m.fv.push_back(corners[t[k]]);
        m.fe.push_back(edge(corners[t[k]], corners[t[(k + 1) % 3]]));
      }
      m.face_polygon.push_back(p);
      const double area = m.face_area(f);
      for(int k = 0; k < 3; ++k)
        if(area > best[t[k]]) { best[t[k]] = area; m.polygon_corner[first + t[k]] = 3 * f + std::size_t(k); }
    }
    m.polygon_begin.push_back(m.polygon_corner.size());
    ++p;
  }
  m.nf = m.face_polygon.size();
  if(polygons_with_diagonals)
  {
    m.edge_virtual.assign(m.ne, 0);
    std::fill(m.edge_virtual.begin() + std::ptrdiff_t(input_edges), m.edge_virtual.end(), 1);
    m.input_face = m.face_polygon;
  }
  else
  {
    m.face_polygon.clear();   // the triangles are the polygons
    m.polygon_begin.clear();
    m.polygon_corner.clear();
  }
  finalize_mesh_tables(m);
  return m;
}

// Adds a dual 1-chain (paper Sec. 3.7) to `chain`: each pair (a, b) of polygons adds a jump of +1 from
// a into b across the input edge they share (left minus right on its arc). Throws Invalid_input, naming
// the pair, when a or b is out of range or the two share no edge.
template <class PairRange>
void add_dual_chain(const Mesh_tables& m, const PairRange& pairs, std::vector<double>& chain)
{
  auto polygon = [&](std::size_t f) { return m.face_polygon.empty() ? f : m.face_polygon[f]; };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> arc_of;   // (polygon, polygon) -> arc, both orders
  for(std::size_t a = 0; a < m.arcs.size(); ++a)
  {
    if(m.is_virtual(m.arcs[a].edge)) continue;
    const std::size_t L = polygon(m.arcs[a].left_side / 3), R = polygon(m.arcs[a].right_side / 3);
    arc_of.emplace(std::make_pair(L, R), a);
    arc_of.emplace(std::make_pair(R, L), a);
  }
  const std::size_t np = m.number_of_polygons();
  std::size_t k = 0;
  for(const auto& pair : pairs)
  {
    const std::size_t a = std::size_t(std::get<0>(pair)), b = std::size_t(std::get<1>(pair));
    const std::string which = "dual chain pair " + std::to_string(k++) + " (" + std::to_string(a) + ", " + std::to_string(b) + ")";
    if(a >= np || b >= np) throw Invalid_input(which + ": polygon index out of range (" + std::to_string(np) + " polygons)");
    const auto it = arc_of.find(std::make_pair(a, b));
    if(it == arc_of.end()) throw Invalid_input(which + ": the two polygons share no edge");
    const Arc& arc = m.arcs[it->second];
    chain[arc.edge] += polygon(arc.left_side / 3) == b ? 1. : -1.;   // rises into b
  }
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
