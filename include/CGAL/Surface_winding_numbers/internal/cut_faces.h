// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Steps of conforming_cut() on the faces: the curves' points, edges, faces and segments of the cut; the
// chords of every face and where they cross; a face of the input whose sides received new vertices split
// along its chords, and every piece triangulated without degenerate triangles.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_FACES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_FACES_H

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Barycentric coordinates closer than this to 0 are 0, points on an edge closer than this (relative to its
// length) are one point, and so are crossings on a chord.
constexpr double cut_snap_tolerance = 1e-9;

// A point of the curves before the cut: a vertex, or a point on an edge given by the barycentric
// coordinates of the edge's ends (`at_source`, `at_target` along the reference halfedge).
template <class TriangleMesh, class FT>
struct Cut_point
{
  // the vertex (an edge point: once inserted)
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex = boost::graph_traits<TriangleMesh>::null_vertex();
  std::size_t edge = std::size_t(-1);                                     // edge point: its Cut_edge
  FT at_source = FT(0), at_target = FT(0);
  bool used = false;                                                      // on a segment that is not skipped
};

// An edge of the input with points on it.
template <class TriangleMesh>
struct Cut_edge
{
  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h;      // the reference halfedge
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor source, target;
  std::vector<std::size_t> points;                                        // along h once sorted
};

// A face of the input that is cut: its corners, its sides (halfedge k from corner k to corner k+1) and
// the segments crossing it.
template <class TriangleMesh>
struct Cut_face
{
  typename boost::graph_traits<TriangleMesh>::face_descriptor f;
  std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3> corner;
  std::array<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, 3> side;
  std::vector<std::size_t> chords;                                        // segments, deduplicated
  // where chords cross: for each chord, its crossings (parameter from its first point, crossing) in order;
  // each crossing's barycentric coordinates, and its vertex once inserted
  std::vector<std::vector<std::pair<double, std::size_t> > > crossings;
  std::vector<std::array<double, 3> > inner;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> inner_vertex;
};

// A segment between two consecutive points of a curve.
struct Cut_segment
{
  std::size_t a, b, curve, index;
  std::size_t edge;   // along an edge with points on it: its Cut_edge; none along another edge, or inside a face
  std::size_t face;   // inside a face: its Cut_face; none along an edge
};

// A chord of a face: from vertex a to vertex b on its border, through the crossings `inner` (indices of
// crossings of the face) in order.
template <class Vertex>
struct Face_chord
{
  Vertex a, b;
  std::vector<std::size_t> inner;
};

// Where the chords p0 p1 and q0 q1 of a triangle cross (points in barycentric coordinates, whose ends
// interleave around the triangle): p0 + t (p1 - p0) = q0 + u (q1 - q0), with t and u kept at least the
// snapping tolerance away from the ends (the crossing of two chords is inside the triangle).
inline void chord_crossing(const std::array<double, 3>& p0, const std::array<double, 3>& p1,
                           const std::array<double, 3>& q0, const std::array<double, 3>& q1, double& t, double& u)
{
  // in the affine coordinates 1 and 2
  const double a = p1[1] - p0[1], b = -(q1[1] - q0[1]), c = p1[2] - p0[2], d = -(q1[2] - q0[2]);
  const double r = q0[1] - p0[1], s = q0[2] - p0[2];
  const double det = a * d - b * c;
  t = (r * d - b * s) / det;
  u = (a * s - c * r) / det;
  auto clamp = [](double x) {
    return x == x ? (std::min)(1 - cut_snap_tolerance, (std::max)(cut_snap_tolerance, x)) : 0.5;
  };
  t = clamp(t);
  u = clamp(u);
}

// The crossings of the chords of a face, given by their ends in barycentric coordinates (`from`, `to`) and
// by the positions of their ends around the face (`range`, ordered pairs): two chords cross where their
// ends interleave. Fills, for each chord, its crossings (parameter from `from`, index into `inner`) in
// order along it, and the barycentric coordinates of every crossing in `inner`. A crossing closer than the
// snapping tolerance along a chord to one already on it is that one (three chords or more through a point).
template <class Position>
void chord_crossings(const std::vector<std::pair<Position, Position> >& range, const std::vector<std::array<double, 3> >& from,
                     const std::vector<std::array<double, 3> >& to,
                     std::vector<std::vector<std::pair<double, std::size_t> > >& crossings,
                     std::vector<std::array<double, 3> >& inner)
{
  const std::size_t n = range.size(), none = std::size_t(-1);
  crossings.assign(n, {});
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
    {
      const auto &r = range[i], &q = range[j];
      if(!((r.first < q.first && q.first < r.second && r.second < q.second) ||
           (q.first < r.first && r.first < q.second && q.second < r.second)))
        continue;   // the ends do not interleave around the face: no crossing
      double t, u;
      chord_crossing(from[i], to[i], from[j], to[j], t, u);
      std::size_t x = none;
      for(const auto& c : crossings[i]) if(std::abs(c.first - t) <= cut_snap_tolerance) x = c.second;
      for(const auto& c : crossings[j]) if(x == none && std::abs(c.first - u) <= cut_snap_tolerance) x = c.second;
      if(x == none)
      {
        x = inner.size();
        inner.push_back({from[i][0] + t * (to[i][0] - from[i][0]), from[i][1] + t * (to[i][1] - from[i][1]),
                         from[i][2] + t * (to[i][2] - from[i][2])});
      }
      for(auto [c, param] : {std::make_pair(i, t), std::make_pair(j, u)})
      {
        bool known = false;
        for(const auto& k : crossings[c]) known = known || k.second == x;
        if(!known) crossings[c].emplace_back(param, x);
      }
    }
  for(auto& c : crossings) std::sort(c.begin(), c.end());
}

// The chords of every face to cut (its segments, deduplicated: `Cut_face::chords`) and where they cross
// (`Cut_face::crossings` and `inner`, by chord_crossings() on the chords' ends around the face). Returns, for
// every segment inside a face, the chord it runs along (the first segment with its two points).
template <class TriangleMesh, class FT>
std::vector<std::size_t> cross_chords(const TriangleMesh& tm, const std::vector<Cut_point<TriangleMesh, FT> >& points,
                                      const std::vector<Cut_edge<TriangleMesh> >& cut_edges,
                                      const std::vector<Cut_segment>& segments, std::vector<Cut_face<TriangleMesh> >& cut_faces)
{
  const std::size_t none = std::size_t(-1);
  // position of a point on the border of a cut face: (side, coordinate of the side's end)
  auto position = [&](const Cut_face<TriangleMesh>& cf, std::size_t p) {
    for(int k = 0; k < 3; ++k)
    {
      if(points[p].edge == none)
      {
        if(points[p].vertex == cf.corner[k]) return std::make_pair(k, FT(0));
        continue;
      }
      const auto h = cut_edges[points[p].edge].h;
      if(cf.side[k] == h) return std::make_pair(k, points[p].at_target);
      if(cf.side[k] == opposite(h, tm)) return std::make_pair(k, points[p].at_source);
    }
    return std::make_pair(3, FT(0));   // cannot happen: the point is on the face
  };
  std::vector<std::size_t> chord_of(segments.size(), none);   // the chord a segment inside a face runs along
  for(std::size_t s = 0; s < segments.size(); ++s)
  {
    if(segments[s].face == none) continue;
    auto& cf = cut_faces[segments[s].face];
    for(std::size_t t : cf.chords)
    {
      const std::size_t a = segments[t].a, b = segments[t].b;
      if((a == segments[s].a && b == segments[s].b) || (a == segments[s].b && b == segments[s].a)) chord_of[s] = t;
    }
    if(chord_of[s] == none)
    {
      chord_of[s] = s;
      cf.chords.push_back(s);
    }
  }
  for(auto& cf : cut_faces)
  {
    const std::size_t n = cf.chords.size();
    std::vector<std::pair<std::pair<int, FT>, std::pair<int, FT> > > range(n);
    std::vector<std::array<double, 3> > from(n), to(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Cut_segment& sg = segments[cf.chords[i]];
      range[i] = std::make_pair(position(cf, sg.a), position(cf, sg.b));
      for(int end = 0; end < 2; ++end)
      {
        const auto pos = end == 0 ? range[i].first : range[i].second;
        std::array<double, 3>& bary = end == 0 ? from[i] : to[i];
        bary = {0., 0., 0.};
        bary[pos.first] = 1 - CGAL::to_double(pos.second);
        bary[(pos.first + 1) % 3] = CGAL::to_double(pos.second);
      }
      if(range[i].second < range[i].first) std::swap(range[i].first, range[i].second);
    }
    chord_crossings(range, from, to, cf.crossings, cf.inner);
  }
  return chord_of;
}

// angle at a of the triangle abc (the sides divided by their largest coordinate: no underflow or
// overflow at any scale)
template <class Point>
double corner_angle(const Point& a, const Point& b, const Point& c)
{
  double u[3] = {CGAL::to_double(b.x()) - CGAL::to_double(a.x()), CGAL::to_double(b.y()) - CGAL::to_double(a.y()),
                 CGAL::to_double(b.z()) - CGAL::to_double(a.z())};
  double w[3] = {CGAL::to_double(c.x()) - CGAL::to_double(a.x()), CGAL::to_double(c.y()) - CGAL::to_double(a.y()),
                 CGAL::to_double(c.z()) - CGAL::to_double(a.z())};
  for(double* v : {u, w})
  {
    const double m = (std::max)({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    if(m > 0)
      for(int k = 0; k < 3; ++k) v[k] /= m;
  }
  const double x[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return std::atan2(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), u[0] * w[0] + u[1] * w[1] + u[2] * w[2]);
}

template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
face_loop(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> loop;
  for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) loop.push_back(h);
  return loop;
}

/*
  Splits the face `f` of `tm` along the chords and triangulates the pieces.

  Before the call `f` is a triangle of the input with corners `corner[0..2]` (counter-clockwise) whose
  sides may carry vertices inserted by the cut: a convex polygon, some of whose vertices are collinear.
  The chords join two vertices of `f` that are not on a common side; where two of them cross they go
  through a crossing (`inner` of the chord): the first chord through a crossing inserts its vertex
  (`inner_vertex`, at the barycentric coordinates `inner` with respect to the corners), the others go
  through it. Every piece stays convex.

  `line` (halfedge -> int) tells on which straight line each side of a piece lies: the three sides of the
  triangle get 0, 1, 2, every chord and every diagonal a new number from `next_line`. A vertex of a piece is
  a corner where its two sides lie on different lines. Pieces are triangulated by clipping ears at corners
  (so no triangle has three collinear vertices), the ear with the largest smallest angle first, and never
  an ear that would leave fewer than three corners. The descriptor `f` stays with the piece, and in the
  end the triangle, that has the corner `keep`, and `target(halfedge(f, tm))` is `keep`. New faces are
  added with `add_face()` (appended, for `Surface_mesh`). Every piece gets `f` in `origin` (face -> face),
  and no face outside `f` has `f` there (the pieces are told from their neighbours by it).
*/
template <class TriangleMesh, class VertexPointMap, class LineMap, class OriginMap>
void cut_and_triangulate_face(
  TriangleMesh& tm, VertexPointMap vpm, typename boost::graph_traits<TriangleMesh>::face_descriptor f,
  const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3>& corner,
  const std::vector<Face_chord<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& chords,
  const std::vector<std::array<double, 3> >& inner,
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& inner_vertex,
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor keep, LineMap line, int& next_line, OriginMap origin)
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  auto inner_point = [&](const std::array<double, 3>& b) {   // a combination of the corners
    double xyz[3] = {0., 0., 0.};
    for(int k = 0; k < 3; ++k)
    {
      const Point& c = get(vpm, corner[k]);
      for(int i = 0; i < 3; ++i) xyz[i] += b[k] * CGAL::to_double(c[i]);
    }
    return Point(xyz[0], xyz[1], xyz[2]);
  };
  inner_vertex.assign(inner.size(), Traits::null_vertex());

  // the sides of the triangle
  std::vector<halfedge_descriptor> loop = face_loop(f, tm);
  std::size_t start = 0;
  while(source(loop[start], tm) != corner[0]) ++start;
  for(std::size_t k = 0, side = 0; k < loop.size(); ++k)
  {
    const halfedge_descriptor g = loop[(start + k) % loop.size()];
    put(line, g, int(side));
    if(target(g, tm) == corner[(side + 1) % 3]) ++side;
  }

  // splits the piece that has u and v on its border along uv (nothing if uv is a side of it), on `chord_line`.
  // The piece is found among the faces around u (the pieces of f are the faces whose origin is f): searching
  // all pieces made the cut quadratic in the crossings of a face.
  put(origin, f, f);
  std::vector<face_descriptor> pieces(1, f);
  auto split_piece = [&](vertex_descriptor u, vertex_descriptor v, int chord_line) {
    halfedge_descriptor hu = Traits::null_halfedge(), hv = Traits::null_halfedge();
    face_descriptor piece = Traits::null_face();
    for(halfedge_descriptor gu : CGAL::halfedges_around_target(u, tm))
    {
      if(is_border(gu, tm) || get(origin, face(gu, tm)) != f) continue;
      hv = Traits::null_halfedge();
      for(halfedge_descriptor g : CGAL::halfedges_around_face(gu, tm))
        if(target(g, tm) == v) hv = g;
      if(hv != Traits::null_halfedge()) { hu = gu; piece = face(gu, tm); break; }
    }
    CGAL_assertion(piece != Traits::null_face());
    if(piece == Traits::null_face() || target(next(hu, tm), tm) == v || target(next(hv, tm), tm) == u)
      return;   // already an edge of the piece
    // split_face(h1, h2) leaves face(h1) the part from target(h2) to target(h1): f keeps `keep`
    bool keep_on_v_to_u = (v == keep);
    for(halfedge_descriptor g = next(hv, tm); !keep_on_v_to_u; g = next(g, tm))
    {
      keep_on_v_to_u = (target(g, tm) == keep);
      if(g == hu) break;
    }
    const bool swap = (piece == f && !keep_on_v_to_u);
    const halfedge_descriptor h = CGAL::Euler::split_face(swap ? hv : hu, swap ? hu : hv, tm);
    put(line, h, chord_line);
    put(line, opposite(h, tm), chord_line);
    put(origin, face(opposite(h, tm), tm), f);
    pieces.push_back(face(opposite(h, tm), tm));
  };
  // the chords split f into pieces
  for(const auto& chord : chords)
  {
    const int chord_line = next_line++;
    std::vector<vertex_descriptor> path{chord.a};
    for(std::size_t x : chord.inner) path.push_back(inner_vertex[x]);
    path.push_back(chord.b);
    for(std::size_t i = 0; i + 1 < path.size();)
    {
      std::size_t j = i + 1;   // the next vertex of the chord that is already in the mesh
      while(path[j] == Traits::null_vertex()) ++j;
      split_piece(path[i], path[j], chord_line);
      // the crossings between them, inserted on the new edge from path[i]
      vertex_descriptor from = path[i];
      for(std::size_t k = i + 1; k < j; ++k)
      {
        const halfedge_descriptor h = halfedge(from, path[j], tm).first;
        const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tm);   // hnew: from -> new, h: new -> path[j]
        inner_vertex[chord.inner[k - 1]] = path[k] = target(hnew, tm);
        put(vpm, path[k], inner_point(inner[chord.inner[k - 1]]));
        put(line, hnew, chord_line);
        put(line, opposite(hnew, tm), chord_line);
        from = path[k];
      }
      i = j;
    }
  }

  // ears
  for(std::size_t p = 0; p < pieces.size(); ++p)
  {
    face_descriptor piece = pieces[p];
    while(true)
    {
      loop = face_loop(piece, tm);
      const std::size_t n = loop.size();
      if(n <= 3) break;
      auto at = [&](std::size_t i) { return loop[(i + n) % n]; };   // vertex i is source(loop[i])
      std::vector<char> is_corner(n);
      std::size_t corners = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        is_corner[i] = get(line, at(i + n - 1)) != get(line, at(i));
        corners += is_corner[i] ? 1 : 0;
      }
      std::size_t best = n;
      double best_quality = -1.;
      for(std::size_t i = 0; i < n; ++i)
      {
        if(!is_corner[i]) continue;
        const std::size_t left = corners - 1 + (is_corner[(i + n - 1) % n] ? 0 : 1) + (is_corner[(i + 1) % n] ? 0 : 1);
        if(left < 3) continue;
        const auto& a = get(vpm, source(at(i + n - 1), tm));
        const auto& b = get(vpm, source(at(i), tm));
        const auto& c = get(vpm, target(at(i), tm));
        double q = (std::min)(corner_angle(a, b, c), (std::min)(corner_angle(b, c, a), corner_angle(c, a, b)));
        if(!(q == q)) q = 0.;
        if(q > best_quality) { best_quality = q; best = i; }
      }
      if(best == n) best = 0;   // cannot happen for a convex polygon with three corners or more
      // the diagonal from source(at(best - 1)) to target(at(best)) cuts the ear off
      const bool ear_keeps_f = (piece == f && source(at(best), tm) == keep);
      const halfedge_descriptor h1 = at(best + n - 2), h2 = at(best);
      const halfedge_descriptor h = ear_keeps_f ? CGAL::Euler::split_face(h2, h1, tm) : CGAL::Euler::split_face(h1, h2, tm);
      put(line, h, next_line);
      put(line, opposite(h, tm), next_line);
      ++next_line;
      put(origin, face(h, tm), f);
      put(origin, face(opposite(h, tm), tm), f);
      if(ear_keeps_f) piece = face(opposite(h, tm), tm);   // the rest moved to the new face
    }
  }

  for(halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(f, tm), tm))
    if(target(g, tm) == keep) { set_halfedge(f, g, tm); break; }
}

