// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Flat, index-based description of a triangle mesh: the only mesh representation the numerical
// core sees. Built once from a FaceGraph (or, later, from a polygon soup).

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_MESH_TABLES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_MESH_TABLES_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

/*
  Conventions.
  - Corner c = 3*f + k is vertex fv[c] inside face f (k = 0, 1, 2, in the face's orientation order).
  - Side s = 3*f + k is the oriented side of face f from corner 3f+k to corner 3f+(k+1)%3; the face
    lies to the left of its sides. fe[s] is the side's edge, fs[s] = +1 if the side runs along the
    edge's reference direction ev[2e] -> ev[2e+1], -1 otherwise.
  - An arc is a pair of faces glued along an edge. Jumps of corner functions across an arc are always
    measured left minus right, and a chain value on an edge is the jump across its arc. For faces
    glued with opposite orientations (the oriented manifold case) the "left" face is the one whose
    side runs along the edge's reference direction, so that the chain is the usual primal 1-chain.
    Two faces traversing their edge the same way (a nonorientable gluing, paper Sec. 3.7) make an arc
    too: its left face is the one that comes first in the input, and the chain value on the edge is
    then a dual 1-chain value (the jump from the second face into the first).
  - An edge with exactly one side is a border edge. An edge with more than two sides is a
    nonmanifold edge: its first side is paired with each of the others in arcs across which nothing
    may jump (paper Sec. 2.4.1). A vertex whose faces do not form a single fan through the manifold
    edges (or that lies on a nonmanifold edge) is a nonmanifold vertex: its corners get c = 0
    (Eq. 3) and no jump is allowed across the edges at it (Sec. 2.2, Sec. 3.4).
*/
struct Arc
{
  std::size_t edge;
  std::size_t left_side;   // side of the left face (fs = +1)
  std::size_t right_side;  // side of the right face (fs = -1)
};

struct Mesh_tables
{
  std::size_t nv = 0, nf = 0, ne = 0;
  std::vector<double> points;        // 3 * nv
  std::vector<std::size_t> fv;       // 3 * nf, corner -> vertex
  std::vector<std::size_t> fe;       // 3 * nf, side -> edge
  std::vector<int> fs;               // 3 * nf, side -> +-1
  std::vector<std::size_t> ev;       // 2 * ne, reference direction

  std::vector<std::size_t> edge_side_begin, edge_sides;       // CSR edge -> sides
  std::vector<Arc> arcs;
  std::vector<std::size_t> edge_arc;                          // edge -> arc or npos
  std::vector<std::size_t> unpaired_edges;                    // nonmanifold edges (more than two sides)
  std::size_t nonorientable_arcs = 0;                         // arcs joining faces that traverse their edge the same way
  std::vector<char> vertex_nonmanifold;                       // empty when every vertex is manifold
  std::vector<char> edge_at_nonmanifold;                      // nonmanifold edges and edges at nonmanifold vertices
  std::size_t nonmanifold_vertices = 0;
  std::vector<char> edge_on_border;                           // exactly one incident side
  std::vector<std::size_t> vertex_corner_begin, vertex_corners; // CSR vertex -> corners
  std::vector<char> vertex_on_border;

  // Connected components of faces glued along arcs; isolated vertices belong to none.
  std::size_t n_components = 0;
  std::vector<std::size_t> face_component;
  std::vector<std::size_t> vertex_component;                  // npos for isolated vertices
  std::vector<long> component_euler_characteristic;           // V - E + F
  std::vector<std::size_t> component_border_edges;
  std::vector<std::size_t> component_first_face;

  // Polygon input (polygon_tables.h): the polygon of every triangle, and the diagonals added inside
  // polygons ("virtual" edges: no curve along them, no jump of the residual function across them).
  // Both empty when every input face is a triangle.
  std::vector<std::size_t> face_polygon;
  std::vector<char> edge_virtual;
  // the corners of polygon p, in its order, are the table corners polygon_corner[polygon_begin[p] ..
  // polygon_begin[p + 1]) (of the largest of its triangles at that vertex)
  std::vector<std::size_t> polygon_begin, polygon_corner;
  std::size_t number_of_polygons() const { return polygon_begin.empty() ? nf : polygon_begin.size() - 1; }
  // the table corner of corner k of polygon p, and a triangle of p (all of them carry its label)
  std::size_t polygon_corner_at(std::size_t p, std::size_t k) const
  {
    return polygon_begin.empty() ? 3 * p + k : polygon_corner[polygon_begin[p] + k];
  }
  std::size_t polygon_triangle(std::size_t p) const { return polygon_corner_at(p, 0) / 3; }
  bool is_virtual(std::size_t e) const { return !edge_virtual.empty() && edge_virtual[e]; }
  bool is_nonmanifold(std::size_t v) const { return !vertex_nonmanifold.empty() && vertex_nonmanifold[v]; }
  // no function may jump across e: a diagonal inside a polygon, a nonmanifold edge or an edge at a
  // nonmanifold vertex (Eq. 11 gets the equality constraints of Sec. 3.4 there)
  bool jump_forbidden(std::size_t e) const
  {
    return is_virtual(e) || (!edge_at_nonmanifold.empty() && edge_at_nonmanifold[e]);
  }
  // not an oriented 2-manifold: the Euler characteristic no longer tells the topology, the harmonic
  // basis and the reduced residual (which assume one) are not used
  bool is_general() const { return nonmanifold_vertices > 0 || nonorientable_arcs > 0; }

