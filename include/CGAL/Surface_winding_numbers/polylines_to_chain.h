// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_POLYLINES_TO_CHAIN_H
#define CGAL_SURFACE_WINDING_NUMBERS_POLYLINES_TO_CHAIN_H

#include <CGAL/Surface_winding_numbers/conforming_cut.h>
#include <CGAL/Surface_winding_numbers/internal/surface_walk.h>
#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>
#include <CGAL/Surface_winding_numbers/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersRef
what `polylines_to_chain()` did with the polylines, or why it refused them.
\tparam TriangleMesh the mesh type passed to `polylines_to_chain()`
*/
template <class TriangleMesh>
struct Polylines_to_chain_result
{
  /// empty on success; otherwise why the polylines were refused (the mesh and the chain are then unchanged)
  std::string error;
  /// what was skipped: empty polylines, polylines without any point near the surface (each names its polyline)
  std::vector<std::string> warnings;
  /// points of all polylines
  std::size_t points = 0;
  /// points farther than the tolerance from the surface (each one makes a gap)
  std::size_t points_off_surface = 0;
  /// segments between two points near the surface that the walk could not follow (border reached, or the
  /// plane section turning away): each one makes a gap
  std::size_t failed_walks = 0;
  /// pieces of curve along border edges of the mesh (maximal runs of consecutive edges), dropped: a chain
  /// may not lie on a border edge, which has no face on its other side for the winding number to jump to
  std::size_t border_pieces = 0;
  /// for each polyline, its pieces along the border (they add up to `border_pieces`)
  std::vector<std::size_t> polyline_border_pieces;
  /// \deprecated always 0: pieces of curve that cross get a vertex of the cut where they cross
  /// (`Conforming_cut_result::crossing_vertices`)
  std::size_t dropped_crossings = 0;
  /// curves (maximal unbroken pieces) put on the mesh
  std::size_t curves = 0;
  /// for each polyline, the pieces it was cut into, each a sequence of indices of its points; a closed
  /// polyline without gap is one piece whose last index equals its first
  std::vector<std::vector<std::vector<std::size_t> > > pieces;
  /// what `conforming_cut()` did with the curves through edge points
  Conforming_cut_result<TriangleMesh> cut;

  /// `true` if the polylines were put on the mesh
  explicit operator bool() const { return error.empty(); }
};

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief puts 3D polylines onto the surface of `tm`, cutting it so that they run along edges, and adds them
to `chain`.

Every point is projected to the closest point of the surface (`CGAL::Polygon_mesh_processing::locate_with_AABB_tree()`).
Points farther from the surface than `projection_tolerance` are dropped, and the polyline is broken there.
Two consecutive projected points `a` and `b` are joined by a straight walk through faces: the curve on
the surface is the intersection of the surface with the plane through `a` and `b` that contains the mean
of the two faces' normals, followed from face to face until the face of `b`. The walk is local, linear in
the number of faces crossed, and stays under what the user drew; a geodesic shortest path
(`CGAL::Surface_mesh_shortest_path`) would cost a sequence tree per point and cut the corners of what the
user drew. A walk that meets the border of the mesh or goes astray makes a gap. The surface winding
numbers close the gaps, so a broken curve is an ordinary input.

