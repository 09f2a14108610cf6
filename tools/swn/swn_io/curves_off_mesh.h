// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The tool's curves off the mesh: 3D polylines (--polylines FILE.obj) and a stamped 2D drawing (--stamp
// FILE.svg --direction X,Y,Z), put on the (already cut) mesh by the library's polylines_to_chain().

#ifndef CGAL_SWN_TOOL_IO_CURVES_OFF_MESH_H
#define CGAL_SWN_TOOL_IO_CURVES_OFF_MESH_H

#include "swn_io/conforming_cut.h"
#include "swn_io/errors.h"
#include "swn_io/read_polylines.h"

#include <CGAL/Surface_winding_numbers/polylines_to_chain.h>
#include <CGAL/Surface_winding_numbers/stamp_polylines.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief curves given off the mesh, as read from their files.
*/
struct Off_mesh_curves
{
  /// the `--polylines` file (empty: none) and its 3D polylines
  std::string polylines_file;
  Obj_polylines polylines;
  /// the `--stamp` file (empty: none), its drawing, and the direction it is stamped along
  std::string stamp_file;
  Svg_drawing drawing;
  std::array<double, 3> direction = {0, 0, -1};

  bool empty() const { return polylines_file.empty() && stamp_file.empty(); }
};

/// reads the files of `curves` (throws `Input_error` on bad input)
inline void read_off_mesh_curves(Off_mesh_curves& curves)
{
  if(!curves.polylines_file.empty()) curves.polylines = read_obj_polylines(curves.polylines_file);
  if(!curves.stamp_file.empty()) curves.drawing = read_svg_polylines(curves.stamp_file);
}

/*!
  \brief what the library did with the curves of one file (`--polylines` or `--stamp`): the counts of
  `polylines_to_chain()` and of its cut.
*/
struct Off_mesh_report
{
  /// the file, and whether it is a stamped drawing
  std::string file;
  bool stamp = false;
  /// polylines in the file (a stamp: the drawing's), and, for a stamp, the polylines the stamp gave (a ray
  /// missing the mesh, meeting the back of a face or jumping to another layer breaks a polyline)
  std::size_t polylines = 0, stamped_polylines = 0;
  /// `Polylines_to_chain_result`: points (a stamp: of the stamped polylines), points farther than the mean
  /// edge length from the surface, segments the walk could not follow, pieces along the border of the
  /// mesh dropped, vertices the cut put where curves cross inside a face
  /// (`Conforming_cut_result::crossing_vertices`), curves put on the mesh
  std::size_t points = 0, points_off_surface = 0, failed_walks = 0, border_pieces = 0, crossing_vertices = 0, curves = 0;
  /// the cut: vertices and faces added, short pieces refined and the vertices and faces that added
  std::size_t cut_vertices = 0, cut_faces = 0, refined_pieces = 0, refinement_vertices = 0, refinement_faces = 0;
  /// one line per polyline broken into pieces, losing points or pieces along the border (`FILE:LINE: ...`),
  /// for `--verbose`
  std::vector<std::string> details;
};

