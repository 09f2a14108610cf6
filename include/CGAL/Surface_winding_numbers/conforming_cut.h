// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_CONFORMING_CUT_H
#define CGAL_SURFACE_WINDING_NUMBERS_CONFORMING_CUT_H

#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/internal/cut_curves.h>
#include <CGAL/Surface_winding_numbers/internal/refine_short_pieces.h>
#include <CGAL/Surface_winding_numbers/parameters.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersRef
what `conforming_cut()` did, or why it refused to do anything.
\tparam TriangleMesh the mesh type passed to `conforming_cut()`
*/
template <class TriangleMesh>
struct Conforming_cut_result
{
  /// the vertex descriptor of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  /// why the cut was refused
  enum Error
  {
    NO_ERROR,          ///< the cut was done
    INVALID_LOCATION,  ///< a point has no face, coordinates that are negative or not finite, or lies strictly inside its face
    NO_COMMON_FACE,    ///< the two points of a segment lie on no common face
    CROSSING_SEGMENTS, ///< \deprecated not returned since segments that cross inside a face get a vertex where they cross
    INVALID_PARAMETER  ///< `minimum_piece_edges` is above `max_minimum_piece_edges` (with the refinement on)
  };

  /// the largest `minimum_piece_edges` accepted: a short piece is refined into at most this many edges
  static constexpr std::size_t max_minimum_piece_edges = std::size_t(1) << 16;

  /// `NO_ERROR`, or why the cut was refused (the mesh and the chain are then unchanged)
  Error error = NO_ERROR;
  /// the reason of the refusal in words (empty on success)
  std::string message;
  /// on `INVALID_LOCATION`: the curve and the point at fault; on the other errors: the curve and the
  /// segment at fault (segment `k` joins points `k` and `k+1` of the curve)
  std::size_t curve = 0;
  /// see `curve`
  std::size_t index = 0;
  /// \deprecated always 0: was the other curve of `CROSSING_SEGMENTS`, which is not returned
  std::size_t other_curve = 0;
  /// \deprecated always 0: was the other segment of `CROSSING_SEGMENTS`, which is not returned
  std::size_t other_index = 0;

  /// for each curve and each of its points, the vertex of the cut mesh at that point; the null vertex for a
  /// point that is on no segment (a curve of one point, or repeated points only)
  std::vector<std::vector<vertex_descriptor> > curve_vertices;
  /// number of segments added to the chain
  std::size_t segments = 0;
  /// number of segments skipped because their two points coincide
  std::size_t skipped_segments = 0;
  /// vertices added on edges by the cut
  std::size_t cut_vertices = 0;
  /// faces added by the cut
  std::size_t cut_faces = 0;
  /// vertices added by the cut inside faces, where segments cross (included in `cut_vertices`)
  std::size_t crossing_vertices = 0;
  /// chain pieces refined
  std::size_t refined_pieces = 0;
  /// vertices added by the refinement of short pieces
  std::size_t refinement_vertices = 0;
  /// faces added by the refinement of short pieces
  std::size_t refinement_faces = 0;

  /// `true` if the cut was done
  explicit operator bool() const { return error == NO_ERROR; }
};

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief cuts `tm` so that curves given as sequences of points on its surface run along edges, adds them to
`chain`, and refines the short pieces of the chain that end inside the mesh.

Each curve is a sequence of points on the mesh, each point a vertex or a point on an edge, given as a face
location: a face `f` and three barycentric coordinates with respect to `source(halfedge(f, tm), tm)`,
`target(halfedge(f, tm), tm)` and `target(next(halfedge(f, tm), tm), tm)` (the type
`CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT>` of `CGAL/Polygon_mesh_processing/locate.h`).
Consecutive points are joined by a straight segment inside a face or along an edge. The cut:

- inserts a vertex (`CGAL::Euler::split_edge()`) at every point on an edge, at the combination of the edge's
  ends with the point's coordinates; no vertex moves. Coordinates below \f$ 10^{-9} \f$ times their sum are
  0 (the point is on an edge, or a vertex, up to rounding), and points of one edge closer than
  \f$ 10^{-9} \f$ times its length become one vertex, as do points equal as locations;
