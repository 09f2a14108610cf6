// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Makes an input curve conform to the mesh edges (cutting faces along segments between edge points), turns it
// into an integer edge chain, and splits short curve pieces.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_IO_CONFORMING_CUT_H
#define CGAL_SURFACE_WINDING_NUMBERS_IO_CONFORMING_CUT_H

#include <CGAL/Surface_winding_numbers/IO/errors.h>
#include <CGAL/Surface_winding_numbers/IO/read_mesh.h>
#include <CGAL/Surface_winding_numbers/IO/curve_io.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

/*!
  \file conforming_cut.h

  `conforming_cut()` turns curves (`Curve_set`) on a mesh into an integer 1-chain on the edges of a possibly
  refined copy of the mesh.

  <b>Chain convention.</b> `chain[e]` (indexed by the `Surface_mesh` edge index) counts how many times the curve
  runs along `halfedge(e, mesh)` (from `source(halfedge(e))` to `target(halfedge(e))`), minus how many times it
  runs the other way. Here `e` is the descriptor from `edges(mesh)`, whose halfedge is the halfedge of index
  `2*e`. (Pitfall: in CGAL 5.5 the descriptor `edge(h, mesh)` remembers `h`, so `halfedge(edge(h, mesh), mesh)`
  returns `h` itself, which may be the odd halfedge `2*e+1`.)

  <b>No cut needed.</b> If every point used by a segment is a vertex point (consecutive vertices of a segment
  are then adjacent, as validated by the readers), the mesh is copied unchanged and each segment adds +1 along
  its direction.

  <b>Conforming cut</b> (otherwise; notes section 4.2):
  - points are de-duplicated by exact equality (same vertex, or same edge and same t); only points used by a
    segment with two distinct endpoints are inserted; segments with identical endpoints are skipped;
  - every used edge point becomes a new vertex at `(1-t)*first(e) + t*second(e)`; new vertices get the indices
    `n, n+1, ...` (n = number of input vertices) in the order of the points in the curve set(s); existing
    vertices keep their index and position;
  - a segment whose two points lie on a common mesh edge runs along that edge (through any points inserted
    between them); any other segment is joined inside the common face of its two points (the lowest-index
    common face); two such segments crossing inside a face are rejected (`Input_error` naming both lines);
  - every face that received a point on its boundary is re-triangulated: it is split along the segments, and
    each piece (a convex polygon whose vertices lie on the triangle's sides) is triangulated by clipping
    corners, never making a triangle out of three collinear points, preferring the ear with the largest
    minimal angle. Face `j` of the input keeps index `j` (holding one of its pieces); the other pieces are
    appended after the last input face, in input face order.

  <b>Short-piece refinement</b> (notes section 4.3; `Cut_options::refine_short_pieces`, on by default).
  Interior endpoints (vertices with nonzero boundary of the chain that are not on the mesh boundary) are taken
  out of the jump-Laplace system, so curve edges touching them lose their jump; a piece made of a single edge
  between two endpoints would vanish. Rule used here:
  - the curve is cut into pieces at every vertex whose chain boundary is nonzero or that has a number of
    incident curve edges other than 2; a piece is a maximal path of curve edges between two such vertices
    (closed loops without such a vertex are never refined);
  - a piece with n < N edges (N = `Cut_options::min_piece_edges`, default 8) that ends at an *interior*
    endpoint is refined: each of its edges is split at its midpoint into 2^k sub-edges, with
    k = max(1, floor(log2(floor(N/n)))) (n=1: 8 sub-edges, n=2: 4 each, n=3..7: 2 each). This is the authors' rule
    (`splitEdgesIfNecessary`, MAX_EDGE_SPLITS = 3) without their shared-counter quirk, with pieces also broken
    at junctions, and without refining pieces whose both ends are on the mesh boundary;
  - a split joins the new vertex to the opposite vertex of each incident face (2 new faces per interior edge,
    1 per boundary edge); both halves inherit the chain value. New vertices and faces are appended.
*/

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief options of `conforming_cut()`.
*/
struct Cut_options
{
  /// split the edges of short curve pieces ending at interior endpoints (see the file documentation)
  bool refine_short_pieces = true;
  /// pieces with fewer edges than this are refined
  std::size_t min_piece_edges = 8;
};

