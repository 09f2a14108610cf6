// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_CONFORMING_CUT_H
#define CGAL_SURFACE_WINDING_NUMBERS_CONFORMING_CUT_H

#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/internal/cut_faces.h>
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
    CROSSING_SEGMENTS, ///< not returned: segments that cross inside a face get a vertex where they cross
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
  /// not used (see `CROSSING_SEGMENTS`)
  std::size_t other_curve = 0;
  /// see `other_curve`
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

/// \cond SKIP_IN_MANUAL
namespace internal {

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

struct Cut_segment
{
  std::size_t a, b, curve, index;
  std::size_t edge;   // along an edge with points on it: its Cut_edge; none along another edge, or inside a face
  std::size_t face;   // inside a face: its Cut_face; none along an edge
};

} // namespace internal
/// \endcond

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
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::FT FT;
  typedef typename boost::property_traits<ChainMap>::value_type Chain_value;
  typedef typename boost::property_traits<
    typename GetVertexPointMap<TriangleMesh, NamedParameters>::type>::value_type Point;
  typedef Conforming_cut_result<TriangleMesh> Result;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace snp = Surface_winding_numbers::internal_np;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, tm));
  const bool refine = choose_parameter(get_parameter(np, snp::refine_short_pieces), true);
  const std::size_t min_edges = choose_parameter(get_parameter(np, snp::minimum_piece_edges), std::size_t(8));
  const std::size_t none = std::size_t(-1);
  const FT snap(internal::cut_snap_tolerance);   // relative to the face or the edge

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

  // ---- the points, deduplicated: vertices by a vertex map, edge points per edge of the input
  std::vector<internal::Cut_point<TriangleMesh, FT> > points;
  std::vector<internal::Cut_edge<TriangleMesh> > cut_edges;
  std::vector<std::vector<std::size_t> > curve_points;
  const auto reference = internal::reference_halfedge_marks(tm);
  // dynamic maps start with value-initialized values (0, false)
  auto edge_of = get(CGAL::dynamic_edge_property_t<std::size_t>(), tm);   // Cut_edge + 1, 0: none
  {
    auto vertex_point = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);   // point + 1, 0: none
    std::size_t c = 0;
    for(const auto& curve : curves)
    {
      curve_points.emplace_back();
      std::size_t j = 0;
      for(const auto& location : curve)
      {
        const face_descriptor f = location.first;
        std::array<FT, 3> w;
        int zeros = 0;
        bool valid = f != Traits::null_face();
        FT sum(0);
        for(int k = 0; k < 3; ++k)
        {
          w[k] = FT(location.second[k]);
          valid = valid && CGAL::is_finite(w[k]) && !(w[k] < -snap);
          sum += w[k];
        }
        valid = valid && sum > FT(0);
        // coordinates within the snapping tolerance of 0 are 0: the point is on the border up to rounding
        for(int k = 0; valid && k < 3; ++k)
          if(!(w[k] > snap * sum)) { w[k] = FT(0); ++zeros; }
        if(valid && zeros < 3)
        {
          sum = w[0] + w[1] + w[2];
          for(int k = 0; k < 3; ++k) w[k] = w[k] / sum;
        }
        if(!valid || zeros == 0 || zeros == 3)
          return refuse(Result::INVALID_LOCATION, c, j,
                        !valid ? "a point has no face, or negative or non-finite coordinates"
                               : "a point lies strictly inside a face (only vertices and points on edges are supported)");
        // vertex k of the face is source(h[k]); coordinate k belongs to it
        const halfedge_descriptor h0 = halfedge(f, tm);
        const std::array<halfedge_descriptor, 3> h = {h0, next(h0, tm), next(next(h0, tm), tm)};
        std::size_t id = points.size();
        if(zeros == 2)
        {
          int k = 0;
          while(w[k] == FT(0)) ++k;
          const vertex_descriptor v = source(h[k], tm);
          if(get(vertex_point, v) != 0) id = get(vertex_point, v) - 1;
          else
          {
            put(vertex_point, v, id + 1);
            points.emplace_back();
            points.back().vertex = v;
          }
        }
        else
        {
          int k = 0;
          while(w[k] != FT(0)) ++k;
          halfedge_descriptor e = h[(k + 1) % 3];   // the side opposite to vertex k
          FT at_source = w[(k + 1) % 3], at_target = w[(k + 2) % 3];
          if(!get(reference, e)) { e = opposite(e, tm); std::swap(at_source, at_target); }
          if(get(edge_of, edge(e, tm)) == 0)
          {
            cut_edges.push_back({e, source(e, tm), target(e, tm), {}});
            put(edge_of, edge(e, tm), cut_edges.size());
          }
          auto& ce = cut_edges[get(edge_of, edge(e, tm)) - 1];
          for(std::size_t p : ce.points)   // one point for points on an edge closer than the tolerance
            if(CGAL::abs(points[p].at_target - at_target) <= snap) id = p;
          if(id == points.size())
          {
            points.emplace_back();
            points.back().edge = get(edge_of, edge(e, tm)) - 1;
            points.back().at_source = at_source;
            points.back().at_target = at_target;
            ce.points.push_back(id);
          }
        }
        curve_points.back().push_back(id);
        ++j;
      }
      ++c;
    }
    for(auto& ce : cut_edges)
      std::sort(ce.points.begin(), ce.points.end(), [&](std::size_t p, std::size_t q) {
        return points[p].at_target < points[q].at_target ||
               (points[p].at_target == points[q].at_target && points[q].at_source < points[p].at_source);
      });
  }

  // ---- the segments: along an edge, or inside a face (chords)
  std::vector<internal::Cut_segment> segments;
  std::vector<internal::Cut_face<TriangleMesh> > cut_faces;
  auto face_of = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);   // Cut_face + 1, 0: none
  auto cut_face = [&](face_descriptor f) {
    if(get(face_of, f) == 0)
    {
      const halfedge_descriptor h0 = halfedge(f, tm);
      internal::Cut_face<TriangleMesh> cf;
      cf.f = f;
      cf.side = {h0, next(h0, tm), next(next(h0, tm), tm)};
      for(int k = 0; k < 3; ++k) cf.corner[k] = source(cf.side[k], tm);
      cut_faces.push_back(cf);
      put(face_of, f, cut_faces.size());
    }
    return get(face_of, f) - 1;
  };
  auto faces_of_edge = [&](const internal::Cut_edge<TriangleMesh>& ce) {
    std::vector<face_descriptor> r;
    for(halfedge_descriptor g : {ce.h, opposite(ce.h, tm)})
      if(!is_border(g, tm)) r.push_back(face(g, tm));
    return r;
  };
  for(std::size_t c = 0; c < curve_points.size(); ++c)
    for(std::size_t j = 0; j + 1 < curve_points[c].size(); ++j)
    {
      const std::size_t a = curve_points[c][j], b = curve_points[c][j + 1];
      if(a == b) { ++result.skipped_segments; continue; }
      internal::Cut_segment s{a, b, c, j, none, none};
      const auto &pa = points[a], &pb = points[b];
      bool found = false;
      if(pa.edge == none && pb.edge == none)   // two vertices: along their edge
      {
        const auto h = halfedge(pa.vertex, pb.vertex, tm);
        found = h.second;
        if(found && get(edge_of, edge(h.first, tm)) != 0) s.edge = get(edge_of, edge(h.first, tm)) - 1;
      }
      else if(pa.edge == pb.edge)   // two points on one edge
      {
        s.edge = pa.edge;
        found = true;
      }
      else if(pa.edge != none && pb.edge != none)   // points on two edges: inside their common face
      {
        for(face_descriptor f : faces_of_edge(cut_edges[pa.edge]))
          for(face_descriptor g : faces_of_edge(cut_edges[pb.edge]))
            if(f == g && !found) { s.face = cut_face(f); found = true; }
      }
      else   // a vertex and a point on an edge: along the edge if the vertex ends it, else inside a face
      {
        const std::size_t e = pa.edge != none ? pa.edge : pb.edge;
        const vertex_descriptor v = pa.edge != none ? pb.vertex : pa.vertex;
        const auto& ce = cut_edges[e];
        if(v == ce.source || v == ce.target) { s.edge = e; found = true; }
        else
          for(halfedge_descriptor g : {ce.h, opposite(ce.h, tm)})
            if(!is_border(g, tm) && target(next(g, tm), tm) == v && !found) { s.face = cut_face(face(g, tm)); found = true; }
      }
      if(!found)
        return refuse(Result::NO_COMMON_FACE, c, j, "the segment does not lie in a single face (its two points share no face)");
      points[a].used = points[b].used = true;
      segments.push_back(s);
    }

  // ---- chords of every face, deduplicated; where two of them cross, a vertex inside the face
  // position of a point on the border of a cut face: (side, coordinate of the side's end)
  auto position = [&](const internal::Cut_face<TriangleMesh>& cf, std::size_t p) {
    for(int k = 0; k < 3; ++k)
    {
      if(points[p].edge == none)
      {
        if(points[p].vertex == cf.corner[k]) return std::make_pair(k, FT(0));
        continue;
      }
      const halfedge_descriptor h = cut_edges[points[p].edge].h;
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
      const internal::Cut_segment& sg = segments[cf.chords[i]];
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
    internal::chord_crossings(range, from, to, cf.crossings, cf.inner);
    result.crossing_vertices += cf.inner.size();
  }
  for(const auto& ce : cut_edges)
  {
    bool used = false;
    for(std::size_t p : ce.points) used = used || points[p].used;
    if(used)
      for(face_descriptor f : faces_of_edge(ce)) cut_face(f);
  }

  // ---- the cut (nothing was changed so far). The chain is kept as a flow on the halfedges.
  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  auto flow = get(CGAL::dynamic_halfedge_property_t<Chain_value>(), tm);
  auto origin = get(CGAL::dynamic_face_property_t<face_descriptor>(), tm);   // the input face of every piece
  for(face_descriptor f : faces(tm)) put(origin, f, f);
  for(auto e : edges(tm))
    if(get(chain, e) != Chain_value(0)) put(flow, halfedge(e, tm), get(chain, e));
  for(std::size_t p = 0; p < points.size(); ++p)
  {
    auto& point = points[p];
    if(point.edge == none || !point.used) continue;
    // the sub-edge between the nearest points already inserted on both sides
    const auto& ce = cut_edges[point.edge];
    vertex_descriptor before = ce.source, after = ce.target;
    const auto at = std::find(ce.points.begin(), ce.points.end(), p);
    for(auto q = ce.points.begin(); q != at; ++q)
      if(points[*q].vertex != Traits::null_vertex()) before = points[*q].vertex;
    for(auto q = ce.points.end(); q != at + 1;)
      if(points[*--q].vertex != Traits::null_vertex()) after = points[*q].vertex;
    const halfedge_descriptor h = halfedge(before, after, tm).first;
    const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tm);   // hnew: before -> new, h: new -> after
    point.vertex = target(hnew, tm);
    const Point &ps = get(vpm, ce.source), &pt = get(vpm, ce.target);
    put(vpm, point.vertex, Point(point.at_source * ps.x() + point.at_target * pt.x(),
                                 point.at_source * ps.y() + point.at_target * pt.y(),
                                 point.at_source * ps.z() + point.at_target * pt.z()));
    put(flow, hnew, get(flow, h));
    put(flow, opposite(hnew, tm), get(flow, opposite(h, tm)));
  }
  if(!cut_faces.empty())
  {
    auto line = get(CGAL::dynamic_halfedge_property_t<int>(), tm);
    int next_line = 3;
    std::vector<internal::Face_chord<vertex_descriptor> > chords;
    for(face_descriptor f : faces(tm))   // in the order of faces(tm), for the numbering of the new faces
    {
      if(get(face_of, f) == 0) continue;
      auto& cf = cut_faces[get(face_of, f) - 1];
      chords.clear();
      for(std::size_t i = 0; i < cf.chords.size(); ++i)
      {
        chords.push_back({points[segments[cf.chords[i]].a].vertex, points[segments[cf.chords[i]].b].vertex, {}});
        for(const auto& c : cf.crossings[i]) chords.back().inner.push_back(c.second);
      }
      // f keeps the piece with target(halfedge(f)), the first vertex of f for meshes read from files
      internal::cut_and_triangulate_face(tm, vpm, f, cf.corner, chords, cf.inner, cf.inner_vertex, cf.corner[1],
                                         line, next_line, origin);
    }
  }
  // the curves on the edges
  for(const auto& s : segments)
  {
    const vertex_descriptor va = points[s.a].vertex, vb = points[s.b].vertex;
    std::vector<vertex_descriptor> path{va, vb};
    if(s.face != none)   // its chord, through the crossings
    {
      const auto& cf = cut_faces[s.face];
      const std::size_t c = chord_of[&s - segments.data()];
      const std::size_t i = std::size_t(std::find(cf.chords.begin(), cf.chords.end(), c) - cf.chords.begin());
      path.assign(1, points[segments[c].a].vertex);
      for(const auto& x : cf.crossings[i]) path.push_back(cf.inner_vertex[x.second]);
      path.push_back(points[segments[c].b].vertex);
      if(path.front() != va) std::reverse(path.begin(), path.end());
    }
    else if(s.edge != none)
    {
      const auto& ce = cut_edges[s.edge];
      std::vector<vertex_descriptor> along{ce.source};
      for(std::size_t p : ce.points)
        if(points[p].used) along.push_back(points[p].vertex);
      along.push_back(ce.target);
      auto ia = std::find(along.begin(), along.end(), va), ib = std::find(along.begin(), along.end(), vb);
      if(ib < ia) path.assign(std::make_reverse_iterator(ia + 1), std::make_reverse_iterator(ib));
      else path.assign(ia, ib + 1);
    }
    for(std::size_t k = 0; k + 1 < path.size(); ++k)
    {
      const auto h = halfedge(path[k], path[k + 1], tm);
      CGAL_assertion(h.second);
      put(flow, h.first, get(flow, h.first) + Chain_value(1));
    }
  }
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
