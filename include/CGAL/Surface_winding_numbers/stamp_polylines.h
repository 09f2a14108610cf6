// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_STAMP_POLYLINES_H
#define CGAL_SURFACE_WINDING_NUMBERS_STAMP_POLYLINES_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/internal/surface_walk.h>
#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/// \cond SKIP_IN_MANUAL
namespace internal {

// `v` divided by its length, computed without overflow or underflow (divided by its largest coordinate
// first); throws Invalid_input, naming `what`, if `v` is null or not finite.
template <class Vector_3>
Vector_3 unit_direction(const Vector_3& v, const std::string& what)
{
  const double c[3] = {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
  const double m = (std::max)({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
  if(!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]) || !(m > 0))
    throw Invalid_input(what + " is " + (m > 0 || !(m == m) ? "not finite" : "the null vector"));
  const double u[3] = {c[0] / m, c[1] / m, c[2] / m};
  const double l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  return Vector_3(u[0] / l, u[1] / l, u[2] / l);
}

// throws Invalid_input, naming the polyline and the point (0-based), if a point of the drawing is not finite
template <class PolylineRange>
void check_drawing(const PolylineRange& drawing, const std::string& who)
{
  std::size_t c = 0;
  for(const auto& polyline : drawing)
  {
    std::size_t j = 0;
    for(const auto& p : polyline)
    {
      if(!std::isfinite(double(p[0])) || !std::isfinite(double(p[1])))
        throw Invalid_input(who + ": polyline " + std::to_string(c) + ", point " + std::to_string(j) +
                            " of the drawing has a coordinate that is not finite");
      ++j;
    }
    ++c;
  }
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceWindingNumbersRef
where a 2D drawing is placed in space to be stamped onto a mesh: the drawing's point `(x, y)` is the
origin of the ray `origin + x * x_axis + y * y_axis + t * direction`, `t >= 0`.
\tparam GT a model of `Kernel`
*/
template <class GT>
struct Stamp_frame
{
  /// the place of the drawing's point (0, 0)
  typename GT::Point_3 origin;
  /// the drawing's unit vector along its `x` axis
  typename GT::Vector_3 x_axis;
  /// the drawing's unit vector along its `y` axis
  typename GT::Vector_3 y_axis;
  /// the direction of the rays, from the drawing towards the mesh
  typename GT::Vector_3 direction;
};

/*!
\ingroup PkgSurfaceWindingNumbersRef
the frame that shows the drawing as seen by a viewer looking at `tm` along `direction`, with the
drawing's `x` to the viewer's right and its `y` downwards (as in SVG), centred on the mesh and scaled so that
it covers the fraction `fill` of the mesh's extent across the view (the larger of the two ratios decides).
The drawing lies in front of the mesh, at one bounding-box diagonal from its centre. The viewer's up
is the projection of the `z` axis, or of the `y` axis when `direction` is within 25 degrees of `z`.
\tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point map
\tparam PolylineRange a range of ranges of 2D points given as `std::array<double, 2>` (or anything with
        `p[0]`, `p[1]`)
\throws Invalid_input if `direction` is the null vector or not finite, a point of the drawing is not finite,
the drawing has no point, or the mesh has no vertex or an extent that is not finite.
*/
template <class TriangleMesh, class PolylineRange, class Vector_3>
Stamp_frame<typename CGAL::Kernel_traits<Vector_3>::Kernel>
fit_stamp_frame(const TriangleMesh& tm, const PolylineRange& drawing, const Vector_3& direction, double fill = 0.8)
{
  typedef typename CGAL::Kernel_traits<Vector_3>::Kernel GT;
  typedef typename GT::Point_3 Point_3;
  const Vector_3 d = internal::unit_direction(direction, "fit_stamp_frame(): the direction");
  internal::check_drawing(drawing, "fit_stamp_frame()");
  const Vector_3 z(0, 0, 1), y(0, 1, 0);
  const Vector_3 up = std::abs(CGAL::to_double(d * z)) > std::cos(25. / 180. * 3.141592653589793) ? y : z;
  Vector_3 right = CGAL::cross_product(d, up);
  right = right / std::sqrt(CGAL::to_double(right.squared_length()));
  const Vector_3 down = CGAL::cross_product(d, right);   // right x down = direction, as screen x, y and depth
  // the mesh's extent across the view
  const double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto v : vertices(tm))
  {
    const Vector_3 p = get(vpm, v) - CGAL::ORIGIN;
    const double c[3] = {CGAL::to_double(p * right), CGAL::to_double(p * down), CGAL::to_double(p * d)};
    for(int k = 0; k < 3; ++k) { lo[k] = (std::min)(lo[k], c[k]); hi[k] = (std::max)(hi[k], c[k]); }
  }
  if(!(lo[0] <= hi[0]) || !std::isfinite(hi[0] - lo[0]) || !std::isfinite(hi[1] - lo[1]) || !std::isfinite(hi[2] - lo[2]))
    throw Invalid_input("fit_stamp_frame(): the mesh has no vertex, or an extent that is not finite");
  // halves: no overflow for drawings spanning the whole range of doubles
  double dlo[2] = {inf, inf}, dhi[2] = {-inf, -inf};
  for(const auto& polyline : drawing)
    for(const auto& p : polyline)
      for(int k = 0; k < 2; ++k) { dlo[k] = (std::min)(dlo[k], double(p[k]) / 2); dhi[k] = (std::max)(dhi[k], double(p[k]) / 2); }
  if(!(dlo[0] <= dhi[0])) throw Invalid_input("fit_stamp_frame(): the drawing has no point");
  const double w = dhi[0] - dlo[0], h = dhi[1] - dlo[1];   // half the drawing's width and height
  const double tiny = (std::numeric_limits<double>::min)();
  const double scale = (std::min)(fill * ((hi[0] - lo[0]) / 2) / (std::max)(w, tiny), fill * ((hi[1] - lo[1]) / 2) / (std::max)(h, tiny));
  const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  // the drawing's centre on the mesh's centre, the plane a diagonal in front of it
  const Point_3 centre = CGAL::ORIGIN + (lo[0] / 2 + hi[0] / 2) * right + (lo[1] / 2 + hi[1] / 2) * down +
                         (lo[2] / 2 + hi[2] / 2 - diagonal) * d;
  Stamp_frame<GT> frame;
  frame.x_axis = scale * right;
  frame.y_axis = scale * down;
  frame.direction = d;
  frame.origin = centre - (dlo[0] + dhi[0]) * frame.x_axis - (dlo[1] + dhi[1]) * frame.y_axis;
  return frame;
}

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief stamps a 2D drawing onto `tm`: every point of the drawing, placed in space by `frame`, is sent
along `frame.direction` and lands where its ray first hits the surface (AABB tree ray shooting).

The segments of the drawing are first divided into pieces no longer than half the mean edge length of `tm`
(measured in space), so that the stamped polylines follow the surface. A polyline is broken where a ray
misses the mesh, where it first hits a face from its back (the face's normal pointing away from the
drawing: through a hole, the inside of the surface), and where two consecutive points land more than four
mean edge lengths apart (a jump to another layer of the surface, or a steep flank seen from the side). A
closed polyline (last point equal to the first) stays closed only if it is not broken. The result is meant
for `polylines_to_chain()`, and the surface winding numbers close the gaps.
\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles, with an internal vertex point map
\tparam PolylineRange a range of ranges of 2D points given as `std::array<double, 2>` (or anything with
        `p[0]`, `p[1]`)
\tparam GT a model of `Kernel`, with the point type of the mesh
\returns the stamped polylines, each a `std::vector` of points of the mesh
\throws Invalid_input if a point of the drawing is not finite or is placed by `frame` at a point that is not
finite, the frame's direction is the null vector or not finite, its origin or axes are not finite, a vertex
of the mesh is not finite, or the divided drawing would have more than \f$ 2^{26} \f$ points. The rays are
shot at unit scale (the mesh's coordinates multiplied by a power of two), so that a mesh and its copy
scaled by any power of ten from 1e-150 to 1e150 get the same stamp, up to the scale.
*/
template <class TriangleMesh, class PolylineRange, class GT>
std::vector<std::vector<typename GT::Point_3> >
stamp_polylines(const TriangleMesh& tm, const PolylineRange& drawing, const Stamp_frame<GT>& frame)
{
  typedef typename GT::Point_3 Point_3;
  typedef typename GT::Vector_3 Vector_3;
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type VPM;
  namespace PMP = CGAL::Polygon_mesh_processing;

  // bad input first
  internal::check_drawing(drawing, "stamp_polylines()");
  const Vector_3 direction = internal::unit_direction(frame.direction, "stamp_polylines(): the frame's direction");
  for(const Vector_3& v : {frame.origin - CGAL::ORIGIN, frame.x_axis, frame.y_axis})
    if(!std::isfinite(CGAL::to_double(v.x())) || !std::isfinite(CGAL::to_double(v.y())) || !std::isfinite(CGAL::to_double(v.z())))
      throw Invalid_input("stamp_polylines(): the frame's origin or axes are not finite");
  std::vector<std::vector<Point_3> > result;
  if(faces(tm).empty()) return result;
  const VPM vpm = get(CGAL::vertex_point, tm);
  bool finite = true;
  const double unit = internal::mesh_unit_scale(tm, vpm, finite);
  if(!finite) throw Invalid_input("stamp_polylines(): a vertex of the mesh has a coordinate that is not finite");

  // everything below at unit scale (the queries of the AABB tree square lengths), back to the input's scale
  // at the end
  typedef internal::Scaled_point_map<VPM, Point_3> SPM;
  const SPM spm{vpm, unit};
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, SPM> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Primitive> > Tree;
  Tree tree;
  PMP::build_AABB_tree(tm, tree, CGAL::parameters::vertex_point_map(spm));
  const double mean_edge = internal::mean_edge_length(tm, spm);
  const double step = mean_edge / 2;
  auto in_space = [&](const auto& p) {   // unit scale; not finite where the drawing is too large for the frame
    const Vector_3 x = double(p[0]) * frame.x_axis + double(p[1]) * frame.y_axis;
    return CGAL::ORIGIN + unit * ((frame.origin - CGAL::ORIGIN) + x);
  };
  auto finite_point = [](const Point_3& p) {
    return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) && std::isfinite(CGAL::to_double(p.z()));
  };

  // the drawing's points in space, segments divided; at most `max_points` in all (a drawing far larger
  // than the mesh, or a mesh with degenerate edges, is refused rather than run without bound)
  const std::size_t max_points = std::size_t(1) << 26;
  std::vector<std::vector<Point_3> > dense_polylines;
  std::size_t total = 0;
  std::size_t c = 0;
  for(const auto& polyline : drawing)
  {
    std::vector<Point_3> in;
    for(const auto& p : polyline)
    {
      in.push_back(in_space(p));
      if(!finite_point(in.back()))
        throw Invalid_input("stamp_polylines(): polyline " + std::to_string(c) + ", point " + std::to_string(in.size() - 1) +
                            " of the drawing is placed at a point that is not finite (drawing too large for its frame)");
    }
    ++c;
    dense_polylines.emplace_back();
    if(in.empty()) continue;
    std::vector<Point_3>& dense = dense_polylines.back();
    dense.push_back(in.front());
    for(std::size_t i = 0; i + 1 < in.size(); ++i)
    {
      const double pieces = internal::length(in[i + 1] - in[i]) / step;
      if(!(pieces <= double(max_points - total)))
        throw Invalid_input("stamp_polylines(): the drawing, divided into pieces of half the mean edge length of the "
                            "mesh, would have more than " + std::to_string(max_points) + " points");
      const std::size_t n = std::size_t(std::ceil(pieces));
      for(std::size_t k = 1; k < n; ++k) dense.push_back(in[i] + (double(k) / double(n)) * (in[i + 1] - in[i]));
      dense.push_back(in[i + 1]);
      total += n;
    }
  }

  c = 0;
  for(const auto& polyline : drawing)
  {
    const std::vector<Point_3>& dense = dense_polylines[c++];
    if(dense.empty()) continue;
    std::vector<Point_3> in;
    for(const auto& p : polyline) in.push_back(in_space(p));
    const bool closed = in.size() > 2 && in.front() == in.back();
    // the hits; a miss, or a jump to another layer of the surface, breaks the polyline
    std::vector<std::vector<Point_3> > pieces(1);
    bool missed = false, first_missed = false;
    for(std::size_t i = 0; i < dense.size(); ++i)
    {
      const auto loc = PMP::locate_with_AABB_tree(typename GT::Ray_3(dense[i], direction), tree, tm,
                                                  CGAL::parameters::vertex_point_map(spm));
      bool hit = loc.first != boost::graph_traits<TriangleMesh>::null_face();
      if(hit)   // a face seen from its back (through a hole, the inside of the surface) is a miss
      {
        const auto g = halfedge(loc.first, tm);
        const Point_3 &a = get(spm, source(g, tm)), &b = get(spm, target(g, tm)), &d = get(spm, target(next(g, tm), tm));
        hit = CGAL::to_double(CGAL::cross_product(b - a, d - a) * direction) < 0;
      }
      const Point_3 q = hit ? PMP::construct_point(loc, tm, CGAL::parameters::vertex_point_map(vpm)) : dense[i];
      const bool jump = hit && !pieces.back().empty() &&
                        internal::length(pieces.back().back() - q) * unit > 4 * mean_edge;
      if(!hit || jump)
      {
        missed = true;
        first_missed = first_missed || i == 0;
        if(!pieces.back().empty()) pieces.emplace_back();
      }
      if(hit) pieces.back().push_back(q);
    }
    if(pieces.back().empty()) pieces.pop_back();
    if(closed && missed && !first_missed && pieces.size() > 1)   // the last piece runs on into the first
    {
      pieces.back().insert(pieces.back().end(), pieces.front().begin() + 1, pieces.front().end());
      pieces.erase(pieces.begin());
    }
    for(auto& piece : pieces)
      if(piece.size() > 1) result.push_back(std::move(piece));
  }
  return result;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_STAMP_POLYLINES_H