/*!
  \brief result of `conforming_cut()`.
*/
template <class Point>
struct Cut_result
{
  /// the mesh the chain lives on (a copy of the input, possibly cut and refined)
  CGAL::Surface_mesh<Point> mesh;
  /// per edge index of `mesh`: the integer chain, signed w.r.t. `halfedge(e, mesh)`
  std::vector<int> chain;
  /// for every point of the curve set(s) (in order, sets concatenated), its vertex in `mesh`, or -1 if the
  /// point was not used by any segment
  std::vector<std::size_t> point_vertex;
  /// true if the cut inserted vertices
  bool cut = false;
  /// \name Statistics
  /// @{

  /// vertices/faces of the input mesh
  std::size_t input_vertices = 0, input_faces = 0;
  /// @}
  /// \name Conforming cut
  /// @{

  /// vertices/faces added by the conforming cut
  std::size_t cut_new_vertices = 0, cut_new_faces = 0;
  /// @}
  /// \name After the cut
  /// @{

  /// vertices/faces after the cut, before the short-piece refinement
  std::size_t vertices_after_cut = 0, faces_after_cut = 0;
  /// @}
  /// \name Short-piece refinement
  /// @{

  /// vertices/faces added by the short-piece refinement, and the number of refined pieces
  std::size_t refine_new_vertices = 0, refine_new_faces = 0, refined_pieces = 0;
  /// @}
  /// segments skipped because their two points coincide
  std::size_t skipped_segments = 0;
  /// number of segments that produced chain values
  std::size_t used_segments = 0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

struct Cut_location
{
  bool on_edge = false;
  std::size_t v = 0;      // vertex (on_edge == false) or new vertex id once assigned
  std::size_t e = 0;      // CGAL edge index (on_edge)
  double t = 0.;          // along the authors' halfedge of e
  bool operator==(const Cut_location& o) const
  {
    return on_edge == o.on_edge && (on_edge ? (e == o.e && t == o.t) : v == o.v);
  }
};

struct Cut_segment
{
  std::size_t pa, pb;     // global point indices
  std::size_t line;
  const std::string* file;
};

inline double angle_at(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c)
{
  // angle at a in triangle abc
  double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  double d = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
  double x[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  return std::atan2(n, d);
}

/// Triangulates a convex polygon given by vertex ids; edge_line[i] labels the line carrying edge
/// (poly[i], poly[i+1]). Never emits a triangle whose three vertices lie on one line.
inline void triangulate_convex_polygon(std::vector<std::size_t> poly, std::vector<long long> edge_line,
                                       long long& next_line, const std::vector<std::array<double, 3> >& pos,
                                       std::vector<std::array<std::size_t, 3> >& out)
{
  while(poly.size() > 3)
  {
    const std::size_t n = poly.size();
    std::vector<char> corner(n);
    std::size_t corners = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      corner[i] = edge_line[(i + n - 1) % n] != edge_line[i];
      corners += corner[i] ? 1 : 0;
    }
    std::size_t best = n;
    double best_q = -1.;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!corner[i]) continue;
      std::size_t ip = (i + n - 1) % n, in = (i + 1) % n;
      std::size_t after = corners - 1 + (corner[ip] ? 0 : 1) + (corner[in] ? 0 : 1);
      if(after < 3) continue;
      const auto &a = pos[poly[ip]], &b = pos[poly[i]], &c = pos[poly[in]];
      double q = std::min(angle_at(a, b, c), std::min(angle_at(b, c, a), angle_at(c, a, b)));
      if(!(q == q)) q = 0.;
      if(q > best_q) { best_q = q; best = i; }
    }
    if(best == n)  // cannot happen for a convex polygon with >= 3 corners; stay total anyway
      best = 0;
    std::size_t ip = (best + n - 1) % n, in = (best + 1) % n;
    out.push_back({poly[ip], poly[best], poly[in]});
    edge_line[ip] = next_line++;
    poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(best));
    edge_line.erase(edge_line.begin() + static_cast<std::ptrdiff_t>(best));
  }
  if(poly.size() == 3)
    out.push_back({poly[0], poly[1], poly[2]});
}

