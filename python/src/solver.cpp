// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// `swn._swn.Solver`: a Surface_mesh built from (V, F) and the package's Surface_winding_numbers_solver on
// it, with the sparse solver chosen by name; `_solve()` takes curves as vertex polylines (flattened, with
// offsets and one multiplicity each) and the settings, and returns the outputs as numpy arrays, in the
// order of the input's faces and of the mesh's edges, and the per-region confidence when asked.
// `solve_on_mesh()` is the same for one solve.

#include "swn_python.h"

#include "swn_io/solver_choice.h"

#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/Label_confidence.h>

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
namespace IO = CGAL::Surface_winding_numbers::IO;

namespace {

// the per-face, per-corner and per-edge outputs of a solve on a Surface_mesh, and the confidence when asked
struct Mesh_outputs
{
  std::vector<int> labels, G, bounding, second_best;
  std::vector<double> g, w, face_cost;
  std::vector<std::size_t> region;
  SWN::Label_confidence confidence;
  SWN::Solve_report report;
};

// the library's solver on a mesh, with the sparse solver fixed at construction and the residual solver
// chosen at each solve
class Mesh_solver
{
public:
  virtual ~Mesh_solver() = default;
  virtual bool is_valid() const = 0;
  virtual const SWN::Solve_report& report() const = 0;
  virtual bool solve(const std::vector<int>& chain, const Solve_options& o, bool keep, Mesh_outputs& out) = 0;
};

template <class SparseSolver>
class Mesh_solver_of : public Mesh_solver
{
public:
  explicit Mesh_solver_of(const Mesh& mesh) : mesh_(mesh), solver_(mesh) {}
  bool is_valid() const override { return solver_.is_valid(); }
  const SWN::Solve_report& report() const override { return solver_.report(); }
  bool solve(const std::vector<int>& chain, const Solve_options& o, bool keep, Mesh_outputs& out) override
  {
    const auto ei = get(boost::edge_index, mesh_);
    const auto fi = get(boost::face_index, mesh_);
    auto edge_map = [&](auto& v) { return boost::make_iterator_property_map(v.begin(), ei); };
    const Mesh::Face_index anchor = o.anchor_face < 0 ? Mesh::null_face() : Mesh::Face_index(Mesh::size_type(o.anchor_face));
    // tail: the innermost named parameters (the report, and the residual solver when not the default)
    const auto run = [&](const auto& tail) {
      const auto np =
        SWN::parameters::nonbounding_chain_map(edge_map(out.G),
        SWN::parameters::nonbounding_chain_real_map(edge_map(out.g),
        SWN::parameters::bounding_chain_map(edge_map(out.bounding),
        SWN::parameters::winding_number_map(boost::make_iterator_property_map(out.w.begin(), get(boost::halfedge_index, mesh_)),
        SWN::parameters::epsilon(o.epsilon,
        SWN::parameters::use_reduced_residual(o.reduced_residual,
        SWN::parameters::completed_homology_class(o.completed_homology_class,
        SWN::parameters::filter_nonbounding_loops(o.filter_nonbounding_loops,
        SWN::parameters::label_anchor_face(anchor,
        SWN::parameters::concurrency(o.concurrency,
        SWN::parameters::keep_hodge_factorization(keep, tail))))))))))).verbose(o.verbose);
      const auto labels = boost::make_iterator_property_map(out.labels.begin(), fi);
      if(!o.confidence) return solver_.solve(boost::make_iterator_property_map(chain.begin(), ei), labels, np);
      // the confidence outputs (computed only when asked: a second instantiation of the solve)
      return solver_.solve(boost::make_iterator_property_map(chain.begin(), ei), labels,
                           SWN::parameters::label_confidence(std::ref(out.confidence),
                           SWN::parameters::confidence_map(boost::make_iterator_property_map(out.face_cost.begin(), fi),
                           SWN::parameters::region_map(boost::make_iterator_property_map(out.region.begin(), fi),
                           SWN::parameters::second_best_label_map(boost::make_iterator_property_map(out.second_best.begin(), fi), np)))));
    };
    const auto report = SWN::parameters::report(std::ref(out.report));
#ifdef CGAL_SWN_USE_LEMON
    // the default residual solver: the one the solver keeps between solves (each re-solve starts from the last answer)
    if(o.lp_solver == "lemon") return run(report);
#endif
    return IO::with_lp_solver(o.lp_solver, [&](auto& lp) { return run(SWN::parameters::lp_solver(std::ref(lp), report)); });
  }

private:
  const Mesh& mesh_;
  SWN::Surface_winding_numbers_solver<Mesh, SparseSolver> solver_;
};

// the library's solver on `mesh` with the sparse solver `name` (runs without the GIL)
std::unique_ptr<Mesh_solver> make_mesh_solver(const Mesh& mesh, const std::string& name)
{
  return IO::with_linear_solver(name, [&](auto sparse_solver) -> std::unique_ptr<Mesh_solver> {
    return std::make_unique<Mesh_solver_of<decltype(sparse_solver)>>(mesh);
  });
}

// adds the polylines vertices[offsets[i]:offsets[i+1]], each `multiplicities[i]` times, to the chain
// (SWN::add_halfedges_to_chain(), once per distinct multiplicity); ValueError naming `curves[i]` if a
// vertex is out of range or two consecutive vertices are not joined by an edge
void add_curves(const Mesh& mesh, const Curve_arrays& curves, std::vector<int>& chain)
{
  const auto vx = curves.vertices.unchecked<1>();
  const auto of = curves.offsets.unchecked<1>();
  const auto mu = curves.multiplicities.unchecked<1>();
  if(of.shape(0) != mu.shape(0) + 1 || of(0) != 0 || of(of.shape(0) - 1) != vx.shape(0))
    throw py::value_error("curves: offsets and multiplicities do not match the vertices");
  const std::int64_t nv = std::int64_t(mesh.number_of_vertices());
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
                                    Mesh::Vertex_index(Mesh::size_type(vx(k))), mesh);
      if(!h.second)
        throw py::value_error(curve + "vertices " + std::to_string(vx(k - 1)) + " and " + std::to_string(vx(k)) +
                              " are not joined by an edge of the mesh");
      halfedges.push_back(h.first);
    }
  }
  auto chain_map = boost::make_iterator_property_map(chain.begin(), get(boost::edge_index, mesh));
  for(const auto& [m, halfedges] : by_multiplicity)
    if(m != 0 && !halfedges.empty()) SWN::add_halfedges_to_chain(mesh, halfedges, chain_map, m);
}

