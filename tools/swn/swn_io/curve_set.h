// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Curves as read from files: points (mesh vertices, points on mesh edges) and directed segments between
// them, each with the line it came from; and the authors' edge numbering the files refer to.

#ifndef CGAL_SWN_TOOL_IO_CURVE_SET_H
#define CGAL_SWN_TOOL_IO_CURVE_SET_H

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief a point of an input curve: a mesh vertex, or a point on a mesh edge.
*/
struct Curve_point
{
  /// kind of point
  enum Kind { VERTEX, EDGE };
  /// vertex point or edge point
  Kind kind = VERTEX;
  /// the vertex index (VERTEX), or the edge index in the authors' numbering (EDGE)
  std::size_t element = 0;
  /// EDGE only: parameter in (0,1) from first(e) (t = 0) to second(e) (t = 1)
  double t = 0.;
  /// 1-based line of the record that defined the point (0 if none)
  std::size_t line = 0;
};

/*!
  \brief a directed segment of an input curve, between two entries of `Curve_set::points`.
*/
struct Curve_segment
{
  /// index of the start point in `Curve_set::points`
  std::size_t a = 0;
  /// index of the end point in `Curve_set::points`
  std::size_t b = 0;
  /// 1-based line of the record that defined the segment
  std::size_t line = 0;
};

/*!
  \brief a pair of faces of a dual chain: the function jumps by +1 from `face_a` to `face_b`.
*/
struct Curve_dual_pair
{
  /// the face the jump starts from (0-based)
  std::size_t face_a = 0;
  /// the face the jump goes to, one higher than `face_a` (0-based)
  std::size_t face_b = 0;
  /// 1-based line of the `c` record
  std::size_t line = 0;
  /// the offset added to the record's indices when they were read (-1 for 1-based indices): the file
  /// numbers the faces `face_a - index_offset` and `face_b - index_offset`
  long long index_offset = -1;
};

/*!
  \brief a curve read from a file, in a neutral description.
*/
struct Curve_set
{
  /// the points of the curve, referred to by index from `segments`
  std::vector<Curve_point> points;
  /// the directed segments of the curve
  std::vector<Curve_segment> segments;
  /// the pairs of faces of the dual chains (`c` records)
  std::vector<Curve_dual_pair> dual_pairs;
  /// the file the curve came from, used in error messages
  std::string file;
};

/*!
  \brief curve file formats; see the file documentation for the detection rule.
*/
enum class Curve_file_format { AUTO, AUTHORS, POLYLINES, HALFEDGES };

/*!
  \brief returns, for each edge of the authors' numbering, the halfedge from first(e) to second(e).

  The numbering scans the faces in index order and, within face (v0,v1,v2), the halfedges v0->v1, v1->v2,
  v2->v0, where v0 is `target(halfedge(f, mesh))` (the first vertex in the file for meshes read by
  `read_mesh()`). The first time an undirected edge is met it gets the next index and its direction.
*/
template <class Point>
std::vector<typename CGAL::Surface_mesh<Point>::Halfedge_index>
authors_edge_halfedges(const CGAL::Surface_mesh<Point>& mesh)
{
  typedef typename CGAL::Surface_mesh<Point>::Halfedge_index Halfedge_index;
  std::vector<Halfedge_index> result;
  result.reserve(mesh.number_of_edges());
  std::vector<bool> seen(mesh.number_of_edges() + mesh.number_of_removed_edges(), false);
  for(auto f : mesh.faces())
  {
    Halfedge_index h0 = mesh.halfedge(f);
    Halfedge_index h = mesh.next(h0);
    while(true)
    {
      std::size_t e = std::size_t(mesh.edge(h));
      if(!seen[e]) { seen[e] = true; result.push_back(h); }
      if(h == h0) break;
      h = mesh.next(h);
    }
  }
  return result;
}

/*!
  \brief returns, for each edge index of the authors' numbering (notes section 5.3), the pair
  (first(e), second(e)) of vertex indices. See `authors_edge_halfedges()`.
*/
template <class Point>
std::vector<std::pair<std::size_t, std::size_t> > authors_edge_numbering(const CGAL::Surface_mesh<Point>& mesh)
{
  std::vector<std::pair<std::size_t, std::size_t> > r;
  for(auto h : authors_edge_halfedges(mesh))
    r.emplace_back(std::size_t(mesh.source(h)), std::size_t(mesh.target(h)));
  return r;
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_CURVE_SET_H