/// the report in one line: `polylines FILE: ...` or `stamp FILE: ...`
inline std::string summary_line(const Off_mesh_report& r)
{
  std::string s = std::string(r.stamp ? "stamp " : "polylines ") + r.file + ": " + std::to_string(r.polylines) + " polylines";
  if(r.stamp) s += " stamped as " + std::to_string(r.stamped_polylines);
  return s + ", " + std::to_string(r.points) + " points (" + std::to_string(r.points_off_surface) + " off the surface), " +
         std::to_string(r.failed_walks) + " failed walks, " + std::to_string(r.border_pieces) + " pieces along the border "
         "dropped, " + std::to_string(r.crossing_vertices) + " crossings: " +
         std::to_string(r.curves) + " curves; cut: " + std::to_string(r.cut_vertices) + " vertices added, " +
         std::to_string(r.refined_pieces) + " pieces refined (" + std::to_string(r.refinement_vertices) + " vertices)";
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// "polyline K..." of the library's warnings, with the line of polyline K in `lines` (if given)
inline std::string locate_polyline_warning(const std::string& w, const std::string& file, const std::vector<std::size_t>& lines)
{
  std::size_t k = 0, i = 9;
  if(w.compare(0, 9, "polyline ") != 0 || i >= w.size() || !std::isdigit((unsigned char)w[i])) return file + ": " + w;
  for(; i < w.size() && std::isdigit((unsigned char)w[i]); ++i) k = k > lines.size() ? k : 10 * k + std::size_t(w[i] - '0');
  return Input_error::format(file, k < lines.size() ? lines[k] : 0, w);
}

// the per-polyline lines of `r` and the warnings about polylines that lose points or are broken; `given`:
// the polylines as given, `lines` their lines in the file (empty for stamped polylines)
template <class Result, class PolylineRange, class Warn>
void polyline_details(const Result& r, const PolylineRange& given, const std::vector<std::size_t>& lines,
                      Off_mesh_report& report, const Warn& warn)
{
  std::size_t k = 0, warned = 0, not_warned = 0;
  for(const auto& polyline : given)
  {
    if(k >= r.pieces.size()) break;
    const auto& pieces = r.pieces[k];
    const std::size_t n = polyline.size();
    const bool closed = n > 2 && polyline.front() == polyline.back();
    const std::size_t distinct = closed ? n - 1 : n;
    std::vector<bool> on(distinct, false);
    for(const auto& piece : pieces)
      for(std::size_t i : piece) if(i < distinct) on[i] = true;
    const std::size_t kept = std::size_t(std::count(on.begin(), on.end(), true));
    const bool broken = pieces.size() > 1 || (closed && pieces.size() == 1 && !pieces[0].empty() && pieces[0].front() != pieces[0].back());
    const std::size_t border = k < r.polyline_border_pieces.size() ? r.polyline_border_pieces[k] : 0;
    const std::string where = Input_error::format(report.file, k < lines.size() ? lines[k] : 0,
                                                  std::string(report.stamp ? "stamped polyline " : "polyline ") + std::to_string(k));
    ++k;
    if(kept == 0 || (kept == distinct && !broken && border == 0)) continue;   // nothing lost (no point near: the library's warning)
    std::string d = where + ": ";
    if(kept < distinct) d += std::to_string(distinct - kept) + " of its " + std::to_string(distinct) +
                             " points are farther than the mean edge length from the surface and dropped; ";
    d += "on the surface in " + std::to_string(pieces.size()) + (pieces.size() == 1 ? " piece" : " pieces") +
         (broken ? " (gaps)" : "");
    if(border > 0) d += "; " + std::to_string(border) + (border == 1 ? " piece" : " pieces") + " along the border of the mesh dropped";
    report.details.push_back(d);
    if(report.stamp || kept == distinct) continue;   // warnings: the polylines as drawn that lose points
    if(warned < 10) { warn(d); ++warned; }
    else ++not_warned;
  }
  if(not_warned > 0) warn(report.file + ": " + std::to_string(not_warned) + " more polylines lose points (--verbose lists them)");
}

} // namespace internal
/// \endcond

