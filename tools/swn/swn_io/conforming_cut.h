// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// The curves of the files on the edges of the mesh: `vertex_curve_chain()` for curves through vertices only,
// `conforming_cut()` for any curve, through the library's CGAL::Surface_winding_numbers::conforming_cut(),
// with the file and line of the record at fault when the curves are refused.

#ifndef CGAL_SWN_TOOL_IO_CONFORMING_CUT_H
#define CGAL_SWN_TOOL_IO_CONFORMING_CUT_H

#include "swn_io/curve_set.h"
#include "swn_io/errors.h"

#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/conforming_cut.h>

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief options of `conforming_cut()`: the short-piece refinement of the library's `conforming_cut()`.
*/
struct Cut_options
{
  /// split the edges of short curve pieces ending at interior endpoints
  bool refine_short_pieces = true;
  /// pieces with fewer edges than this are refined; at most `Conforming_cut_result::max_minimum_piece_edges`
  /// (65536) with the refinement on, else `conforming_cut()` throws `std::invalid_argument`
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
  /// per face index of `mesh`: the index of the input face it is a piece of (faces not cut: themselves)
  std::vector<std::size_t> face_origin;
  /// for every point of the curve set(s) (in order, sets concatenated), its vertex in `mesh`, or -1 if the
  /// point is on no segment (or on degenerate ones only)
  std::vector<std::size_t> point_vertex;
  /// true if the cut inserted vertices
  bool cut = false;
  /// vertices/faces of the input mesh
  std::size_t input_vertices = 0, input_faces = 0;
  /// vertices/faces added by the conforming cut
  std::size_t cut_new_vertices = 0, cut_new_faces = 0;
  /// vertices/faces after the cut, before the short-piece refinement
  std::size_t vertices_after_cut = 0, faces_after_cut = 0;
  /// vertices/faces added by the short-piece refinement, and the number of refined pieces
  std::size_t refine_new_vertices = 0, refine_new_faces = 0, refined_pieces = 0;
  /// segments skipped because their two points coincide
  std::size_t skipped_segments = 0;
  /// number of segments that produced chain values
  std::size_t used_segments = 0;
};

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
  std::vector<typename Mesh::Halfedge_index> halfedges;
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
    const auto h = mesh.halfedge(typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(p.element)),
                                 typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(q.element)));
    if(h == Mesh::null_halfedge())
      throw Input_error(curve.file, s.line, "vertices " + std::to_string(p.element) + " and " +
                                               std::to_string(q.element) + " are not adjacent");
    halfedges.push_back(h);
  }
  std::vector<int> chain(mesh.number_of_edges(), 0);
  auto chain_map = boost::make_iterator_property_map(chain.begin(), get(boost::edge_index, mesh));
  add_halfedges_to_chain(mesh, halfedges, chain_map);
  return chain;
}