// Cuts every face to cut (`face_of`: face -> Cut_face + 1) along its chords, in the order of faces(tm), for
// the numbering of the new faces; each keeps the piece with target(halfedge(f)), the first vertex of f for
// meshes read from files.
template <class TriangleMesh, class VertexPointMap, class FT, class FaceOfMap, class OriginMap>
void cut_every_face(TriangleMesh& tm, VertexPointMap vpm, FaceOfMap face_of, std::vector<Cut_face<TriangleMesh> >& cut_faces,
                    const std::vector<Cut_point<TriangleMesh, FT> >& points, const std::vector<Cut_segment>& segments,
                    OriginMap origin)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  if(cut_faces.empty()) return;
  auto line = get(CGAL::dynamic_halfedge_property_t<int>(), tm);
  int next_line = 3;
  std::vector<Face_chord<vertex_descriptor> > chords;
  for(auto f : faces(tm))
  {
    if(get(face_of, f) == 0) continue;
    auto& cf = cut_faces[get(face_of, f) - 1];
    chords.clear();
    for(std::size_t i = 0; i < cf.chords.size(); ++i)
    {
      chords.push_back({points[segments[cf.chords[i]].a].vertex, points[segments[cf.chords[i]].b].vertex, {}});
      for(const auto& c : cf.crossings[i]) chords.back().inner.push_back(c.second);
    }
    cut_and_triangulate_face(tm, vpm, f, cf.corner, chords, cf.inner, cf.inner_vertex, cf.corner[1], line, next_line, origin);
  }
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_FACES_H