The curve made of the points where walks cross edges is put on the mesh by `conforming_cut()`; polyline
points strictly inside a face are not vertices of the curve (inside a face the curve is the straight
chord between the two points where it crosses the face's border, within one face of the polyline).
Crossings closer than 2 % of an edge's length to one of its ends are moved to that vertex, so that the
cut makes no sliver triangle. Points that lie on an edge or a vertex up to rounding (barycentric
coordinates below \f$ 10^{-9} \f$) are on it, and vertices within \f$ 10^{-9} \f$ mean edge lengths of a
walk's plane are on the walk: a polyline that runs along edges, or through vertices, follows them, and a
closed one stays closed. A polyline whose last point equals its first is closed. Where two pieces of curve
cross inside a face (self-intersecting strokes), the cut puts a vertex at the crossing (one cut for all
the curves). The open ends of a polyline end at its first and last edge crossing.

The pieces of curve that run along border edges of the mesh are dropped, since a chain may not lie on a
border edge; they are counted in `Polylines_to_chain_result::border_pieces` and, per polyline, in
`Polylines_to_chain_result::polyline_border_pieces`. What is left of the curve ends on the border there,
and the labels are those of the curve without the pieces along the border. A polyline drawn only along
the border puts no curve on the mesh (no error: `Polylines_to_chain_result::curves` does not count it).

The geometric queries (closest points, walks) run on the mesh's coordinates multiplied by a power of two
that brings its bounding box to unit size, so that a mesh and its copies scaled by any power of ten from
1e-150 to 1e150 get the same curve, up to the scale.

\tparam TriangleMesh a model of `MutableFaceGraph`, `FaceListGraph`, `EdgeListGraph` and `VertexListGraph` whose
        faces are triangles
\tparam PolylineRange a range of ranges of points (type `%Point_3` of the kernel)
\tparam ChainMap a model of `ReadWritePropertyMap` with key `boost::graph_traits<TriangleMesh>::%edge_descriptor`
        and an integer value type, signed along `halfedge(e, tm)` (as for `CGAL::surface_winding_numbers()`)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh, cut in place
\param polylines the polylines, each an ordered sequence of points
\param chain read on the edges of `tm` before the cut, written on every edge after it
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{Surface_winding_numbers::parameters::projection_tolerance}
    \cgalParamDescription{points farther than this from the surface make gaps}
    \cgalParamType{`double`}
    \cgalParamDefault{the mean edge length of `tm`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::refine_short_pieces}
    \cgalParamDescription{passed to `conforming_cut()`}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::minimum_piece_edges}
    \cgalParamDescription{passed to `conforming_cut()`}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{8}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::face_origin_map}
    \cgalParamDescription{an output, passed to `conforming_cut()`: for every face after the cut, the face of the input it is a piece of}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and value type}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done, with warnings for the polylines that gave nothing (empty, or with no point near
the surface); converts to `false` and changes nothing if a point has a coordinate that is not finite
(the error names the polyline and the point), or a vertex of the mesh, or if `conforming_cut()` refuses
the curves (`minimum_piece_edges` above `Conforming_cut_result::max_minimum_piece_edges`).
*/
template <class TriangleMesh, class PolylineRange, class ChainMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Polylines_to_chain_result<TriangleMesh>
polylines_to_chain(TriangleMesh& tm, const PolylineRange& polylines, ChainMap chain,
                   const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::face_descriptor face_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::FT FT;
  typedef typename GT::Point_3 Point;
  typedef typename GT::Vector_3 Vector_3;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef internal::Scaled_point_map<VPM, Point> SPM;   // the queries run at unit scale
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, SPM> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Primitive> > Tree;
  typedef internal::Surface_walk<TriangleMesh, SPM, GT> Walk;
  typedef typename Walk::Spot Spot;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT> Location;
  namespace PMP = CGAL::Polygon_mesh_processing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  Polylines_to_chain_result<TriangleMesh> result;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));

  // bad input first: nothing is changed
  std::size_t c = 0;
  for(const auto& polyline : polylines)
  {
    std::size_t j = 0;
    for(const auto& p : polyline)
    {
      if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) || !std::isfinite(CGAL::to_double(p.z())))
      {
        result.error = "polyline " + std::to_string(c) + ", point " + std::to_string(j) + ": a coordinate is not finite";
        return result;
      }
      ++j;
    }
    ++c;
  }
  if(faces(tm).empty())
  {
    result.error = "the mesh has no face";
    return result;
  }
  bool finite = true;
  const double unit = internal::mesh_unit_scale(tm, vpm, finite);
  if(!finite)
  {
    result.error = "a vertex of the mesh has a coordinate that is not finite";
    return result;
  }
  const SPM spm{vpm, unit};
  const double mean_edge = internal::mean_edge_length(tm, spm);   // at unit scale
  const double tolerance = choose_parameter(get_parameter(np, internal_np::projection_tolerance), mean_edge / unit);
  // a point farther from the mesh's box than the tolerance (or than 1e100 at unit scale) is far from the
  // surface: it is not queried, so that squared distances cannot overflow
  const CGAL::Bbox_3 box = PMP::bbox(tm, CGAL::parameters::vertex_point_map(spm));
  const double margin = (std::min)(tolerance * unit, 1e100);

  Tree tree;
  PMP::build_AABB_tree(tm, tree, CGAL::parameters::vertex_point_map(spm));
  const Walk walker(tm, spm, mean_edge);

  // ---- the spots of every curve, polyline by polyline
  std::vector<std::vector<Spot> > curves;
  std::vector<std::size_t> curve_polyline;   // the polyline of every curve
  c = 0;
  for(const auto& polyline : polylines)
  {
    std::vector<Point> pts(std::begin(polyline), std::end(polyline));
    for(Point& p : pts)   // at unit scale; points that overflow are far from the surface
      p = Point(unit * CGAL::to_double(p.x()), unit * CGAL::to_double(p.y()), unit * CGAL::to_double(p.z()));
    result.pieces.emplace_back();
    result.points += pts.size();
    const bool closed = pts.size() > 2 && pts.front() == pts.back();
    if(closed) pts.pop_back();
    const std::size_t n = pts.size();
    if(n == 0) { result.warnings.push_back("polyline " + std::to_string(c) + " is empty"); ++c; continue; }
    std::vector<Location> loc(n);
    std::vector<bool> near(n);
    std::size_t near_points = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const Vector_3 p = pts[i] - CGAL::ORIGIN;
      near[i] = std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) && std::isfinite(CGAL::to_double(p.z()));
      for(int k = 0; k < 3 && near[i]; ++k)
        near[i] = CGAL::to_double(p[k]) >= box.min(k) - margin && CGAL::to_double(p[k]) <= box.max(k) + margin;
      if(!near[i]) continue;
      loc[i] = PMP::locate_with_AABB_tree(pts[i], tree, tm, CGAL::parameters::vertex_point_map(spm));
      const Point q = PMP::construct_point(loc[i], tm, CGAL::parameters::vertex_point_map(spm));
      near[i] = internal::length(q - pts[i]) <= tolerance * unit;
      near_points += near[i];
    }
    result.points_off_surface += (n - near_points) + (closed && !near[0]);
    if(near_points == 0)
    {
      result.warnings.push_back("polyline " + std::to_string(c) + ": no point within " + std::to_string(tolerance) +
                                " of the surface (all " + std::to_string(pts.size() + closed) + " points make a gap)");
      ++c;
      continue;
    }
    // the pieces: walks between consecutive points near the surface
    std::vector<std::vector<Spot> > pieces(1);
    std::vector<std::vector<std::size_t> > indices(1);
    bool broken = false, wrap_broken = false;
    const std::size_t pairs = closed ? n : n - 1;
    auto end_piece = [&]() {
      broken = true;
      if(!indices.back().empty()) { pieces.emplace_back(); indices.emplace_back(); }
    };
    for(std::size_t i = 0; i < pairs; ++i)
    {
      const std::size_t k = (i + 1) % n;
      if(!near[i]) { end_piece(); if(k == 0) wrap_broken = true; continue; }
      const Spot from = walker.spot(loc[i]);
      if(from.kind != Spot::FACE) pieces.back().push_back(from);
      indices.back().push_back(i);
      if(!near[k]) { end_piece(); if(k == 0) wrap_broken = true; continue; }
      std::vector<Spot> crossed;
      const auto normal = walker.face_normal(loc[i].first) + walker.face_normal(loc[k].first);
      const Point b = PMP::construct_point(loc[k], tm, CGAL::parameters::vertex_point_map(spm));
      if(walker.walk(from, loc[k].first, b, normal, crossed))
        pieces.back().insert(pieces.back().end(), crossed.begin(), crossed.end());
      else
      {
        ++result.failed_walks;
        end_piece();
        if(k == 0) wrap_broken = true;
      }
    }
    if(!closed && near[n - 1])
    {
      const Spot last = walker.spot(loc[n - 1]);
      if(last.kind != Spot::FACE) pieces.back().push_back(last);
      indices.back().push_back(n - 1);
    }
    if(closed && !broken)
    {
      if(!pieces.back().empty()) pieces.back().push_back(pieces.back().front());
      indices.back().push_back(0);
    }
    else if(closed && !wrap_broken && pieces.size() > 1)   // the last piece runs on into the first
    {
      pieces.back().insert(pieces.back().end(), pieces.front().begin(), pieces.front().end());
      indices.back().insert(indices.back().end(), indices.front().begin(), indices.front().end());
      pieces.erase(pieces.begin());
      indices.erase(indices.begin());
    }
    for(std::size_t p = 0; p < pieces.size(); ++p)
    {
      if(indices[p].empty()) continue;
      result.pieces.back().push_back(indices[p]);
      curves.push_back(std::move(pieces[p]));
      curve_polyline.push_back(c);
    }
    ++c;
  }

  // ---- crossings near a vertex moved to it, repeated spots merged, no piece along a border edge
  std::vector<std::vector<Location> > locations;
  auto same = [&](const Spot& s, const Spot& r) {
    if(s.kind != r.kind) return false;
    if(s.kind == Spot::VERTEX) return s.v == r.v;
    if(s.h == r.h) return std::abs(s.t - r.t) < 1e-9;
    return s.h == opposite(r.h, tm) && std::abs(s.t - (1 - r.t)) < 1e-9;
  };
  // the border edge both spots are on, if any
  auto along_border = [&](const Spot& s, const Spot& r) {
    auto on = [&](const Spot& x, typename Traits::halfedge_descriptor h) {
      return x.kind == Spot::VERTEX ? (x.v == source(h, tm) || x.v == target(h, tm)) : edge(x.h, tm) == edge(h, tm);
    };
    const Spot& e = s.kind == Spot::EDGE ? s : r;
    if(e.kind == Spot::EDGE) return is_border_edge(e.h, tm) && on(s, e.h) && on(r, e.h);
    const auto h = halfedge(s.v, r.v, tm);
    return h.second && is_border_edge(h.first, tm);
  };
  // a point inside an edge between two points of that edge: the curve runs along the edge, and the point
  // would only split it
  auto redundant = [&](const Spot& before, const Spot& s, const Spot& after) {
    if(s.kind != Spot::EDGE) return false;
    auto on = [&](const Spot& x) {
      return x.kind == Spot::VERTEX ? (x.v == source(s.h, tm) || x.v == target(s.h, tm))
                                    : x.kind == Spot::EDGE && edge(x.h, tm) == edge(s.h, tm);
    };
    return on(before) && on(after);
  };
  auto to_location = [&](const Spot& s) {
    // a face around the spot and the spot's coordinates in it
    typename Traits::halfedge_descriptor h = s.h;
    double t = s.t;
    if(s.kind == Spot::VERTEX)
    {
      t = 1;
      for(auto g : halfedges_around_target(halfedge(s.v, tm), tm))
        if(!is_border(g, tm)) { h = g; break; }
    }
    else if(is_border(h, tm)) { h = opposite(h, tm); t = 1 - t; }
    const face_descriptor f = face(h, tm);
    const auto h0 = halfedge(f, tm);
    const int k = h == h0 ? 0 : (h == next(h0, tm) ? 1 : 2);   // source(h) is vertex k of f
    std::array<FT, 3> w = {FT(0), FT(0), FT(0)};
    if(s.kind == Spot::VERTEX) w[(k + 1) % 3] = FT(1);
    else { w[k] = FT(1 - t); w[(k + 1) % 3] = FT(t); }
    return Location(f, w);
  };
  result.polyline_border_pieces.assign(result.pieces.size(), 0);
  for(std::size_t i = 0; i < curves.size(); ++i)
  {
    const std::vector<Spot>& curve = curves[i];
    std::vector<std::vector<Spot> > parts(1);
    std::size_t border_pieces = 0;
    bool on_border = false, first_on_border = false, segments = false;   // the last and the first segment
    for(Spot s : curve)
    {
      if(s.kind == Spot::EDGE && (s.t < 0.02 || s.t > 0.98))
      {
        s.v = s.t < 0.5 ? source(s.h, tm) : target(s.h, tm);
        s.kind = Spot::VERTEX;
        s.p = get(spm, s.v);
      }
      if(!parts.back().empty() && same(parts.back().back(), s)) continue;
      if(!parts.back().empty())
      {
        const bool border = along_border(parts.back().back(), s);
        if(border) parts.emplace_back();
        border_pieces += border && !on_border;
        if(!segments) first_on_border = border;
        on_border = border;
        segments = true;
      }
      parts.back().push_back(s);
      if(parts.back().size() > 2 && redundant(parts.back()[parts.back().size() - 3], parts.back()[parts.back().size() - 2], s))
        parts.back().erase(parts.back().end() - 2);
    }
    // a closed curve whose first and last segments are along the border: one piece along the border
    if(border_pieces > 1 && first_on_border && on_border && same(curve.front(), curve.back())) --border_pieces;
    result.border_pieces += border_pieces;
    result.polyline_border_pieces[curve_polyline[i]] += border_pieces;
    auto& loop = parts.front();   // a closed curve: its first point too
    if(parts.size() == 1 && loop.size() > 3 && same(loop.front(), loop.back()) && redundant(loop[loop.size() - 2], loop[0], loop[1]))
    {
      loop.erase(loop.begin());
      loop.back() = loop.front();
    }
    for(const auto& part : parts)
    {
      if(part.size() < 2) continue;
      locations.emplace_back();
      for(const Spot& s : part) locations.back().push_back(to_location(s));
    }
  }

  // ---- one cut for all curves; where pieces cross inside a face, the cut puts a vertex
  result.cut = conforming_cut(tm, locations, chain, np);
  result.curves = locations.size();
  if(!result.cut) result.error = result.cut.message;
  return result;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_POLYLINES_TO_CHAIN_H
