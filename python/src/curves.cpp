// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Curves off the mesh: `_polylines_to_chain()` puts 3D polylines onto the triangle mesh (V, F) with the
// library's polylines_to_chain(), `_stamp_polylines()` stamps a 2D drawing (an SVG file read by the tool's
// reader, or 2D polylines) with stamp_polylines() in a given or fitted frame first. Both return the cut
// mesh, the curves on its edges, the input face of every face (the named parameter face_origin_map) and
// what the library did.

#include "swn_python.h"

#include "swn_io/read_polylines.h"

#include <CGAL/Surface_winding_numbers/polylines_to_chain.h>
#include <CGAL/Surface_winding_numbers/stamp_polylines.h>

#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace swn_python {

namespace SWN = CGAL::Surface_winding_numbers;
namespace IO = CGAL::Surface_winding_numbers::IO;

namespace {

typedef std::vector<std::vector<K::Point_3>> Polylines_3;
typedef std::vector<std::vector<std::array<double, 2>>> Polylines_2;

// the polylines of a sequence of (k, d) arrays of points; ValueError naming `what[i]` on a bad shape or a
// point that is not finite
template <int D, class Point, class Make>
std::vector<std::vector<Point>> read_polylines(py::handle polylines, const std::string& what, Make make)
{
  std::vector<std::vector<Point>> result;
  const py::module_ np = py::module_::import("numpy");
  std::size_t i = 0;
  for(py::handle p : polylines)
  {
    const std::string name = what + "[" + std::to_string(i++) + "]";
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(np.attr("asarray")(p, "float64"));
    if(!a || a.ndim() != 2 || a.shape(1) != D)
      throw py::value_error(name + " must be a (k, " + std::to_string(D) + ") array of points");
    const auto r = a.unchecked<2>();
    result.emplace_back();
    for(py::ssize_t k = 0; k < r.shape(0); ++k)
    {
      for(int c = 0; c < D; ++c)
        if(!std::isfinite(r(k, c)))
          throw py::value_error(name + ": point " + std::to_string(k) + " has a non-finite coordinate");
      result.back().push_back(make(&r(k, 0)));
    }
  }
  return result;
}

K::Vector_3 vector_of(const std::array<double, 3>& v) { return K::Vector_3(v[0], v[1], v[2]); }
py::tuple tuple_of(const K::Vector_3& v) { return py::make_tuple(v.x(), v.y(), v.z()); }

// the library's polylines_to_chain() on the mesh of (V, F): the dict of a CurveOnMesh, with `face_origin`
py::dict put_on_mesh(Mesh& mesh, const Polylines_3& polylines, std::optional<double> projection_tolerance,
                     bool refine_short_pieces, std::size_t minimum_piece_edges, py::dict info)
{
  const std::size_t input_vertices = mesh.number_of_vertices(), input_faces = mesh.number_of_faces();
  auto chain = mesh.add_property_map<Mesh::Edge_index, int>("e:swn_python_chain", 0).first;
  auto origin = mesh.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:swn_python_origin").first;
  SWN::Polylines_to_chain_result<Mesh> r;
  {
    py::gil_scoped_release release;
    const auto np = SWN::parameters::refine_short_pieces(refine_short_pieces,
                    SWN::parameters::minimum_piece_edges(minimum_piece_edges,
                    SWN::parameters::face_origin_map(origin)));
    r = projection_tolerance ? SWN::polylines_to_chain(mesh, polylines, chain, SWN::parameters::projection_tolerance(*projection_tolerance, np))
                             : SWN::polylines_to_chain(mesh, polylines, chain, np);
  }
  if(!r) throw py::value_error(r.error);
  if(mesh.has_garbage()) throw std::logic_error("the cut left removed elements in the mesh");
  std::vector<int> values(mesh.number_of_edges(), 0);
  for(Mesh::Edge_index e : mesh.edges()) values[std::size_t(e)] = chain[e];
  mesh.remove_property_map(chain);
  const py::tuple curve = chain_halfedges(mesh, values);
  if(py::len(curve[1]) == 0)
    throw py::value_error(IO::no_curve_left_reason(r.points, r.points_off_surface, r.border_pieces, r.curves, r.failed_walks,
                                                   projection_tolerance ? "projection_tolerance" : "the mean edge length"));
  std::vector<std::int64_t> face_origin(mesh.number_of_faces());
  for(Mesh::Face_index f : mesh.faces()) face_origin[std::size_t(f)] = std::int64_t(origin[f]);
  mesh.remove_property_map(origin);
  const std::pair<const char*, std::size_t> counts[] = {
    {"input_vertices", input_vertices}, {"input_faces", input_faces}, {"cut_vertices", r.cut.cut_vertices},
    {"cut_faces", r.cut.cut_faces}, {"refinement_vertices", r.cut.refinement_vertices},
    {"refinement_faces", r.cut.refinement_faces}, {"refined_pieces", r.cut.refined_pieces}, {"points", r.points},
    {"points_off_surface", r.points_off_surface}, {"failed_walks", r.failed_walks},
    {"crossing_vertices", r.cut.crossing_vertices}, {"curves", r.curves}, {"border_pieces", r.border_pieces}};
  for(const auto& [key, value] : counts) info[key] = value;
  info["pieces"] = r.pieces;
  py::list warnings = info.contains("warnings") ? py::list(info["warnings"]) : py::list();
  for(const std::string& w : r.warnings) warnings.append(w);
  info["warnings"] = warnings;
  py::dict d;
  d["V"] = vertex_array(mesh);
  d["F"] = face_array(mesh);
  d["halfedges"] = curve[0];
  d["multiplicities"] = curve[1];
  d["face_origin"] = array_of(face_origin);
  d["info"] = info;
  return d;
}

// the triangle mesh of (V, F), its warnings in `info`
void mesh_of(py::handle V, py::handle F, Mesh& mesh, py::dict& info)
{
  std::vector<std::string> warnings;
  mesh_from_arrays(V, F, mesh, warnings);
  info["warnings"] = string_list(warnings);
}

py::dict polylines_to_chain(py::handle V, py::handle F, py::handle polylines, std::optional<double> projection_tolerance,
                            bool refine_short_pieces, std::size_t minimum_piece_edges)
{
  Mesh mesh;
  py::dict info;
  mesh_of(V, F, mesh, info);
  const Polylines_3 p = read_polylines<3, K::Point_3>(polylines, "polylines", [](const double* x) { return K::Point_3(x[0], x[1], x[2]); });
  return put_on_mesh(mesh, p, projection_tolerance, refine_short_pieces, minimum_piece_edges, info);
}

// `drawing`: an SVG file name (str) or 2D polylines; `frame`: (origin, x_axis, y_axis, direction), or None for
// the frame fitted along `direction` with `fill`
py::dict stamp_polylines(py::handle V, py::handle F, py::handle drawing, std::optional<std::array<std::array<double, 3>, 4>> frame,
                         std::array<double, 3> direction, double fill, std::optional<double> projection_tolerance,
                         bool refine_short_pieces, std::size_t minimum_piece_edges)
{
  Mesh mesh;
  py::dict info;
  mesh_of(V, F, mesh, info);
  py::list warnings = info["warnings"].cast<py::list>();
  Polylines_2 polylines;
  if(py::isinstance<py::str>(drawing))
  {
    const std::string file = drawing.cast<std::string>();
    IO::Svg_drawing svg;
    {
      py::gil_scoped_release release;
      svg = IO::read_svg_polylines(file);
    }
    polylines = std::move(svg.polylines);
    for(const std::string& w : svg.warnings) warnings.append(w);
  }
  else
    polylines = read_polylines<2, std::array<double, 2>>(drawing, "drawing", [](const double* x) { return std::array<double, 2>{x[0], x[1]}; });
  std::size_t points = 0;
  for(const auto& p : polylines) points += p.size();
  if(points == 0) throw py::value_error("the drawing has no point");
  SWN::Stamp_frame<K> f;
  if(frame)
  {
    const auto& [o, x, y, d] = *frame;
    f.origin = K::Point_3(o[0], o[1], o[2]);
    f.x_axis = vector_of(x);
    f.y_axis = vector_of(y);
    f.direction = vector_of(d);
    for(const auto& v : *frame)
      for(double c : v)
        if(!std::isfinite(c)) throw py::value_error("frame: a coordinate is not finite");
    if(f.direction.squared_length() == 0) throw py::value_error("frame: the direction is the null vector");
  }
  else
  {
    if(!std::isfinite(direction[0] + direction[1] + direction[2]) || vector_of(direction).squared_length() == 0)
      throw py::value_error("direction must be three finite numbers, not all zero");
    if(!(fill > 0) || !std::isfinite(fill)) throw py::value_error("fill must be positive and finite");
    f = SWN::fit_stamp_frame(mesh, polylines, vector_of(direction), fill);
  }
  Polylines_3 stamped;
  {
    py::gil_scoped_release release;
    stamped = SWN::stamp_polylines(mesh, polylines, f);
  }
  if(stamped.empty()) throw py::value_error("the stamped drawing misses the mesh");
  info["frame"] = py::make_tuple(py::make_tuple(f.origin.x(), f.origin.y(), f.origin.z()), tuple_of(f.x_axis),
                                 tuple_of(f.y_axis), tuple_of(f.direction));
  info["warnings"] = warnings;
  return put_on_mesh(mesh, stamped, projection_tolerance, refine_short_pieces, minimum_piece_edges, info);
}

} // namespace

void bind_curves(py::module_& m)
{
  m.def("_polylines_to_chain", &polylines_to_chain, py::arg("V"), py::arg("F"), py::arg("polylines"),
        py::arg("projection_tolerance"), py::arg("refine_short_pieces"), py::arg("minimum_piece_edges"));
  m.def("_stamp_polylines", &stamp_polylines, py::arg("V"), py::arg("F"), py::arg("drawing"), py::arg("frame"),
        py::arg("direction"), py::arg("fill"), py::arg("projection_tolerance"), py::arg("refine_short_pieces"),
        py::arg("minimum_piece_edges"));
}

} // namespace swn_python