// one solve of the curves on `mesh` by `solver`, its outputs as numpy arrays (W per face, w per corner,
// the chains per edge) and the report
py::dict solve(Mesh_solver& solver, const Mesh& mesh, const Curve_arrays& curves, const Solve_options& options,
               bool keep, std::mutex* mutex)
{
  const std::size_t nf = mesh.number_of_faces(), ne = mesh.number_of_edges();
  std::vector<int> chain(ne, 0);
  add_curves(mesh, curves, chain);
  Mesh_outputs out;
  out.labels.assign(nf, 0);
  out.G.assign(ne, 0);
  out.bounding.assign(ne, 0);
  out.g.assign(ne, 0.);
  out.w.assign(mesh.number_of_halfedges(), std::numeric_limits<double>::quiet_NaN());
  if(options.confidence)
  {
    out.second_best.assign(nf, 0);
    out.face_cost.assign(nf, 0.);
    out.region.assign(nf, 0);
  }
  bool ok = false;
  {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lock;   // one solve at a time on a solver
    if(mutex) lock = std::unique_lock<std::mutex>(*mutex);
    ok = solver.solve(chain, options, keep, out);
  }
  if(!ok) raise_failure(out.report);

  // w at corner k of face f: halfedge(f) points to the face's first vertex (build_oriented_mesh())
  py::array_t<double> w_corners({py::ssize_t(nf), py::ssize_t(3)});
  auto wc = w_corners.mutable_unchecked<2>();
  for(Mesh::Face_index f : mesh.faces())
  {
    Mesh::Halfedge_index h = mesh.halfedge(f);
    for(int k = 0; k < 3; ++k, h = mesh.next(h)) wc(py::ssize_t(f), k) = out.w[std::size_t(h)];
  }
  py::dict result;
  result["W"] = array_of(out.labels);
  result["w"] = w_corners;
  result["bounding"] = array_of(out.bounding);
  result["G"] = array_of(out.G);
  result["g"] = array_of(out.g);
  result["report"] = report_dict(out.report);
  if(options.confidence) result["confidence"] = confidence_dict(out.confidence, out.face_cost, out.region, out.second_best);
  return result;
}