namespace internal {

// Curves may end on the border of the mesh but not run along it (the solver refuses a chain on a border
// edge, naming the mesh). After the cut, a segment whose two vertices `ends[k]` are joined by border edges
// through vertices added by the cut (indices from `input_vertices` on: the segment ran along one edge of the
// input) is blamed, at its file and line `where[k]`, if one of those edges keeps a chain value.
template <class Point, class Vertex>
void refuse_curves_along_the_border(const CGAL::Surface_mesh<Point>& mesh, const std::vector<int>& chain,
                                    std::size_t input_vertices, const std::vector<std::vector<Vertex> >& ends,
                                    const std::vector<std::pair<const std::string*, std::size_t> >& where)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  bool any = false;
  for(auto e : mesh.edges()) any = any || (chain[std::size_t(e)] != 0 && mesh.is_border(e));
  if(!any) return;
  // from the border halfedge h on, in the border's direction (forward) or against it, until `to` or a vertex of
  // the input: the vertex reached, and whether an edge on the way keeps a chain value
  auto walk = [&](Halfedge_index h, bool forward, Vertex to, bool& charged) {
    for(;;)
    {
      charged = charged || chain[std::size_t(mesh.edge(h))] != 0;
      const Vertex v = forward ? mesh.target(h) : mesh.source(h);
      if(v == to || std::size_t(v) < input_vertices) return v;
      h = forward ? mesh.next(h) : mesh.prev(h);
    }
  };
  auto border_halfedge_into = [&](Vertex v) {
    Halfedge_index in = Mesh::null_halfedge();
    for(Halfedge_index h : CGAL::halfedges_around_target(v, mesh))
      if(mesh.is_border(h)) in = h;
    return in;
  };
  for(std::size_t k = 0; k < ends.size(); ++k)
  {
    const Vertex a = ends[k][0], b = ends[k][1];
    if(a == Mesh::null_vertex() || b == Mesh::null_vertex() || !mesh.is_border(a) || !mesh.is_border(b)) continue;
    const Halfedge_index in = border_halfedge_into(a);
    if(in == Mesh::null_halfedge()) continue;
    for(bool forward : {true, false})
    {
      bool charged = false;
      if(walk(forward ? mesh.next(in) : in, forward, b, charged) != b || !charged) continue;
      // the edge of the input: its two vertices of the input, from a away from b and from b away from a
      bool ignored = false;
      Vertex from = a, to = b;
      if(std::size_t(a) >= input_vertices) from = walk(forward ? in : mesh.next(in), !forward, Mesh::null_vertex(), ignored);
      const Halfedge_index out = border_halfedge_into(b);
      if(std::size_t(b) >= input_vertices) to = walk(forward ? mesh.next(out) : out, forward, Mesh::null_vertex(), ignored);
      throw Input_error(*where[k].first, where[k].second,
                        "the curve runs along the edge from vertex " + std::to_string((std::min)(std::size_t(from), std::size_t(to))) +
                            " to vertex " + std::to_string((std::max)(std::size_t(from), std::size_t(to))) +
                            ", on the border of the mesh (it has one face): curves may end on the border but not run along it");
    }
  }
}

} // namespace internal