  // Index of every element in the input's numbering when the tables were renumbered
  // (locality_order.h); empty when the tables keep it. Error messages name elements by it.
  std::vector<std::size_t> input_vertex, input_edge, input_face;
  std::size_t input_vertex_index(std::size_t v) const { return input_vertex.empty() ? v : input_vertex[v]; }
  std::size_t input_edge_index(std::size_t e) const { return input_edge.empty() ? e : input_edge[e]; }
  std::size_t input_face_index(std::size_t f) const { return input_face.empty() ? f : input_face[f]; }
  // of edges a and b (npos: none), the one that comes first in the input's numbering
  std::size_t first_edge_in_input(std::size_t a, std::size_t b) const
  {
    if(a == npos) return b;
    if(b == npos) return a;
    return input_edge_index(b) < input_edge_index(a) ? b : a;
  }

  static std::size_t face_of(std::size_t corner_or_side) { return corner_or_side / 3; }
  static std::size_t next_in_face(std::size_t c) { return 3 * (c / 3) + (c % 3 + 1) % 3; }
  static std::size_t prev_in_face(std::size_t c) { return 3 * (c / 3) + (c % 3 + 2) % 3; }
  // side s joins corners s (tail) and next_in_face(s) (head)
  std::size_t tail(std::size_t s) const { return fv[s]; }
  std::size_t head(std::size_t s) const { return fv[next_in_face(s)]; }

  // the corner of face f at vertex v, npos if v is not a vertex of f
  std::size_t corner_at(std::size_t f, std::size_t v) const
  {
    for(std::size_t k = 0; k < 3; ++k)
      if(fv[3 * f + k] == v) return 3 * f + k;
    return npos;
  }

  const double* point(std::size_t v) const { return &points[3 * v]; }
  // the points are the input's coordinates times this power of two (unit_scale(): a unit bounding box)
  double point_scale = 1.;