// In CGAL 5.5, `Surface_mesh::edge(h)` keeps `h` inside the edge descriptor, so `halfedge(edge(h))` is `h`
// itself. The reference halfedge of edge index i is halfedge 2i (what `halfedge(e, mesh)` returns for the
// descriptors of `edges(mesh)`): always test the parity instead.
template <class Halfedge_index>
bool is_canonical(Halfedge_index h)
{
  return (std::size_t(h) & 1) == 0;
}

template <class Point>
std::array<double, 3> to_array(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <class Mesh>
void add_chain(const Mesh& m, std::vector<int>& chain, std::size_t a, std::size_t b, int value)
{
  typedef typename Mesh::Vertex_index Vertex_index;
  auto hb = CGAL::halfedge(Vertex_index(static_cast<typename Mesh::size_type>(a)),
                           Vertex_index(static_cast<typename Mesh::size_type>(b)), m);
  if(!hb.second)
    throw std::logic_error("conforming_cut: missing edge (" + std::to_string(a) + ", " + std::to_string(b) + ")");
  auto e = m.edge(hb.first);
  chain[std::size_t(e)] += is_canonical(hb.first) ? value : -value;
}

template <class Mesh>
void split_edge_recursively(Mesh& m, std::vector<int>& chain, typename Mesh::Halfedge_index h, std::size_t rounds)
{
  if(rounds == 0) return;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  if(m.is_border(h)) h = m.opposite(h);
  auto e = m.edge(h);
  int ch = is_canonical(h) ? chain[std::size_t(e)] : -chain[std::size_t(e)];
  auto pu = m.point(m.source(h));
  auto pv = m.point(m.target(h));
  Halfedge_index hnew = CGAL::Euler::split_edge(h, m);  // hnew: u->w, h: w->v
  typedef typename Mesh::Point P;
  m.point(m.target(hnew)) = P((CGAL::to_double(pu.x()) + CGAL::to_double(pv.x())) / 2,
                              (CGAL::to_double(pu.y()) + CGAL::to_double(pv.y())) / 2,
                              (CGAL::to_double(pu.z()) + CGAL::to_double(pv.z())) / 2);
  chain.resize(m.number_of_edges(), 0);
  auto enew = m.edge(hnew);
  chain[std::size_t(enew)] = is_canonical(hnew) ? ch : -ch;
  if(!m.is_border(hnew))
    CGAL::Euler::split_face(hnew, m.next(h), m);
  Halfedge_index oh = m.opposite(h), ohn = m.opposite(hnew);  // v->w, w->u
  if(!m.is_border(oh))
    CGAL::Euler::split_face(oh, m.next(ohn), m);
  chain.resize(m.number_of_edges(), 0);
  split_edge_recursively(m, chain, hnew, rounds - 1);
  split_edge_recursively(m, chain, h, rounds - 1);
}

/// Short-piece refinement; returns the number of refined pieces.
template <class Mesh>
std::size_t refine_short_pieces(Mesh& m, std::vector<int>& chain, std::size_t min_edges)
{
  typedef typename Mesh::Halfedge_index Halfedge_index;
  const std::size_t nv = m.number_of_vertices();
  std::vector<long long> boundary(nv, 0);
  std::vector<int> degree(nv, 0);
  for(auto e : m.edges())
  {
    int c = chain[std::size_t(e)];
    if(c == 0) continue;
    auto h = m.halfedge(e);
    boundary[std::size_t(m.target(h))] += c;
    boundary[std::size_t(m.source(h))] -= c;
    ++degree[std::size_t(m.target(h))];
    ++degree[std::size_t(m.source(h))];
  }
  auto is_break = [&](std::size_t v) { return boundary[v] != 0 || degree[v] != 2; };
  auto interior_endpoint = [&](std::size_t v) {
    return boundary[v] != 0 && !m.is_border(typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(v)));
  };
  std::vector<char> visited(m.number_of_edges(), 0);
  std::vector<std::vector<Halfedge_index> > risky;
  for(auto v : m.vertices())
  {
    if(degree[std::size_t(v)] == 0 || !is_break(std::size_t(v))) continue;
    for(auto h0 : CGAL::halfedges_around_source(v, m))
    {
      if(chain[std::size_t(m.edge(h0))] == 0 || visited[std::size_t(m.edge(h0))]) continue;
      std::vector<Halfedge_index> piece;
      Halfedge_index h = h0;
      while(true)
      {
        visited[std::size_t(m.edge(h))] = 1;
        piece.push_back(h);
        auto w = m.target(h);
        if(is_break(std::size_t(w))) break;
        Halfedge_index nexth = Halfedge_index();
        for(auto g : CGAL::halfedges_around_source(m.opposite(h), m))
          if(m.edge(g) != m.edge(h) && chain[std::size_t(m.edge(g))] != 0) { nexth = g; break; }
        if(nexth == Halfedge_index() || visited[std::size_t(m.edge(nexth))]) break;
        h = nexth;
      }
      bool ends_inside = interior_endpoint(std::size_t(v)) || interior_endpoint(std::size_t(m.target(piece.back())));
      if(ends_inside && piece.size() < min_edges)
        risky.push_back(std::move(piece));
    }
  }
  for(const auto& piece : risky)
  {
    std::size_t n = piece.size();
    std::size_t q = min_edges / n, k = 0;
    while((std::size_t(1) << (k + 1)) <= q) ++k;
    k = std::max<std::size_t>(k, 1);  // every edge of a short piece is split at least once
    for(Halfedge_index h : piece)
      split_edge_recursively(m, chain, h, k);
  }
  return risky.size();
}

} // namespace internal
/// \endcond