/*!
  \brief makes the curves conform to the mesh edges and returns the cut and refined mesh with the curves'
  chain.

  Every segment of the curve sets becomes a curve of two points for the library's
  `CGAL::Surface_winding_numbers::conforming_cut()` (see there for the cut, the numbering of the new
  vertices and faces and the refinement of short pieces): a vertex point is located in a face around its
  vertex, an edge point `e J T` at `(1-T, T)` along the authors' halfedge of edge `J`.

  \param mesh a mesh as returned by `read_mesh()` (no garbage; `halfedge(f)` at the face's first vertex)
  \param curves the curve sets, all on `mesh`; their points are numbered consecutively in
         `Cut_result::point_vertex`
  \param options refinement options
  \throws Input_error (with the file and line of the offending record) on dual pairs ("dual chains (c lines)
  are not supported yet"), an index out of range, t outside [0,1], a segment whose points share no face (segments
  crossing inside a face get a vertex where they cross), or a segment along the border of the mesh where the
  curves do not cancel (curves may end on the border, not run along it).
*/
template <class Point>
Cut_result<Point> conforming_cut(const CGAL::Surface_mesh<Point>& mesh, const std::vector<Curve_set>& curves,
                                 const Cut_options& options = Cut_options())
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef std::pair<typename Mesh::Face_index, std::array<double, 3> > Location;
  namespace PMP = CGAL::Polygon_mesh_processing;

  if(mesh.has_garbage())
    throw std::invalid_argument("conforming_cut: the mesh has garbage (call collect_garbage() first)");
  for(const Curve_set& cs : curves)
    if(!cs.dual_pairs.empty())
      throw Input_error(cs.file, cs.dual_pairs.front().line, "dual chains (c lines) are not supported yet");

  const std::size_t nv = mesh.number_of_vertices(), nf = mesh.number_of_faces();
  const std::vector<Halfedge_index> ae = authors_edge_halfedges(mesh);
  auto locate = [&](const Curve_set& cs, const Curve_point& p) -> Location {
    if(p.kind == Curve_point::VERTEX)
    {
      if(p.element >= nv)
        throw Input_error(cs.file, p.line, "vertex index " + std::to_string(p.element) + " is out of range (" +
                                              std::to_string(nv) + " vertices)");
      const Vertex_index v(static_cast<typename Mesh::size_type>(p.element));
      if(mesh.is_isolated(v)) return Location(Mesh::null_face(), {1., 0., 0.});   // on no face: refused below
      return PMP::locate_vertex<double>(v, mesh);
    }
    if(p.element >= ae.size())
      throw Input_error(cs.file, p.line, "edge index " + std::to_string(p.element) + " is out of range (" +
                                            std::to_string(ae.size()) + " edges)");
    if(!(p.t >= 0. && p.t <= 1.))
      throw Input_error(cs.file, p.line, "edge parameter t is not in [0,1]");
    return PMP::locate_on_halfedge<double>(ae[p.element], p.t, mesh);
  };

  // one curve of two points per segment, with where it comes from
  std::vector<std::array<Location, 2> > segments;
  std::vector<std::pair<const std::string*, std::size_t> > where;   // file, line
  std::vector<std::array<std::size_t, 2> > ends;                    // the points, numbered over all sets
  std::size_t base = 0, skipped = 0;
  for(const Curve_set& cs : curves)
  {
    for(const Curve_segment& s : cs.segments)
    {
      if(s.a >= cs.points.size() || s.b >= cs.points.size())
        throw Input_error(cs.file, s.line, "segment refers to an undefined point");
      const Curve_point &p = cs.points[s.a], &q = cs.points[s.b];
      const Location lp = locate(cs, p), lq = locate(cs, q);
      if(p.kind == q.kind && p.element == q.element && (p.kind == Curve_point::VERTEX || p.t == q.t)) { ++skipped; continue; }
      segments.push_back({lp, lq});
      where.emplace_back(&cs.file, s.line);
      ends.push_back({base + s.a, base + s.b});
    }
    base += cs.points.size();
  }

  Cut_result<Point> result;
  result.input_vertices = nv;
  result.input_faces = nf;
  result.mesh = mesh;
  auto chain = result.mesh.template add_property_map<typename Mesh::Edge_index, int>("e:swn_cut_chain", 0).first;
  auto origin = result.mesh.template add_property_map<typename Mesh::Face_index, typename Mesh::Face_index>("f:swn_cut_origin").first;
  const auto cut = CGAL::Surface_winding_numbers::conforming_cut(
    result.mesh, segments, chain,
    parameters::refine_short_pieces(options.refine_short_pieces, parameters::minimum_piece_edges(options.min_piece_edges,
    parameters::face_origin_map(origin))));
  if(cut.error == cut.INVALID_PARAMETER)   // a setting, not the curve file
    throw std::invalid_argument(cut.message);
  if(!cut)
  {
    const auto& [file, line] = where[cut.curve];
    throw Input_error(*file, line, cut.error == cut.INVALID_LOCATION
                                     ? "the segment does not lie in a single face (its two points share no face)"
                                     : cut.message);
  }
  result.chain.assign(result.mesh.number_of_edges(), 0);
  for(auto e : result.mesh.edges()) result.chain[std::size_t(e)] = chain[e];
  result.mesh.remove_property_map(chain);
  result.face_origin.assign(result.mesh.number_of_faces(), 0);
  for(auto f : result.mesh.faces()) result.face_origin[std::size_t(f)] = std::size_t(origin[f]);
  result.mesh.remove_property_map(origin);
  internal::refuse_curves_along_the_border(result.mesh, result.chain, nv, cut.curve_vertices, where);
  result.point_vertex.assign(base, std::size_t(-1));
  for(std::size_t k = 0; k < segments.size(); ++k)
    for(int end = 0; end < 2; ++end)
      if(cut.curve_vertices[k][end] != Mesh::null_vertex())
        result.point_vertex[ends[k][end]] = std::size_t(cut.curve_vertices[k][end]);
  result.cut = cut.cut_vertices > 0;
  result.cut_new_vertices = cut.cut_vertices;
  result.cut_new_faces = cut.cut_faces;
  result.vertices_after_cut = nv + cut.cut_vertices;
  result.faces_after_cut = nf + cut.cut_faces;
  result.refine_new_vertices = cut.refinement_vertices;
  result.refine_new_faces = cut.refinement_faces;
  result.refined_pieces = cut.refined_pieces;
  result.skipped_segments = skipped + cut.skipped_segments;
  result.used_segments = cut.segments;
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

#endif // CGAL_SWN_TOOL_IO_CONFORMING_CUT_H
