// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The swn tool's readers in Python: `_read_mesh()` (OFF, OBJ, PLY, STL, order kept), and `_read_curve()` /
// `_load()`, which read curves as the tool does and put them on the edges of the mesh with the tool's
// conforming cut (points on edges become vertices, short pieces ending inside the mesh are refined). Their
// errors are the tool's Input_error (FILE:LINE: reason), raised as swn.InputError.

#include "swn_python.h"

#include "swn_io/conforming_cut.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"

#include <pybind11/stl.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace swn_python {

namespace IO = CGAL::Surface_winding_numbers::IO;

namespace {

typedef IO::Cut_result<K::Point_3> Cut_result;

// the curves on the edges of the cut mesh as halfedges (k x 2 vertex pairs, along the curve) with their
// multiplicities (positive), in the order of the mesh's edges, and the input face of every face
py::dict curves_on_mesh_dict(const Cut_result& cut, const std::vector<std::string>& warnings)
{
  const Mesh& mesh = cut.mesh;
  const py::tuple curve = chain_halfedges(mesh, cut.chain);
  py::dict d;
  d["V"] = vertex_array(mesh);
  d["F"] = face_array(mesh);
  d["halfedges"] = curve[0];
  d["multiplicities"] = curve[1];
  d["face_origin"] = array_of(std::vector<std::int64_t>(cut.face_origin.begin(), cut.face_origin.end()));
  py::dict info;
  info["input_vertices"] = cut.input_vertices;
  info["input_faces"] = cut.input_faces;
  info["cut_vertices"] = cut.cut_new_vertices;
  info["cut_faces"] = cut.cut_new_faces;
  info["refinement_vertices"] = cut.refine_new_vertices;
  info["refinement_faces"] = cut.refine_new_faces;
  info["refined_pieces"] = cut.refined_pieces;
  info["skipped_segments"] = cut.skipped_segments;
  info["warnings"] = string_list(warnings);
  d["info"] = info;
  return d;
}

IO::Cut_options cut_options(bool refine_short_pieces, std::size_t minimum_piece_edges)
{
  IO::Cut_options options;
  options.refine_short_pieces = refine_short_pieces;
  options.min_piece_edges = minimum_piece_edges;
  return options;
}

// the tool's conforming cut, on a mesh that keeps the file's numbering (no garbage)
Cut_result cut(const Mesh& mesh, const std::vector<IO::Curve_set>& curves, const IO::Cut_options& options)
{
  Cut_result result = IO::conforming_cut(mesh, curves, options);
  if(result.mesh.has_garbage()) throw std::logic_error("the conforming cut left removed elements in the mesh");
  return result;
}

py::tuple read_mesh(const std::string& path)
{
  Mesh mesh;
  IO::Mesh_read_info info;
  {
    py::gil_scoped_release release;
    info = IO::read_mesh(path, mesh);
  }
  std::vector<std::string> warnings = info.warnings;
  if(IO::has_curve_records(info))
    warnings.push_back(path + ": the file's curve records (l, c) are not read by read_mesh(); swn.load() reads them");
  return py::make_tuple(vertex_array(mesh), face_array(mesh), string_list(warnings));
}

py::dict read_curve(const std::string& path, py::handle V, py::handle F, bool refine_short_pieces,
                    std::size_t minimum_piece_edges)
{
  const Triangle_soup soup = soup_from_arrays(V, F);
  std::vector<std::string> warnings;
  Cut_result result;
  {
    py::gil_scoped_release release;
    Mesh mesh;
    mesh_from_soup(soup, mesh, warnings);
    const IO::Curve_set curve = IO::read_curve_file(path, mesh);
    result = cut(mesh, {curve}, cut_options(refine_short_pieces, minimum_piece_edges));
  }
  return curves_on_mesh_dict(result, warnings);
}

py::dict load(const std::string& mesh_path, const std::optional<std::string>& curve_path, bool refine_short_pieces,
              std::size_t minimum_piece_edges)
{
  IO::Mesh_read_info info;
  Cut_result result;
  {
    py::gil_scoped_release release;
    Mesh mesh;
    info = IO::read_mesh(mesh_path, mesh);
    std::vector<IO::Curve_set> curves;
    if(IO::has_curve_records(info)) curves.push_back(IO::curve_set_from_obj(info, mesh));
    if(curve_path) curves.push_back(IO::read_curve_file(*curve_path, mesh));
    if(curves.empty())
      throw IO::Input_error(mesh_path, 0, "no curve: give a curve file, or `l` lines in an OBJ mesh");
    result = cut(mesh, curves, cut_options(refine_short_pieces, minimum_piece_edges));
  }
  return curves_on_mesh_dict(result, info.warnings);
}

} // namespace

void bind_readers(py::module_& m)
{
  m.def("_read_mesh", &read_mesh, py::arg("path"));
  m.def("_read_curve", &read_curve, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("refine_short_pieces"),
        py::arg("minimum_piece_edges"));
  m.def("_load", &load, py::arg("mesh_path"), py::arg("curve_path"), py::arg("refine_short_pieces"),
        py::arg("minimum_piece_edges"));
}

} // namespace swn_python