class Solver
{
public:
  Solver(py::handle V, py::handle F, const std::string& linear_solver)
  {
    const Triangle_soup soup = soup_from_arrays(V, F);
    {
      py::gil_scoped_release release;
      mesh_from_soup(soup, mesh_, warnings_);
      solver_ = make_mesh_solver(mesh_, linear_solver);
    }
    if(!solver_->is_valid()) raise_failure(solver_->report());
    construction_report_ = solver_->report();
  }

  py::dict solve(const Index_array& vertices, const Index_array& offsets, const Index_array& multiplicities,
                 const py::dict& options)
  {
    return swn_python::solve(*solver_, mesh_, Curve_arrays{vertices, offsets, multiplicities}, solve_options(options),
                             true, &mutex_);
  }

  py::array_t<std::int64_t> edges() const { return edge_array(mesh_); }
  py::dict report() const { return report_dict(construction_report_); }
  py::list warnings() const { return string_list(warnings_); }
  std::size_t number_of_vertices() const { return mesh_.number_of_vertices(); }
  std::size_t number_of_faces() const { return mesh_.number_of_faces(); }

private:
  Mesh mesh_;
  std::vector<std::string> warnings_;
  std::unique_ptr<Mesh_solver> solver_;   // refers to mesh_
  SWN::Solve_report construction_report_;
  std::mutex mutex_;
};

} // namespace

py::dict confidence_dict(const SWN::Label_confidence& c, const std::vector<double>& face_cost,
                         const std::vector<std::size_t>& region, const std::vector<int>& second_best)
{
  py::list regions;
  for(const SWN::Label_region& r : c.regions)
  {
    py::dict d;
    d["label"] = r.label;
    d["faces"] = r.faces;
    d["area"] = r.area;
    d["component"] = r.component;
    d["flip_cost"] = r.flip_cost;
    d["flip_delta"] = r.flip_delta;
    d["boundary_length"] = r.boundary_length;
    d["largest_in_component"] = r.largest_in_component;
    regions.append(d);
  }
  py::dict d;
  d["face_cost"] = array_of(face_cost);
  d["region"] = array_of(std::vector<std::int64_t>(region.begin(), region.end()));
  d["regions"] = regions;
  d["second_best_W"] = array_of(second_best);
  d["second_best_region"] = c.second_best_region == std::size_t(-1) ? py::object(py::none()) : py::object(py::int_(c.second_best_region));
  d["second_best_cost"] = c.second_best_cost;
  return d;
}

py::dict solve_on_mesh(const Mesh& mesh, const Curve_arrays& curves, const Solve_options& options)
{
  std::unique_ptr<Mesh_solver> solver;
  {
    py::gil_scoped_release release;
    solver = make_mesh_solver(mesh, options.linear_solver);
  }
  if(!solver->is_valid()) raise_failure(solver->report());
  // one solve: the Hodge step's per-mesh part is freed before the residual step (lower peak memory)
  py::dict result = solve(*solver, mesh, curves, options, false, nullptr);
  result["edges"] = edge_array(mesh);
  return result;
}

void bind_solver(py::module_& m)
{
  py::class_<Solver>(m, "Solver", "The mesh (V, F) and the package's solver on it; see swn.Solver")
    .def(py::init<py::handle, py::handle, const std::string&>(), py::arg("V"), py::arg("F"), py::arg("linear_solver"))
    .def("_solve", &Solver::solve, py::arg("vertices"), py::arg("offsets"), py::arg("multiplicities"), py::arg("options"))
    .def_property_readonly("edges", &Solver::edges)
    .def_property_readonly("report", &Solver::report)
    .def_property_readonly("warnings", &Solver::warnings)
    .def_property_readonly("number_of_vertices", &Solver::number_of_vertices)
    .def_property_readonly("number_of_faces", &Solver::number_of_faces);
}

} // namespace swn_python