/*!
  \brief computes the chain of curves made only of vertex points on the unchanged mesh.

  \returns per edge index of `mesh`, the chain signed w.r.t. `halfedge(e, mesh)`
  \throws Input_error if a curve has dual pairs ("dual chains (c lines) are not supported yet"), uses an edge
  point (the mesh must be cut: use `conforming_cut()`), or has a segment between non-adjacent vertices.
*/
template <class Point>
std::vector<int> vertex_curve_chain(const CGAL::Surface_mesh<Point>& mesh, const Curve_set& curve)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  if(!curve.dual_pairs.empty())
    throw Input_error(curve.file, curve.dual_pairs.front().line, "dual chains (c lines) are not supported yet");
  std::vector<int> chain(mesh.number_of_edges(), 0);
  for(const Curve_segment& s : curve.segments)
  {
    if(s.a >= curve.points.size() || s.b >= curve.points.size())
      throw Input_error(curve.file, s.line, "segment refers to an undefined point");
    const Curve_point &p = curve.points[s.a], &q = curve.points[s.b];
    if(p.kind != Curve_point::VERTEX || q.kind != Curve_point::VERTEX)
      throw Input_error(curve.file, s.line, "segment uses an edge point: the mesh must be cut (conforming_cut)");
    if(p.element == q.element) continue;
    if(p.element >= mesh.number_of_vertices() || q.element >= mesh.number_of_vertices())
      throw Input_error(curve.file, s.line, "vertex index out of range");
    auto hb = CGAL::halfedge(typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(p.element)),
                             typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(q.element)), mesh);
    if(!hb.second)
      throw Input_error(curve.file, s.line, "vertices " + std::to_string(p.element) + " and " +
                                               std::to_string(q.element) + " are not adjacent");
    auto e = mesh.edge(hb.first);
    chain[std::size_t(e)] += internal::is_canonical(hb.first) ? 1 : -1;
  }
  return chain;
}

