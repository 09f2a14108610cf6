// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Step of conforming_cut(): a face of the input whose sides received new vertices is split along the
// curve segments that cross it (chords), and every piece is triangulated without degenerate triangles.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_FACES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_FACES_H

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

// angle at a of the triangle abc
template <class Point>
double corner_angle(const Point& a, const Point& b, const Point& c)
{
  const double u[3] = {CGAL::to_double(b.x()) - CGAL::to_double(a.x()), CGAL::to_double(b.y()) - CGAL::to_double(a.y()),
                       CGAL::to_double(b.z()) - CGAL::to_double(a.z())};
  const double w[3] = {CGAL::to_double(c.x()) - CGAL::to_double(a.x()), CGAL::to_double(c.y()) - CGAL::to_double(a.y()),
                       CGAL::to_double(c.z()) - CGAL::to_double(a.z())};
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
  The chords join two vertices of `f` that are not on a common side; they do not cross.

  `line` (halfedge -> int) tells on which straight line each side of a piece lies: the three sides of the
  triangle get 0, 1, 2, every chord and every diagonal a new number from `next_line`. A vertex of a piece is
  a corner where its two sides lie on different lines. Pieces are triangulated by clipping ears at corners
  (so no triangle has three collinear vertices), the ear with the largest smallest angle first, and never
  an ear that would leave fewer than three corners. The descriptor `f` stays with the piece, and in the
  end the triangle, that has the corner `keep`, and `target(halfedge(f, tm))` is `keep`. New faces are
  added with `add_face()` (appended, for `Surface_mesh`). Every piece gets `f` in `origin` (face -> face).
*/
template <class TriangleMesh, class VertexPointMap, class LineMap, class OriginMap>
void cut_and_triangulate_face(
  TriangleMesh& tm, VertexPointMap vpm, typename boost::graph_traits<TriangleMesh>::face_descriptor f,
  const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3>& corner,
  const std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                              typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& chords,
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor keep, LineMap line, int& next_line, OriginMap origin)
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;

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

  // the chords split f into pieces
  std::vector<face_descriptor> pieces(1, f);
  for(const auto& chord : chords)
  {
    const vertex_descriptor u = chord.first, v = chord.second;
    halfedge_descriptor hu = Traits::null_halfedge(), hv = Traits::null_halfedge();
    face_descriptor piece = Traits::null_face();
    for(face_descriptor p : pieces)
    {
      hu = hv = Traits::null_halfedge();
      for(halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(p, tm), tm))
      {
        if(target(g, tm) == u) hu = g;
        if(target(g, tm) == v) hv = g;
      }
      if(hu != Traits::null_halfedge() && hv != Traits::null_halfedge()) { piece = p; break; }
    }
    CGAL_assertion(piece != Traits::null_face());
    if(piece == Traits::null_face() || target(next(hu, tm), tm) == v || target(next(hv, tm), tm) == u)
      continue;   // already an edge of the piece
    // split_face(h1, h2) leaves face(h1) the part from target(h2) to target(h1): f keeps `keep`
    bool keep_on_v_to_u = (v == keep);
    for(halfedge_descriptor g = next(hv, tm); !keep_on_v_to_u; g = next(g, tm))
    {
      keep_on_v_to_u = (target(g, tm) == keep);
      if(g == hu) break;
    }
    const bool swap = (piece == f && !keep_on_v_to_u);
    const halfedge_descriptor h = CGAL::Euler::split_face(swap ? hv : hu, swap ? hu : hv, tm);
    put(line, h, next_line);
    put(line, opposite(h, tm), next_line);
    ++next_line;
    put(origin, face(opposite(h, tm), tm), f);
    pieces.push_back(face(opposite(h, tm), tm));
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

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_FACES_H