  // area of face f
  double face_area(std::size_t f) const
  {
    const double *p = point(fv[3 * f]), *q = point(fv[3 * f + 1]), *r = point(fv[3 * f + 2]);
    const double a[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, b[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  double edge_length(std::size_t e) const
  {
    const double* p = point(ev[2 * e]);
    const double* q = point(ev[2 * e + 1]);
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }

  // A component is simply connected, in the relative sense that matters here (every relative
  // 1-cycle bounds), when it is a disk (chi = 1, with border) or a sphere (chi = 2).
  bool component_is_disk_or_sphere(std::size_t c) const
  {
    if(is_general()) return false;
    const long chi = component_euler_characteristic[c];
    return (chi == 1 && component_border_edges[c] > 0) || (chi == 2 && component_border_edges[c] == 0);
  }
  // The dimension of the first cohomology of component c, from its Euler characteristic: 2g for a
  // closed component, 2g + b - 1 = 1 - chi for one with b border loops.
  long component_cohomology_classes(std::size_t c) const
  {
    return (component_border_edges[c] > 0 ? 1 : 2) - component_euler_characteristic[c];
  }
  bool all_components_disks_or_spheres() const
  {
    for(std::size_t c = 0; c < n_components; ++c)
      if(!component_is_disk_or_sphere(c)) return false;
    return true;
  }
};

// The mean length of the interior edges (one per arc): the unit of Eq. 11's costs, in the residual
// problem and in the confidence's flip costs (1 if there is no arc or the mean is not positive).
inline double mean_interior_edge_length(const Mesh_tables& m)
{
  double mean_len = 0;
  for(const Arc& a : m.arcs) mean_len += m.edge_length(a.edge);
  mean_len = m.arcs.empty() ? 1. : mean_len / double(m.arcs.size());
  return mean_len > 0 ? mean_len : 1.;
}

// Per component: 1 if its faces can be oriented so that every edge with exactly two faces is
// traversed once each way (edges with more faces are not considered), 0 otherwise (a Moebius strip).
// Found by propagating a flip bit across the two-sided edges, from each face's sides to the other
// side of their edge (depth first per component). Without nonorientable arcs no flip is needed at all.
inline std::vector<char> component_orientable(const Mesh_tables& m)
{
  std::vector<char> orientable(m.n_components, 1);
  if(m.nonorientable_arcs == 0) return orientable;
  std::vector<signed char> flipped(m.nf, -1);
  std::vector<std::size_t> stack;
  for(std::size_t f0 = 0; f0 < m.nf; ++f0)
  {
    if(flipped[f0] != -1) continue;
    flipped[f0] = 0;
    stack.assign(1, f0);
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(std::size_t s = 3 * f; s < 3 * f + 3; ++s)
      {
        const std::size_t b = m.edge_side_begin[m.fe[s]];
        if(m.edge_side_begin[m.fe[s] + 1] - b != 2) continue;
        const std::size_t t = m.edge_sides[b] == s ? m.edge_sides[b + 1] : m.edge_sides[b], g = t / 3;
        const signed char want = static_cast<signed char>(flipped[f] ^ (m.fs[s] == m.fs[t] ? 1 : 0));
        if(flipped[g] == -1) { flipped[g] = want; stack.push_back(g); }
        else if(flipped[g] != want) orientable[m.face_component[f]] = 0;
      }
    }
  }
  return orientable;
}

// Nonmanifold vertices: the ends of nonmanifold edges, and vertices whose corners fall into several
// fans (corners of one vertex joined across its arcs of two-sided edges); then the edges at them.
inline void find_nonmanifold_vertices(Mesh_tables& m)
{
  m.vertex_nonmanifold.clear();
  m.edge_at_nonmanifold.clear();
  m.nonmanifold_vertices = 0;
  std::vector<char> nonmanifold(m.nv, 0);
  for(std::size_t e : m.unpaired_edges) nonmanifold[m.ev[2 * e]] = nonmanifold[m.ev[2 * e + 1]] = 1;
  Union_find fans(3 * m.nf);
  for(const Arc& a : m.arcs)
  {
    if(m.edge_side_begin[a.edge + 1] - m.edge_side_begin[a.edge] != 2) continue;
    for(int k = 0; k < 2; ++k)
    {
      const std::size_t v = m.ev[2 * a.edge + k];
      fans.unite(m.corner_at(a.left_side / 3, v), m.corner_at(a.right_side / 3, v));
    }
  }
  for(std::size_t v = 0; v < m.nv; ++v)
  {
    const std::size_t b = m.vertex_corner_begin[v], n = m.vertex_corner_begin[v + 1] - b;
    for(std::size_t i = 1; i < n && !nonmanifold[v]; ++i)
      if(fans.find(m.vertex_corners[b + i]) != fans.find(m.vertex_corners[b])) nonmanifold[v] = 1;
    m.nonmanifold_vertices += nonmanifold[v] ? 1 : 0;
  }
  if(m.nonmanifold_vertices == 0) return;
  m.vertex_nonmanifold = std::move(nonmanifold);
  m.edge_at_nonmanifold.assign(m.ne, 0);
  for(std::size_t e = 0; e < m.ne; ++e)
    m.edge_at_nonmanifold[e] = (m.vertex_nonmanifold[m.ev[2 * e]] || m.vertex_nonmanifold[m.ev[2 * e + 1]]) ? 1 : 0;
}

// The indices i of `key` grouped by key[i] (keys below n), in compressed rows: the indices with key k are
// items[begin[k]], ..., items[begin[k + 1] - 1], in increasing order (edge -> sides from fe, vertex ->
// corners from fv).
inline void group_by_key(const std::vector<std::size_t>& key, std::size_t n, std::vector<std::size_t>& begin,
                         std::vector<std::size_t>& items)
{
  begin.assign(n + 1, 0);
  for(const std::size_t k : key) ++begin[k + 1];
  for(std::size_t k = 0; k < n; ++k) begin[k + 1] += begin[k];
  items.assign(key.size(), 0);
  std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
  for(std::size_t i = 0; i < key.size(); ++i) items[fill[key[i]]++] = i;
}

// Completes the tables from points, fv, fe, ev (and nv, nf, ne): orientation signs, incidences,
// arcs, border flags, vertex corner lists and components. Throws Invalid_input on a side whose
// endpoints do not match its edge.
inline void finalize_mesh_tables(Mesh_tables& m)
{
  const std::size_t nside = 3 * m.nf;
  m.fs.assign(nside, 0);
  for(std::size_t s = 0; s < nside; ++s)
  {
    const std::size_t e = m.fe[s], a = m.tail(s), b = m.head(s);
    if(a == m.ev[2 * e] && b == m.ev[2 * e + 1]) m.fs[s] = 1;
    else if(b == m.ev[2 * e] && a == m.ev[2 * e + 1]) m.fs[s] = -1;
    else throw Invalid_input("face " + std::to_string(m.input_face_index(s / 3)) + ": side " + std::to_string(s % 3) +
                           " does not match its edge " + std::to_string(m.input_edge_index(e)));
  }

  group_by_key(m.fe, m.ne, m.edge_side_begin, m.edge_sides);   // edge -> sides

  // arcs and border edges
  m.arcs.clear();
  m.unpaired_edges.clear();
  m.nonorientable_arcs = 0;
  m.edge_arc.assign(m.ne, npos);
  m.edge_on_border.assign(m.ne, 0);
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    const std::size_t b = m.edge_side_begin[e], n = m.edge_side_begin[e + 1] - b;
    if(n == 1) { m.edge_on_border[e] = 1; continue; }
    if(n < 2) continue;
    m.edge_arc[e] = m.arcs.size();
    std::size_t s0 = m.edge_sides[b], s1 = m.edge_sides[b + 1];
    if(n == 2)
    {
      if(m.fs[s0] == -m.fs[s1]) { if(m.fs[s0] < 0) std::swap(s0, s1); }
      else
      {
        if(m.input_face_index(s1 / 3) < m.input_face_index(s0 / 3)) std::swap(s0, s1);
        ++m.nonorientable_arcs;
      }
      m.arcs.push_back(Arc{e, s0, s1});
      continue;
    }
    m.unpaired_edges.push_back(e);
    for(std::size_t i = b + 1; i < b + n; ++i) m.arcs.push_back(Arc{e, s0, m.edge_sides[i]});
  }

  // vertex -> corners, border vertices
  group_by_key(m.fv, m.nv, m.vertex_corner_begin, m.vertex_corners);
  m.vertex_on_border.assign(m.nv, 0);
  for(std::size_t e = 0; e < m.ne; ++e)
    if(m.edge_on_border[e]) m.vertex_on_border[m.ev[2 * e]] = m.vertex_on_border[m.ev[2 * e + 1]] = 1;
  find_nonmanifold_vertices(m);

  // face components through arcs; faces sharing only a vertex (or a nonmanifold edge) are also one
  // component for labelling
  Union_find sets(m.nf);
  for(const Arc& a : m.arcs) sets.unite(a.left_side / 3, a.right_side / 3);
  for(std::size_t v = 0; v < m.nv; ++v)
    for(std::size_t i = m.vertex_corner_begin[v] + 1; i < m.vertex_corner_begin[v + 1]; ++i)
      sets.unite(m.vertex_corners[i] / 3, m.vertex_corners[m.vertex_corner_begin[v]] / 3);
  m.face_component.assign(m.nf, npos);
  m.component_first_face.clear();
  m.n_components = 0;
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    const std::size_t r = sets.find(f);
    if(m.face_component[r] == npos)
    {
      m.face_component[r] = m.n_components++;
      m.component_first_face.push_back(r);
    }
    m.face_component[f] = m.face_component[r];
  }
  m.vertex_component.assign(m.nv, npos);
  for(std::size_t c = 0; c < nside; ++c) m.vertex_component[m.fv[c]] = m.face_component[c / 3];

  m.component_euler_characteristic.assign(m.n_components, 0);
  m.component_border_edges.assign(m.n_components, 0);
  for(std::size_t f = 0; f < m.nf; ++f) ++m.component_euler_characteristic[m.face_component[f]];
  for(std::size_t v = 0; v < m.nv; ++v)
    if(m.vertex_component[v] != npos) ++m.component_euler_characteristic[m.vertex_component[v]];
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    if(m.edge_side_begin[e + 1] == m.edge_side_begin[e]) continue;  // edge without faces
    const std::size_t c = m.face_component[m.edge_sides[m.edge_side_begin[e]] / 3];
    --m.component_euler_characteristic[c];
    if(m.edge_on_border[e]) ++m.component_border_edges[c];
  }
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_MESH_TABLES_H