/*!
  \brief puts the curves onto `cut.mesh` (cutting it further), adds them to `cut.chain` and adds the
  vertices and faces of the cut and of the refinement to the counts of `cut`; calls `warn` with every
  warning as it comes (the drawing's, the library's about polylines that gave nothing, polylines that lose
  points and segments the walk could not follow, each with its file and line).
  \param mesh_file the mesh's file, named when the stamp fails because of the mesh
  \returns one report per file (polylines first, then the stamp)
  \throws Input_error when there is no curve at all on the surface afterwards (every point too far, every
  ray missing or meeting the back of the faces, every piece along the border of the mesh, or curves that
  cancel out), and when the mesh's size puts the stamped points out of the range of doubles.
*/
template <class Point, class Warn>
std::vector<Off_mesh_report> add_off_mesh_curves(Cut_result<Point>& cut, const Off_mesh_curves& curves,
                                                 const std::string& mesh_file, const Warn& warn)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  for(const std::string& w : curves.drawing.warnings) warn(w);
  Mesh& mesh = cut.mesh;
  auto chain = mesh.template add_property_map<typename Mesh::Edge_index, int>("e:swn_off_mesh_chain", 0).first;
  for(auto e : mesh.edges()) chain[e] = cut.chain[std::size_t(e)];
  std::vector<Off_mesh_report> reports;
  std::size_t first_line_on_surface = 0;   // the line of the first polyline put on the surface
  std::string border_file;   // the file and line of the first polyline with a piece along the border
  std::size_t border_line = 0;
  // the input face of every face: the face it is a piece of (polylines_to_chain()), and that one's
  auto origin = mesh.template add_property_map<typename Mesh::Face_index, typename Mesh::Face_index>("f:swn_off_mesh_origin").first;
  auto put_on_mesh = [&](const std::vector<std::vector<Point> >& polylines, Off_mesh_report& report,
                         const std::vector<std::size_t>& lines) {
    for(auto f : mesh.faces()) origin[f] = f;
    const auto r = polylines_to_chain(mesh, polylines, chain, parameters::face_origin_map(origin));
    if(!r) throw Input_error(report.file, 0, r.error);
    std::vector<std::size_t> composed(mesh.number_of_faces());
    for(auto f : mesh.faces()) composed[std::size_t(f)] = cut.face_origin[std::size_t(origin[f])];
    cut.face_origin.swap(composed);
    for(const std::string& w : r.warnings) warn(internal::locate_polyline_warning(w, report.file, lines));
    for(std::size_t k = 0; k < r.pieces.size() && k < lines.size() && first_line_on_surface == 0; ++k)
      if(!r.pieces[k].empty()) first_line_on_surface = lines[k];
    report.points = r.points;
    report.points_off_surface = r.points_off_surface;
    report.failed_walks = r.failed_walks;
    report.border_pieces = r.border_pieces;
    for(std::size_t k = 0; k < r.polyline_border_pieces.size() && border_file.empty(); ++k)
      if(r.polyline_border_pieces[k] > 0) { border_file = report.file; border_line = k < lines.size() ? lines[k] : 0; }
    report.crossing_vertices = r.cut.crossing_vertices;
    report.curves = r.curves;
    report.cut_vertices = r.cut.cut_vertices;
    report.cut_faces = r.cut.cut_faces;
    report.refined_pieces = r.cut.refined_pieces;
    report.refinement_vertices = r.cut.refinement_vertices;
    report.refinement_faces = r.cut.refinement_faces;
    internal::polyline_details(r, polylines, lines, report, warn);
    if(report.failed_walks > 0)
      warn(report.file + ": " + std::to_string(report.failed_walks) + " segments could not be followed along the surface "
           "(the border, or a fold the walk cannot cross): gaps");
    if(report.border_pieces > 0)
      warn(report.file + ": " + std::to_string(report.border_pieces) + (report.border_pieces == 1 ? " piece" : " pieces") +
           " of curve along the border of the mesh dropped (curves may end on the border, not run along it)");
    cut.cut = cut.cut || report.cut_vertices > 0;
    cut.cut_new_vertices += report.cut_vertices;
    cut.cut_new_faces += report.cut_faces;
    cut.refine_new_vertices += report.refinement_vertices;
    cut.refine_new_faces += report.refinement_faces;
    cut.refined_pieces += report.refined_pieces;
  };
  if(!curves.polylines_file.empty())
  {
    reports.emplace_back();
    reports.back().file = curves.polylines_file;
    reports.back().polylines = curves.polylines.polylines.size();
    std::vector<std::vector<Point> > polylines;
    for(const auto& l : curves.polylines.polylines)
    {
      polylines.emplace_back();
      for(const auto& p : l) polylines.back().emplace_back(p[0], p[1], p[2]);
    }
    put_on_mesh(polylines, reports.back(), curves.polylines.lines);
  }
  if(!curves.stamp_file.empty())
  {
    reports.emplace_back();
    Off_mesh_report& report = reports.back();
    report.file = curves.stamp_file;
    report.stamp = true;
    report.polylines = curves.drawing.polylines.size();
    const auto& d = curves.direction;
    auto stamp = [&](double sign) {
      const typename K::Vector_3 v(sign * d[0], sign * d[1], sign * d[2]);
      try
      {
        return stamp_polylines(mesh, curves.drawing.polylines, fit_stamp_frame(mesh, curves.drawing.polylines, v));
      }
      catch(const std::exception& e)   // the library refuses the drawing (Invalid_input): say which file
      {
        throw Input_error(curves.stamp_file, 0, e.what());
      }
    };
    const auto stamped = stamp(1);
    std::ostringstream direction;
    direction.precision(17);
    direction << d[0] << "," << d[1] << "," << d[2];
    if(stamped.empty())
      throw Input_error(curves.stamp_file, 0, stamp(-1).empty()
        ? "the stamped drawing misses the mesh (along --direction " + direction.str() + " and the opposite direction)"
        : "nothing stamped: along --direction " + direction.str() + " every ray misses the mesh or meets the back of its "
          "faces (the side their normals point away from); the opposite direction meets their front");
    for(const auto& l : stamped)
      for(const Point& p : l)
        if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) || !std::isfinite(CGAL::to_double(p.z())))
          throw Input_error(mesh_file, 0, "the drawing " + curves.stamp_file + " cannot be stamped onto this mesh: the "
                            "stamped points are not finite numbers (the mesh's coordinates are too small or too large "
                            "for the ray shooting; scale the mesh towards unit size)");
    report.stamped_polylines = stamped.size();
    if(report.stamped_polylines != report.polylines)
      warn(curves.stamp_file + ": the drawing's " + std::to_string(report.polylines) + " polylines are stamped as " +
           std::to_string(report.stamped_polylines) + " (rays that miss the mesh, meet the back of a face or jump to "
           "another layer of the surface break them: gaps)");
    put_on_mesh(stamped, report, std::vector<std::size_t>());
  }
  bool any = false;
  for(auto e : mesh.edges()) any = any || chain[e] != 0;
  if(!any)
  {
    std::size_t points = 0, off = 0, border = 0, put = 0, failed = 0;
    for(const Off_mesh_report& r : reports)
    {
      points += r.points; off += r.points_off_surface; border += r.border_pieces; put += r.curves; failed += r.failed_walks;
    }
    const std::string why = no_curve_left_reason(points, off, border, put, failed, "the mean edge length");
    if(off < points && put == 0 && border > 0) throw Input_error(border_file, border_line, why);
    const bool polylines = !curves.polylines_file.empty();
    throw Input_error(polylines ? curves.polylines_file : curves.stamp_file, off == points ? 0 : first_line_on_surface, why);
  }
  cut.chain.assign(mesh.number_of_edges(), 0);
  for(auto e : mesh.edges()) cut.chain[std::size_t(e)] = chain[e];
  mesh.remove_property_map(chain);
  mesh.remove_property_map(origin);
  return reports;
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_CURVES_OFF_MESH_H