/*!
  \brief makes the curves conform to the mesh edges and returns the refined mesh with the curves' chain.

  See the file documentation for the rules (cut, re-triangulation, numbering, refinement).

  \param mesh a mesh as returned by `read_mesh()` (no garbage; `halfedge(f)` at the face's first vertex)
  \param curves the curve sets, all on `mesh`; their points are numbered consecutively in
         `Cut_result::point_vertex`
  \param options refinement options
  \throws Input_error (with the file and line of the offending record) on dual pairs ("dual chains (c lines)
  are not supported yet"), an index out of range, t outside [0,1], a segment whose points share no face, or two
  segments crossing inside a face.
*/
template <class Point>
Cut_result<Point> conforming_cut(const CGAL::Surface_mesh<Point>& mesh, const std::vector<Curve_set>& curves,
                                 const Cut_options& options = Cut_options())
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  using internal::Cut_location;
  using internal::Cut_segment;

  if(mesh.has_garbage())
    throw std::invalid_argument("conforming_cut: the mesh has garbage (call collect_garbage() first)");
  for(const Curve_set& cs : curves)
    if(!cs.dual_pairs.empty())
      throw Input_error(cs.file, cs.dual_pairs.front().line, "dual chains (c lines) are not supported yet");

  const std::size_t nv = mesh.number_of_vertices(), nf = mesh.number_of_faces();
  const std::vector<Halfedge_index> ae = authors_edge_halfedges(mesh);

  Cut_result<Point> result;
  result.input_vertices = nv;
  result.input_faces = nf;

  // ---- locations of all points
  std::vector<Cut_location> loc;
  std::vector<Cut_segment> segs;
  for(const Curve_set& cs : curves)
  {
    const std::size_t base = loc.size();
    for(const Curve_point& p : cs.points)
    {
      Cut_location l;
      if(p.kind == Curve_point::VERTEX)
      {
        if(p.element >= nv)
          throw Input_error(cs.file, p.line, "vertex index " + std::to_string(p.element) + " is out of range (" +
                                                std::to_string(nv) + " vertices)");
        l.v = p.element;
      }
      else
      {
        if(p.element >= ae.size())
          throw Input_error(cs.file, p.line, "edge index " + std::to_string(p.element) + " is out of range (" +
                                                std::to_string(ae.size()) + " edges)");
        if(!(p.t >= 0. && p.t <= 1.))
          throw Input_error(cs.file, p.line, "edge parameter t is not in [0,1]");
        Halfedge_index h = ae[p.element];
        if(p.t == 0.) l.v = std::size_t(mesh.source(h));
        else if(p.t == 1.) l.v = std::size_t(mesh.target(h));
        else { l.on_edge = true; l.e = std::size_t(mesh.edge(h)); l.t = p.t; }
      }
      loc.push_back(l);
    }
    for(const Curve_segment& s : cs.segments)
    {
      if(s.a >= cs.points.size() || s.b >= cs.points.size())
        throw Input_error(cs.file, s.line, "segment refers to an undefined point");
      segs.push_back(Cut_segment{base + s.a, base + s.b, s.line, &cs.file});
    }
  }
  // authors' halfedge of each CGAL edge (direction of t)
  std::vector<Halfedge_index> t_halfedge(mesh.number_of_edges());
  for(Halfedge_index h : ae) t_halfedge[std::size_t(mesh.edge(h))] = h;

  auto faces_of = [&](const Cut_location& l, std::vector<std::size_t>& out) {
    out.clear();
    if(!l.on_edge)
    {
      Vertex_index v(static_cast<typename Mesh::size_type>(l.v));
      if(mesh.halfedge(v) != Mesh::null_halfedge())
        for(auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
          if(!mesh.is_border(h)) out.push_back(std::size_t(mesh.face(h)));
    }
    else
    {
      Halfedge_index h = mesh.halfedge(typename Mesh::Edge_index(static_cast<typename Mesh::size_type>(l.e)));
      if(!mesh.is_border(h)) out.push_back(std::size_t(mesh.face(h)));
      if(!mesh.is_border(mesh.opposite(h))) out.push_back(std::size_t(mesh.face(mesh.opposite(h))));
    }
    std::sort(out.begin(), out.end());
  };
  // the CGAL edge shared by two locations, or -1
  const std::size_t none = std::size_t(-1);
  auto common_edge = [&](const Cut_location& a, const Cut_location& b) -> std::size_t {
    if(a.on_edge && b.on_edge) return a.e == b.e ? a.e : none;
    if(!a.on_edge && !b.on_edge)
    {
      auto hb = CGAL::halfedge(Vertex_index(static_cast<typename Mesh::size_type>(a.v)),
                               Vertex_index(static_cast<typename Mesh::size_type>(b.v)), mesh);
      return hb.second ? std::size_t(mesh.edge(hb.first)) : none;
    }
    const Cut_location& ep = a.on_edge ? a : b;
    const Cut_location& vp = a.on_edge ? b : a;
    Halfedge_index h = t_halfedge[ep.e];
    return (std::size_t(mesh.source(h)) == vp.v || std::size_t(mesh.target(h)) == vp.v) ? ep.e : none;
  };

  // ---- classify segments
  struct Classified { std::size_t seg; std::size_t edge; std::size_t face; };  // edge != none: along edge
  std::vector<Classified> cls;
  std::vector<char> used_point(loc.size(), 0);
  std::vector<std::size_t> fa, fb, common;
  for(std::size_t si = 0; si < segs.size(); ++si)
  {
    const Cut_segment& s = segs[si];
    const Cut_location &a = loc[s.pa], &b = loc[s.pb];
    if(a == b) { ++result.skipped_segments; continue; }
    std::size_t e = common_edge(a, b);
    std::size_t f = none;
    if(e == none)
    {
      faces_of(a, fa);
      faces_of(b, fb);
      common.clear();
      std::set_intersection(fa.begin(), fa.end(), fb.begin(), fb.end(), std::back_inserter(common));
      if(common.empty())
        throw Input_error(*s.file, s.line, "the segment does not lie in a single face (its two points share no face)");
      f = common.front();
    }
    cls.push_back(Classified{si, e, f});
    used_point[s.pa] = used_point[s.pb] = 1;
  }
  result.used_segments = cls.size();

  // ---- new vertices for used edge points (dedupe by exact equality)
  std::map<std::pair<std::size_t, double>, std::size_t> edge_point_vertex;
  std::vector<std::array<double, 3> > pos;
  pos.reserve(nv);
  for(auto v : mesh.vertices()) pos.push_back(internal::to_array(mesh.point(v)));
  std::unordered_map<std::size_t, std::vector<std::pair<double, std::size_t> > > on_edge;  // CGAL edge -> (t, vertex)
  result.point_vertex.assign(loc.size(), none);
  for(std::size_t i = 0; i < loc.size(); ++i)
  {
    if(!used_point[i]) continue;
    Cut_location& l = loc[i];
    if(!l.on_edge) { result.point_vertex[i] = l.v; continue; }
    auto ins = edge_point_vertex.emplace(std::make_pair(l.e, l.t), pos.size());
    if(ins.second)
    {
      Halfedge_index h = t_halfedge[l.e];
      auto p = internal::to_array(mesh.point(mesh.source(h)));
      auto q = internal::to_array(mesh.point(mesh.target(h)));
      pos.push_back({(1 - l.t) * p[0] + l.t * q[0], (1 - l.t) * p[1] + l.t * q[1], (1 - l.t) * p[2] + l.t * q[2]});
      on_edge[l.e].emplace_back(l.t, ins.first->second);
    }
    result.point_vertex[i] = ins.first->second;
  }
  auto vertex_of = [&](std::size_t point) { return result.point_vertex[point]; };

  if(pos.size() == nv)
  {
    // ---- no cut: chain on the unchanged mesh
    result.mesh = mesh;
    result.chain.assign(mesh.number_of_edges(), 0);
    for(const Classified& c : cls)
      internal::add_chain(result.mesh, result.chain, vertex_of(segs[c.seg].pa), vertex_of(segs[c.seg].pb), 1);
  }
  else
  {
    result.cut = true;
    // ordered vertices along halfedge(e) for every edge with points (endpoints included)
    std::unordered_map<std::size_t, std::vector<std::size_t> > along;
    for(auto& kv : on_edge)
    {
      auto& pts = kv.second;
      std::sort(pts.begin(), pts.end());
      typename Mesh::Edge_index e(static_cast<typename Mesh::size_type>(kv.first));
      Halfedge_index hd = mesh.halfedge(e);
      std::vector<std::size_t> list;
      list.push_back(std::size_t(mesh.source(hd)));
      if(hd == t_halfedge[kv.first])
        for(auto& p : pts) list.push_back(p.second);
      else
        for(auto it = pts.rbegin(); it != pts.rend(); ++it) list.push_back(it->second);
      list.push_back(std::size_t(mesh.target(hd)));
      along.emplace(kv.first, std::move(list));
    }
    // chords per face
    std::unordered_map<std::size_t, std::vector<std::size_t> > chords_of_face;  // face -> indices into cls
    for(std::size_t k = 0; k < cls.size(); ++k)
      if(cls[k].edge == none) chords_of_face[cls[k].face].push_back(k);

    std::vector<char> affected(nf, 0);
    for(auto& kv : on_edge)
    {
      Halfedge_index h = mesh.halfedge(typename Mesh::Edge_index(static_cast<typename Mesh::size_type>(kv.first)));
      if(!mesh.is_border(h)) affected[std::size_t(mesh.face(h))] = 1;
      if(!mesh.is_border(mesh.opposite(h))) affected[std::size_t(mesh.face(mesh.opposite(h)))] = 1;
    }

    Triangle_soup soup;
    soup.points = pos;
    soup.triangles.resize(nf);
    std::vector<std::array<std::size_t, 3> > extra;
    std::vector<std::array<std::size_t, 3> > tris;
    for(Face_index f : mesh.faces())
    {
      const std::size_t fi = std::size_t(f);
      Halfedge_index h0 = mesh.halfedge(f);
      if(!affected[fi])
      {
        soup.triangles[fi] = {std::size_t(mesh.target(h0)), std::size_t(mesh.target(mesh.next(h0))),
                              std::size_t(mesh.target(mesh.next(mesh.next(h0))))};
        continue;
      }
      // boundary cycle of the face, starting at its first vertex
      std::vector<std::size_t> cyc;
      std::vector<int> side;
      Halfedge_index g = mesh.next(h0);
      for(int k = 0; k < 3; ++k, g = mesh.next(g))
      {
        cyc.push_back(std::size_t(mesh.source(g)));
        side.push_back(k);
        auto it = along.find(std::size_t(mesh.edge(g)));
        if(it != along.end())
        {
          const auto& list = it->second;
          bool fwd = internal::is_canonical(g);
          for(std::size_t m = 1; m + 1 < list.size(); ++m)
          {
            cyc.push_back(fwd ? list[m] : list[list.size() - 1 - m]);
            side.push_back(k);
          }
        }
      }
      const std::size_t K = cyc.size();
      auto position = [&](std::size_t vid) {
        for(std::size_t i = 0; i < K; ++i) if(cyc[i] == vid) return i;
        throw std::logic_error("conforming_cut: chord endpoint not on its face");
      };
      // chords of this face, de-duplicated, checked for crossings
      std::vector<std::pair<std::size_t, std::size_t> > chords;  // positions, first < second
      std::vector<std::size_t> chord_seg;                          // a segment (index into segs) per chord
      auto cf = chords_of_face.find(fi);
      if(cf != chords_of_face.end())
        for(std::size_t k : cf->second)
        {
          const Cut_segment& s = segs[cls[k].seg];
          std::size_t i = position(vertex_of(s.pa)), j = position(vertex_of(s.pb));
          if(i > j) std::swap(i, j);
          bool dup = false;
          for(std::size_t c = 0; c < chords.size(); ++c)
          {
            auto [i2, j2] = chords[c];
            if(i2 == i && j2 == j) { dup = true; break; }
            if((i < i2 && i2 < j && j < j2) || (i2 < i && i < j2 && j2 < j))
            {
              const Cut_segment& s2 = segs[chord_seg[c]];
              std::string other = (s2.file == s.file || *s2.file == *s.file) ? "line " + std::to_string(s2.line)
                                                                            : *s2.file + ":" + std::to_string(s2.line);
              throw Input_error(*s.file, s.line, "this segment crosses the segment at " + other + " inside face " +
                                                     std::to_string(fi) + " (crossing segments are not supported)");
            }
          }
          if(!dup) { chords.emplace_back(i, j); chord_seg.push_back(cls[k].seg); }
        }
      // split the polygon along the chords (positions), then triangulate each piece
      std::vector<std::vector<std::size_t> > polys(1);
      for(std::size_t i = 0; i < K; ++i) polys[0].push_back(i);
      for(auto [i, j] : chords)
      {
        bool done = false;
        for(std::size_t p = 0; p < polys.size() && !done; ++p)
        {
          auto& P = polys[p];
          auto pi = std::find(P.begin(), P.end(), i), pj = std::find(P.begin(), P.end(), j);
          if(pi == P.end() || pj == P.end()) continue;
          std::size_t a = std::size_t(pi - P.begin()), b = std::size_t(pj - P.begin());
          if(a > b) std::swap(a, b);
          if(b - a == 1 || (a == 0 && b == P.size() - 1)) { done = true; break; }  // already an edge
          std::vector<std::size_t> P1(P.begin() + static_cast<std::ptrdiff_t>(a), P.begin() + static_cast<std::ptrdiff_t>(b) + 1);
          std::vector<std::size_t> P2(P.begin() + static_cast<std::ptrdiff_t>(b), P.end());
          P2.insert(P2.end(), P.begin(), P.begin() + static_cast<std::ptrdiff_t>(a) + 1);
          P = std::move(P1);
          polys.push_back(std::move(P2));
          done = true;
        }
        if(!done) throw std::logic_error("conforming_cut: chord not inside any piece");
      }
      tris.clear();
      long long next_line = 3;
      std::map<std::pair<std::size_t, std::size_t>, long long> chord_line;
      for(auto [i, j] : chords) chord_line[{i, j}] = next_line++;
      for(const auto& P : polys)
      {
        std::vector<std::size_t> vids;
        std::vector<long long> lines;
        for(std::size_t k = 0; k < P.size(); ++k)
        {
          std::size_t a = P[k], b = P[(k + 1) % P.size()];
          vids.push_back(cyc[a]);
          if(b == (a + 1) % K) lines.push_back(side[a]);
          else lines.push_back(chord_line.at({std::min(a, b), std::max(a, b)}));
        }
        internal::triangulate_convex_polygon(vids, lines, next_line, pos, tris);
      }
      soup.triangles[fi] = tris.front();
      for(std::size_t k = 1; k < tris.size(); ++k) extra.push_back(tris[k]);
    }
    soup.triangles.insert(soup.triangles.end(), extra.begin(), extra.end());
    Mesh_read_info dummy;
    try
    {
      triangle_soup_to_mesh(soup, result.mesh, dummy, "<conforming cut>");
    }
    catch(const Input_error& e)
    {
      throw std::logic_error(std::string("conforming_cut: invalid result mesh: ") + e.what());
    }
    // chain
    result.chain.assign(result.mesh.number_of_edges(), 0);
    for(const Classified& c : cls)
    {
      std::size_t va = vertex_of(segs[c.seg].pa), vb = vertex_of(segs[c.seg].pb);
      if(c.edge == none)
      {
        internal::add_chain(result.mesh, result.chain, va, vb, 1);
        continue;
      }
      auto it = along.find(c.edge);
      if(it == along.end())
      {
        internal::add_chain(result.mesh, result.chain, va, vb, 1);
        continue;
      }
      const auto& list = it->second;
      std::size_t ia = std::size_t(std::find(list.begin(), list.end(), va) - list.begin());
      std::size_t ib = std::size_t(std::find(list.begin(), list.end(), vb) - list.begin());
      if(ia >= list.size() || ib >= list.size())
        throw std::logic_error("conforming_cut: segment end not on its edge");
      if(ia < ib) for(std::size_t k = ia; k < ib; ++k) internal::add_chain(result.mesh, result.chain, list[k], list[k + 1], 1);
      else for(std::size_t k = ia; k > ib; --k) internal::add_chain(result.mesh, result.chain, list[k], list[k - 1], 1);
    }
  }
  result.vertices_after_cut = result.mesh.number_of_vertices();
  result.faces_after_cut = result.mesh.number_of_faces();
  result.cut_new_vertices = result.vertices_after_cut - nv;
  result.cut_new_faces = result.faces_after_cut - nf;

  if(options.refine_short_pieces && options.min_piece_edges > 1)
  {
    result.refined_pieces = internal::refine_short_pieces(result.mesh, result.chain, options.min_piece_edges);
    result.chain.resize(result.mesh.number_of_edges(), 0);
  }
  result.refine_new_vertices = result.mesh.number_of_vertices() - result.vertices_after_cut;
  result.refine_new_faces = result.mesh.number_of_faces() - result.faces_after_cut;
  return result;
}

/*!
  \brief `conforming_cut()` for a single curve set.
*/
template <class Point>
Cut_result<Point> conforming_cut(const CGAL::Surface_mesh<Point>& mesh, const Curve_set& curve,
                                 const Cut_options& options = Cut_options())
{
  return conforming_cut(mesh, std::vector<Curve_set>{curve}, options);
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_IO_CONFORMING_CUT_H