- where two segments cross inside a face, inserts a vertex at the crossing (crossings closer than
  \f$ 10^{-9} \f$ times a segment's length along it are one vertex, through which all the segments go);
- splits every face crossed by segments along them and triangulates the rest of every face that received a
  vertex on its sides (`CGAL::Euler::split_face()`), never making a triangle out of three collinear vertices
  (ears are clipped at the corners of each piece, the ear with the largest smallest angle first);
- adds every segment to the chain: +1 along it, on each edge it runs along; a segment whose two points
  coincide is skipped;
- if `refine_short_pieces` is `true`, refines the chain pieces (maximal paths of chain edges through vertices
  where exactly two chain edges meet and the chain has no boundary) that have fewer than
  `minimum_piece_edges` edges and end at an interior endpoint (a vertex where the chain has a boundary and
  that is not on the border of the mesh): each of their `n` edges is split at its midpoint into \f$ 2^k \f$
  edges, \f$ k = \max(1, \lfloor \log_2 \lfloor N / n \rfloor \rfloor) \f$ with \f$ N \f$ =
  `minimum_piece_edges`, the new vertices joined to the opposite vertices of the incident faces. The method
  takes interior endpoints out of its jump-Laplace system, so a piece of one edge between two of them would
  vanish (user manual, \ref SWNDefChains and \ref SWNAPIIO).

Split edges keep their chain value (both halves), so `chain` may already hold curves. Faces that keep
their descriptor: every face not cut, and one piece of each cut face `f`, the triangle with the vertex
`v = target(halfedge(f, tm), tm)` of the input (and `target(halfedge(f, tm), tm)` is still `v`); other pieces and the vertices are added with
`add_face()` and `add_vertex()`, so with `CGAL::Surface_mesh` (without removed elements) the indices of the
input are kept and the new ones follow: the vertices of the cut on edges in the order of their first use by
the curves, then the faces of the cut and the crossings face by face in the order of `faces(tm)`, then those
of the refinement.

Nothing is changed when the curves are refused: a point strictly inside a face, or two consecutive points
on no common face (the result tells which), or when `minimum_piece_edges` is above
`Conforming_cut_result::max_minimum_piece_edges` with the refinement on.

\tparam TriangleMesh a model of `MutableFaceGraph`, `FaceListGraph`, `EdgeListGraph` and `VertexListGraph` whose
        faces are triangles
\tparam CurveRange a range of ranges of `std::pair<boost::graph_traits<TriangleMesh>::%face_descriptor, std::array<FT, 3> >`,
        `FT` a number type convertible to the field type of the kernel
\tparam ChainMap a model of `ReadWritePropertyMap` with key `boost::graph_traits<TriangleMesh>::%edge_descriptor`
        and an integer value type, signed along `halfedge(e, tm)` for `e` as met in `edges(tm)` (as for
        `CGAL::surface_winding_numbers()`)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh, cut in place
\param curves the curves, as sequences of face locations
\param chain read on the edges of `tm` before the cut, written on every edge after it
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`; the new vertices get their points through it}
    \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::refine_short_pieces}
    \cgalParamDescription{whether short chain pieces ending at an interior endpoint are refined}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::minimum_piece_edges}
    \cgalParamDescription{pieces with fewer edges than this are refined; a value above
      `Conforming_cut_result::max_minimum_piece_edges` (65536) is refused (`INVALID_PARAMETER`) when the refinement is on}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{8}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::face_origin_map}
    \cgalParamDescription{an output: written for every face of `tm` after the cut (and the refinement) with the
      face of the input it is a piece of; a face that was not cut gets itself. The pieces of an input face
      tile it: their areas add up to its area. Not written when the curves are refused.}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
      as key and value type, valid for the faces the cut adds (e.g. a property map of `CGAL::Surface_mesh`)}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre `tm` is a triangle mesh, and the coordinates of every location sum to 1 (negative ones are refused).
\returns what was done: the vertex of every curve point and the sizes of the cut and of the refinement,
or why the curves were refused; converts to `true` if the cut was done.
*/
template <class TriangleMesh, class CurveRange, class ChainMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Conforming_cut_result<TriangleMesh>
conforming_cut(TriangleMesh& tm, const CurveRange& curves, ChainMap chain,
               const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::face_descriptor face_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::FT FT;
  typedef typename boost::property_traits<ChainMap>::value_type Chain_value;
  typedef Conforming_cut_result<TriangleMesh> Result;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace snp = Surface_winding_numbers::internal_np;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, tm));
  const bool refine = choose_parameter(get_parameter(np, snp::refine_short_pieces), true);
  const std::size_t min_edges = choose_parameter(get_parameter(np, snp::minimum_piece_edges), std::size_t(8));

  Result result;
  auto refuse = [&](typename Result::Error error, std::size_t curve, std::size_t index, const std::string& message) {
    result.error = error;
    result.curve = curve;
    result.index = index;
    result.message = message;
    result.curve_vertices.clear();
    return result;
  };
  if(refine && min_edges > Result::max_minimum_piece_edges)
    return refuse(Result::INVALID_PARAMETER, 0, 0,
                  "minimum_piece_edges is " + std::to_string(min_edges) + ", above the largest accepted value " +
                  std::to_string(Result::max_minimum_piece_edges));

  // ---- the curves' points and segments, and the faces they cut (nothing is changed so far)
  std::vector<internal::Cut_point<TriangleMesh, FT> > points;
  std::vector<internal::Cut_edge<TriangleMesh> > cut_edges;
  std::vector<std::vector<std::size_t> > curve_points;
  std::vector<internal::Cut_segment> segments;
  std::vector<internal::Cut_face<TriangleMesh> > cut_faces;
  // dynamic maps start with value-initialized values (0, false)
  auto edge_of = get(CGAL::dynamic_edge_property_t<std::size_t>(), tm);   // Cut_edge + 1, 0: none
  auto face_of = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);   // Cut_face + 1, 0: none
  internal::Cut_refusal why;
  if(!internal::locate_cut_points<FT>(tm, curves, edge_of, points, cut_edges, curve_points, why))
    return refuse(Result::INVALID_LOCATION, why.curve, why.index, why.message);
  if(!internal::sort_cut_segments<FT>(tm, edge_of, face_of, points, cut_edges, curve_points, segments, cut_faces,
                                      result.skipped_segments, why))
    return refuse(Result::NO_COMMON_FACE, why.curve, why.index, why.message);
  const std::vector<std::size_t> chord_of = internal::cross_chords(tm, points, cut_edges, segments, cut_faces);
  for(const auto& cf : cut_faces) result.crossing_vertices += cf.inner.size();
  internal::add_faces_of_used_edges(tm, points, cut_edges, face_of, cut_faces);

  // ---- the cut. The chain is kept as a flow on the halfedges.
  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  auto flow = get(CGAL::dynamic_halfedge_property_t<Chain_value>(), tm);
  auto origin = get(CGAL::dynamic_face_property_t<face_descriptor>(), tm);   // the input face of every piece
  for(face_descriptor f : faces(tm)) put(origin, f, f);
  for(auto e : edges(tm))
    if(get(chain, e) != Chain_value(0)) put(flow, halfedge(e, tm), get(chain, e));
  internal::insert_edge_points(tm, vpm, points, cut_edges, flow);
  internal::cut_every_face(tm, vpm, face_of, cut_faces, points, segments, origin);
  internal::add_segments_to_flow(tm, points, cut_edges, segments, cut_faces, chord_of, flow);
  result.segments = segments.size();
  result.cut_vertices = num_vertices(tm) - nv;
  result.cut_faces = num_faces(tm) - nf;

  if(refine && min_edges > 1)
  {
    const std::size_t nv_cut = num_vertices(tm), nf_cut = num_faces(tm);
    result.refined_pieces = internal::refine_short_pieces(tm, vpm, flow, origin, min_edges);
    result.refinement_vertices = num_vertices(tm) - nv_cut;
    result.refinement_faces = num_faces(tm) - nf_cut;
  }
  for(auto e : edges(tm))
    put(chain, e, get(flow, halfedge(e, tm)) - get(flow, opposite(halfedge(e, tm), tm)));
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, snp::face_origin_map_t>::value)
  {
    auto face_origin = get_parameter(np, snp::face_origin_map);
    for(face_descriptor f : faces(tm)) put(face_origin, f, get(origin, f));
  }
  for(const auto& cp : curve_points)
  {
    result.curve_vertices.emplace_back();
    for(std::size_t p : cp)
      result.curve_vertices.back().push_back(points[p].used ? points[p].vertex : Traits::null_vertex());
  }
  return result;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_CONFORMING_CUT_H
