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

#include <array>
#include <cstddef>
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
  std::vector<std::vector<std::array<double, 3> > > polylines;
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
  \brief puts the curves onto `cut.mesh` (cutting it further) and adds them to `cut.chain`; calls `warn`
  with every warning as it comes (the drawing's, and the library's about polylines that gave nothing, each
  with its file).
  \throws Input_error when a polyline has a point that is not finite, and when there is no curve at all on
  the surface afterwards (every point too far, every ray missing, and no other curve).
*/
template <class Point, class Warn>
void add_off_mesh_curves(Cut_result<Point>& cut, const Off_mesh_curves& curves, const Warn& warn)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  for(const std::string& w : curves.drawing.warnings) warn(w);
  Mesh& mesh = cut.mesh;
  auto chain = mesh.template add_property_map<typename Mesh::Edge_index, int>("e:swn_off_mesh_chain", 0).first;
  for(auto e : mesh.edges()) chain[e] = cut.chain[std::size_t(e)];
  auto put_on_mesh = [&](const std::vector<std::vector<Point> >& polylines, const std::string& file) {
    const auto r = polylines_to_chain(mesh, polylines, chain);
    if(!r) throw Input_error(file, 0, r.error);
    for(const std::string& w : r.warnings) warn(file + ": " + w);
  };
  if(!curves.polylines_file.empty())
  {
    std::vector<std::vector<Point> > polylines;
    for(const auto& l : curves.polylines)
    {
      polylines.emplace_back();
      for(const auto& p : l) polylines.back().emplace_back(p[0], p[1], p[2]);
    }
    put_on_mesh(polylines, curves.polylines_file);
  }
  if(!curves.stamp_file.empty())
  {
    const typename K::Vector_3 d(curves.direction[0], curves.direction[1], curves.direction[2]);
    const auto stamped = stamp_polylines(mesh, curves.drawing.polylines, fit_stamp_frame(mesh, curves.drawing.polylines, d));
    if(stamped.empty()) throw Input_error(curves.stamp_file, 0, "the stamped drawing misses the mesh");
    put_on_mesh(stamped, curves.stamp_file);
  }
  bool any = false;
  for(auto e : mesh.edges()) any = any || chain[e] != 0;
  if(!any)
    throw Input_error(curves.polylines_file.empty() ? curves.stamp_file : curves.polylines_file, 0,
                      "no curve on the surface (every point is too far from it)");
  cut.chain.assign(mesh.number_of_edges(), 0);
  for(auto e : mesh.edges()) cut.chain[std::size_t(e)] = chain[e];
  mesh.remove_property_map(chain);
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_CURVES_OFF_MESH_H
