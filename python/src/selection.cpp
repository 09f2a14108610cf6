// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Selection cleanup: `_clean_face_selection()` and `_clean_edge_selection()` run the library's
// clean_face_selection() and clean_edge_selection() on the triangle mesh (V, F) with the settings of a solve,
// and return the cleaned selection per face, its border as a chain on the mesh's edges and the report.

#include "swn_python.h"

#include "swn_io/solver_choice.h"

#include <CGAL/Surface_winding_numbers/clean_selection.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace swn_python {

namespace SWN = CGAL::Surface_winding_numbers;
namespace IO = CGAL::Surface_winding_numbers::IO;

namespace {

// runs `clean(np)` with the named parameters of the settings `o`, the bounding chain written to `bounding`
// (by edge index) and the report to `report`; true on success
template <class Clean>
bool with_parameters(const Mesh& mesh, const Solve_options& o, std::vector<int>& bounding,
                     SWN::Solve_report& report, Clean clean)
{
  return IO::with_solvers(o.lp_solver, o.linear_solver, [&](auto& lp, auto sparse_solver) {
    return clean(
      SWN::parameters::bounding_chain_map(boost::make_iterator_property_map(bounding.begin(), get(boost::edge_index, mesh)),
      SWN::parameters::epsilon(o.epsilon,
      SWN::parameters::use_reduced_residual(o.reduced_residual,
      SWN::parameters::filter_nonbounding_loops(o.filter_nonbounding_loops,
      SWN::parameters::concurrency(o.concurrency,
      SWN::parameters::lp_solver(std::ref(lp),
      SWN::parameters::report(std::ref(report))))))))
        .verbose(o.verbose).sparse_linear_solver(sparse_solver));
  });
}

// the cleaned selection `cleaned` (by face index), the bounding chain, the edges, the report and the warnings
py::dict result_dict(const Mesh& mesh, const std::vector<char>& cleaned, const std::vector<int>& bounding,
                     const SWN::Solve_report& report, const std::vector<std::string>& warnings)
{
  py::array_t<bool> selected(py::ssize_t(cleaned.size()));
  auto s = selected.mutable_unchecked<1>();
  for(std::size_t f = 0; f < cleaned.size(); ++f) s(py::ssize_t(f)) = cleaned[f] != 0;
  py::dict d;
  d["selected"] = selected;
  d["bounding"] = array_of(bounding);
  d["edges"] = edge_array(mesh);
  d["report"] = report_dict(report);
  d["warnings"] = string_list(warnings);
  return d;
}

// `face_mask`: m uint8, nonzero for the selected faces (checked by swn/__init__.py against len(F))
py::dict clean_face_selection(py::handle V, py::handle F, const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& face_mask,
                              const py::dict& options)
{
  const Solve_options o = solve_options(options);
  Mesh mesh;
  std::vector<std::string> warnings;
  mesh_from_arrays(V, F, mesh, warnings);
  const std::size_t nf = mesh.number_of_faces();
  if(face_mask.ndim() != 1 || std::size_t(face_mask.shape(0)) != nf)
    throw py::value_error("selection: one value per face (" + std::to_string(nf) + ") is needed");
  const auto mask = face_mask.unchecked<1>();
  std::vector<char> selection(nf), cleaned(nf, 0);
  for(std::size_t f = 0; f < nf; ++f) selection[f] = mask(py::ssize_t(f)) != 0;
  std::vector<int> bounding(mesh.number_of_edges(), 0);
  SWN::Solve_report report;
  bool ok = false;
  {
    py::gil_scoped_release release;
    const auto fi = get(boost::face_index, mesh);
    ok = with_parameters(mesh, o, bounding, report, [&](const auto& np) {
      return SWN::clean_face_selection(mesh, boost::make_iterator_property_map(selection.begin(), fi),
                                       boost::make_iterator_property_map(cleaned.begin(), fi), np);
    });
  }
  if(!ok) raise_failure(report);
  return result_dict(mesh, cleaned, bounding, report, warnings);
}

// `pairs`: (k, 2) vertex pairs of the selected edges, either way round; or, if `mask` is true, `pairs` is (E, 1):
// nonzero for the selected edges of the mesh's edge order
py::dict clean_edge_selection(py::handle V, py::handle F, const Index_array& pairs, bool mask, const py::dict& options)
{
  const Solve_options o = solve_options(options);
  Mesh mesh;
  std::vector<std::string> warnings;
  mesh_from_arrays(V, F, mesh, warnings);
  std::vector<Mesh::Edge_index> selection;
  const auto p = pairs.unchecked<2>();
  if(mask)
  {
    if(std::size_t(p.shape(0)) != mesh.number_of_edges())
      throw py::value_error("selection: a boolean mask needs one value per edge (" + std::to_string(mesh.number_of_edges()) +
                            ", in the order of the edges), not " + std::to_string(p.shape(0)));
    for(Mesh::Edge_index e : mesh.edges())
      if(p(py::ssize_t(e), 0)) selection.push_back(e);
  }
  else
  {
    const std::int64_t nv = std::int64_t(mesh.number_of_vertices());
    for(py::ssize_t k = 0; k < p.shape(0); ++k)
    {
      const std::string which = "selection[" + std::to_string(k) + "]: ";
      for(int c = 0; c < 2; ++c)
        if(p(k, c) < 0 || p(k, c) >= nv)
          throw py::value_error(which + "vertex index " + std::to_string(p(k, c)) + " is out of range (" +
                                std::to_string(nv) + " vertices)");
      const auto h = CGAL::halfedge(Mesh::Vertex_index(Mesh::size_type(p(k, 0))), Mesh::Vertex_index(Mesh::size_type(p(k, 1))), mesh);
      if(!h.second)
        throw py::value_error(which + "vertices " + std::to_string(p(k, 0)) + " and " + std::to_string(p(k, 1)) +
                              " are not joined by an edge of the mesh");
      selection.push_back(mesh.edge(h.first));
    }
  }
  std::vector<char> cleaned(mesh.number_of_faces(), 0);
  std::vector<int> bounding(mesh.number_of_edges(), 0);
  SWN::Solve_report report;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = with_parameters(mesh, o, bounding, report, [&](const auto& np) {
      return SWN::clean_edge_selection(mesh, selection,
                                       boost::make_iterator_property_map(cleaned.begin(), get(boost::face_index, mesh)), np);
    });
  }
  if(!ok) raise_failure(report);
  return result_dict(mesh, cleaned, bounding, report, warnings);
}

} // namespace

void bind_selection(py::module_& m)
{
  m.def("_clean_face_selection", &clean_face_selection, py::arg("V"), py::arg("F"), py::arg("face_mask"),
        py::arg("options"));
  m.def("_clean_edge_selection", &clean_edge_selection, py::arg("V"), py::arg("F"), py::arg("pairs"), py::arg("mask"),
        py::arg("options"));
}

} // namespace swn_python
