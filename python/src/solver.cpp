// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// `swn._swn.Solver`: a Surface_mesh built from (V, F) and the package's Surface_winding_numbers_solver on
// it; `_solve()` takes curves as vertex polylines (flattened, with offsets and one multiplicity each) and
// returns the outputs as numpy arrays, in the order of the input's faces and of the mesh's edges.

#include "swn_python.h"

#include <CGAL/surface_winding_numbers.h>

#include <boost/property_map/property_map.hpp>

#include <climits>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace swn_python {

namespace SWN = CGAL::Surface_winding_numbers;

namespace {

typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

// the report as a dict, its fields under their C++ names, the timings (time_X) in a dict `times`
py::dict report_dict(const SWN::Solve_report& r)
{
  py::dict d, times;
#define SWN_REPORT(F) d[#F] = r.F;
  SWN_REPORT(success) SWN_REPORT(error) SWN_REPORT(invalid_input)
  SWN_REPORT(vertices) SWN_REPORT(edges) SWN_REPORT(faces) SWN_REPORT(components)
  SWN_REPORT(border_edges) SWN_REPORT(border_loops) SWN_REPORT(genus)
  SWN_REPORT(euler_characteristic) SWN_REPORT(orientable)
  SWN_REPORT(curve_edges) SWN_REPORT(interior_endpoints)
  SWN_REPORT(homology_correction) SWN_REPORT(hodge_projection) SWN_REPORT(reduced_residual) SWN_REPORT(lp_ran)
  SWN_REPORT(jump_laplacian_reused) SWN_REPORT(jump_laplacian_update_rank) SWN_REPORT(lp_variables) SWN_REPORT(lp_rows) SWN_REPORT(lp_objective)
  SWN_REPORT(degenerate_weights) SWN_REPORT(min_label) SWN_REPORT(max_label) SWN_REPORT(nonbounding_closing_units)
#undef SWN_REPORT
#define SWN_TIME(F) times[#F] = r.time_##F;
  SWN_TIME(setup) SWN_TIME(jump_laplace) SWN_TIME(hodge) SWN_TIME(residual) SWN_TIME(second_solve)
  SWN_TIME(labels) SWN_TIME(total) SWN_TIME(mesh) SWN_TIME(output_maps)
#undef SWN_TIME
  d["times"] = times;
  return d;
}

// the library's failure as a Python exception with its message: ValueError for bad input, RuntimeError
// for a failed solver step
[[noreturn]] void raise_failure(const SWN::Solve_report& r)
{
  if(r.invalid_input) throw py::value_error(r.error);
  throw std::runtime_error(r.error);
}

template <class T>
py::array_t<T> array_of(const std::vector<T>& values)
{
  py::array_t<T> a(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

class Solver
{
  typedef SWN::Surface_winding_numbers_solver<Mesh> Library_solver;

public:
  Solver(py::handle V, py::handle F)
  {
    const Triangle_soup soup = soup_from_arrays(V, F);
    {
      py::gil_scoped_release release;
      mesh_from_soup(soup, mesh_, warnings_);
      solver_ = std::make_unique<Library_solver>(mesh_);
    }
    if(!solver_->is_valid()) raise_failure(solver_->report());
    construction_report_ = solver_->report();
  }

  py::dict solve(const Index_array& vertices, const Index_array& offsets, const Index_array& multiplicities,
                 double epsilon, bool reduced_residual, bool concurrency, bool keep_hodge_factorization, bool verbose)
  {
    const std::size_t nf = mesh_.number_of_faces(), ne = mesh_.number_of_edges();
    std::vector<int> chain(ne, 0);
    add_curves(vertices, offsets, multiplicities, chain);

    std::vector<int> labels(nf, 0), G(ne, 0), bounding(ne, 0);
    std::vector<double> g(ne, 0.), w(mesh_.number_of_halfedges(), std::numeric_limits<double>::quiet_NaN());
    SWN::Solve_report report;
    bool ok = false;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);   // one solve at a time on this solver
      const auto ei = get(boost::edge_index, mesh_);
      auto edge_map = [&](auto& v) { return boost::make_iterator_property_map(v.begin(), ei); };
      ok = solver_->solve(
        edge_map(chain), boost::make_iterator_property_map(labels.begin(), get(boost::face_index, mesh_)),
        SWN::parameters::nonbounding_chain_map(edge_map(G),
        SWN::parameters::nonbounding_chain_real_map(edge_map(g),
        SWN::parameters::bounding_chain_map(edge_map(bounding),
        SWN::parameters::winding_number_map(boost::make_iterator_property_map(w.begin(), get(boost::halfedge_index, mesh_)),
        SWN::parameters::epsilon(epsilon,
        SWN::parameters::use_reduced_residual(reduced_residual,
        SWN::parameters::concurrency(concurrency,
        SWN::parameters::keep_hodge_factorization(keep_hodge_factorization,
        SWN::parameters::report(std::ref(report))))))))))
          .verbose(verbose));
    }
    if(!ok) raise_failure(report);

    // w at corner k of face f: halfedge(f) points to the face's first vertex (mesh_from_soup())
    py::array_t<double> w_corners({py::ssize_t(nf), py::ssize_t(3)});
    auto wc = w_corners.mutable_unchecked<2>();
    for(Mesh::Face_index f : mesh_.faces())
    {
      Mesh::Halfedge_index h = mesh_.halfedge(f);
      for(int k = 0; k < 3; ++k, h = mesh_.next(h)) wc(py::ssize_t(f), k) = w[std::size_t(h)];
    }
    py::dict result;
    result["W"] = array_of(labels);
    result["w"] = w_corners;
    result["bounding"] = array_of(bounding);
    result["G"] = array_of(G);
    result["g"] = array_of(g);
    result["report"] = report_dict(report);
    return result;
  }

  py::array_t<std::int64_t> edges() const { return edge_array(mesh_); }
  py::dict report() const { return report_dict(construction_report_); }
  py::list warnings() const { return string_list(warnings_); }
  std::size_t number_of_vertices() const { return mesh_.number_of_vertices(); }
  std::size_t number_of_faces() const { return mesh_.number_of_faces(); }

private:
  // adds the polylines vertices[offsets[i]:offsets[i+1]], each `multiplicities[i]` times, to the chain
  // (SWN::add_halfedges_to_chain(), once per distinct multiplicity); ValueError naming `curves[i]` if a
  // vertex is out of range or two consecutive vertices are not joined by an edge
  void add_curves(const Index_array& vertices, const Index_array& offsets, const Index_array& multiplicities,
                  std::vector<int>& chain) const
  {
    const auto vx = vertices.unchecked<1>();
    const auto of = offsets.unchecked<1>();
    const auto mu = multiplicities.unchecked<1>();
    if(of.shape(0) != mu.shape(0) + 1 || of(0) != 0 || of(of.shape(0) - 1) != vx.shape(0))
      throw py::value_error("curves: offsets and multiplicities do not match the vertices");
    const std::int64_t nv = std::int64_t(mesh_.number_of_vertices());
    std::map<int, std::vector<Mesh::Halfedge_index>> by_multiplicity;
    for(py::ssize_t i = 0; i < mu.shape(0); ++i)
    {
      const std::string curve = "curves[" + std::to_string(i) + "]: ";
      if(mu(i) < INT_MIN / 2 || mu(i) > INT_MAX / 2)
        throw py::value_error(curve + "multiplicity " + std::to_string(mu(i)) + " is out of range");
      if(of(i + 1) < of(i)) throw py::value_error(curve + "offsets decrease");
      std::vector<Mesh::Halfedge_index>& halfedges = by_multiplicity[int(mu(i))];
      for(std::int64_t k = of(i); k < of(i + 1); ++k)
      {
        if(vx(k) < 0 || vx(k) >= nv)
          throw py::value_error(curve + "vertex index " + std::to_string(vx(k)) + " is out of range (" +
                                std::to_string(nv) + " vertices)");
        if(k == of(i)) continue;
        const auto h = CGAL::halfedge(Mesh::Vertex_index(Mesh::size_type(vx(k - 1))),
                                      Mesh::Vertex_index(Mesh::size_type(vx(k))), mesh_);
        if(!h.second)
          throw py::value_error(curve + "vertices " + std::to_string(vx(k - 1)) + " and " + std::to_string(vx(k)) +
                                " are not joined by an edge of the mesh");
        halfedges.push_back(h.first);
      }
    }
    auto chain_map = boost::make_iterator_property_map(chain.begin(), get(boost::edge_index, mesh_));
    for(const auto& [m, halfedges] : by_multiplicity)
      if(m != 0 && !halfedges.empty()) SWN::add_halfedges_to_chain(mesh_, halfedges, chain_map, m);
  }

  Mesh mesh_;
  std::vector<std::string> warnings_;
  std::unique_ptr<Library_solver> solver_;   // refers to mesh_
  SWN::Solve_report construction_report_;
  std::mutex mutex_;
};

} // namespace

void bind_solver(py::module_& m)
{
  py::class_<Solver>(m, "Solver", "The mesh (V, F) and the package's solver on it; see swn.Solver")
    .def(py::init<py::handle, py::handle>(), py::arg("V"), py::arg("F"))
    .def("_solve", &Solver::solve, py::arg("vertices"), py::arg("offsets"), py::arg("multiplicities"),
         py::arg("epsilon"), py::arg("reduced_residual"), py::arg("concurrency"),
         py::arg("keep_hodge_factorization"), py::arg("verbose"))
    .def_property_readonly("edges", &Solver::edges)
    .def_property_readonly("report", &Solver::report)
    .def_property_readonly("warnings", &Solver::warnings)
    .def_property_readonly("number_of_vertices", &Solver::number_of_vertices)
    .def_property_readonly("number_of_faces", &Solver::number_of_faces);
}

} // namespace swn_python
