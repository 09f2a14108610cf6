// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The module `swn._swn`: numpy arrays to and from a soup and a Surface_mesh, the report as a dict, the
// exception `InputError`, `_winding_numbers()` (a triangle mesh to solver.cpp, anything else to soup.cpp as
// a polygon soup), and the registration of the solver (solver.cpp), the readers (readers.cpp), the curves
// off the mesh (curves.cpp) and the selection cleanup (selection.cpp). The Python package `swn`
// (python/swn/__init__.py) wraps it.

#include "swn_python.h"

#include "swn_io/solver_choice.h"

#include <CGAL/Surface_winding_numbers/Solve_report.h>

#include <stdexcept>

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace swn_python {

namespace IO = CGAL::Surface_winding_numbers::IO;

namespace {

std::string shape_of(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

bool is_integer_array(const py::array& a) { return a.dtype().kind() == 'i' || a.dtype().kind() == 'u'; }

// the vertex index `x` of face `f` (any Python integer, numpy's included; floats refused)
std::size_t face_vertex(py::handle x, std::size_t f)
{
  PyObject* i = PyNumber_Index(x.ptr());
  if(!i) throw py::error_already_set();
  const long long v = PyLong_AsLongLong(i);
  Py_DECREF(i);
  if(v == -1 && PyErr_Occurred()) throw py::error_already_set();
  if(v < 0) throw py::value_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " (a negative index)");
  return static_cast<std::size_t>(v);
}

// Calls f(T()) with the element type of `a` among the types read in place (`Types...`), or returns false.
// Any memory order and stride is read as it is: numpy arrays of these types are not copied.
template <class... Types, class F>
bool visit_dtype(const py::array& a, F f)
{
  return ((py::isinstance<py::array_t<Types>>(a) ? (f(Types()), true) : false) || ...);
}

// the polygons of the integer array F (m x k, k >= 3): triangles (k = 3) or polygons
void add_faces(const py::array& F, Triangle_soup& soup)
{
  if(!is_integer_array(F))
    throw py::type_error("F must hold integer vertex indices, not " + std::string(py::str(F.dtype())));
  if(F.ndim() != 2) throw py::value_error("F must be an (m, k) array of vertex indices, not of shape " + shape_of(F));
  const std::size_t m = std::size_t(F.shape(0)), k = std::size_t(F.shape(1));
  if(k < 3 && m > 0) throw py::value_error(IO::internal::face_arity_message(0, k));
  auto read = [&](auto t, const py::array& array) {
    typedef decltype(t) T;
    const auto a = array.unchecked<T, 2>();
    std::vector<std::size_t> face(k);
    for(std::size_t j = 0; j < m; ++j)
    {
      for(std::size_t c = 0; c < k; ++c)
      {
        const T v = a(py::ssize_t(j), py::ssize_t(c));
        if constexpr(std::is_signed<T>::value)
          if(v < 0) throw py::value_error("face " + std::to_string(j) + " refers to vertex " + std::to_string(v) + " (a negative index)");
        face[c] = std::size_t(v);
      }
      if(k == 3) soup.triangles.push_back({face[0], face[1], face[2]});
      else soup.polygons.push_back(face);
    }
  };
  if(!visit_dtype<std::int64_t, std::int32_t, std::uint32_t, std::uint64_t>(F, [&](auto t) { read(t, F); }))
    read(std::int64_t(), py::array_t<std::int64_t, py::array::forcecast>::ensure(F));
}

} // namespace

Triangle_soup soup_from_arrays(py::handle V, py::handle F)
{
  Triangle_soup soup;
  const py::module_ np = py::module_::import("numpy");
  const py::array v = np.attr("asarray")(V);
  if(v.dtype().kind() != 'f' && !is_integer_array(v))
    throw py::type_error("V must hold real coordinates, not " + std::string(py::str(v.dtype())));
  if(v.ndim() != 2 || v.shape(1) != 3)
    throw py::value_error("V must be an (n, 3) array of vertex coordinates, not of shape " + shape_of(v));
  soup.points.resize(std::size_t(v.shape(0)));
  auto read_points = [&](auto t, const py::array& array) {
    const auto a = array.unchecked<decltype(t), 2>();
    for(py::ssize_t i = 0; i < a.shape(0); ++i)
    {
      std::array<double, 3>& p = soup.points[std::size_t(i)];
      p = {double(a(i, 0)), double(a(i, 1)), double(a(i, 2))};
      try
      {
        IO::internal::check_finite_point(p, "", 0, std::size_t(i));
      }
      catch(const IO::Input_error& e)
      {
        throw py::value_error(e.reason);
      }
    }
  };
  if(!visit_dtype<double, float>(v, [&](auto t) { read_points(t, v); }))
    read_points(double(), py::array_t<double, py::array::forcecast>::ensure(v));

  if(py::isinstance<py::array>(F)) add_faces(py::reinterpret_borrow<py::array>(F), soup);
  else
  {
    // a sequence of polygons: one integer array if all have the same size, else one polygon at a time
    py::object f;
    try
    {
      f = np.attr("asarray")(F);
    }
    catch(const py::error_already_set&)
    {
      // ragged: numpy refuses it
    }
    const py::array a = f ? py::array(f) : py::array();
    if(f && a.ndim() == 2 && a.shape(1) >= 3 && is_integer_array(a)) add_faces(a, soup);
    else if(f && a.size() == 0) {}   // no face: refused later
    else
    {
      std::size_t j = 0;
      std::vector<std::size_t> face;
      for(py::handle polygon : F)
      {
        if(!PySequence_Check(polygon.ptr()))
          throw py::type_error("face " + std::to_string(j) + " is not a sequence of vertex indices");
        const py::sequence s = py::reinterpret_borrow<py::sequence>(polygon);
        if(s.size() < 3) throw py::value_error(IO::internal::face_arity_message(j, s.size()));
        face.clear();
        for(py::handle x : s) face.push_back(face_vertex(x, j));
        IO::add_face(soup, face, 0);
        ++j;
      }
    }
  }
  soup.point_lines.assign(soup.points.size(), 0);
  soup.triangle_lines.assign(IO::number_of_faces(soup), 0);
  return soup;
}

void mesh_from_soup(const Triangle_soup& soup, Mesh& mesh, std::vector<std::string>& warnings)
{
  IO::Mesh_read_info info;
  try
  {
    IO::triangle_soup_to_mesh(soup, mesh, info, "");
  }
  catch(const IO::Input_error& e)
  {
    throw py::value_error(e.reason);
  }
  warnings = info.warnings;
}

void mesh_from_arrays(py::handle V, py::handle F, Mesh& mesh, std::vector<std::string>& warnings)
{
  const Triangle_soup soup = soup_from_arrays(V, F);
  py::gil_scoped_release release;
  mesh_from_soup(soup, mesh, warnings);
}

py::array_t<double> vertex_array(const Mesh& mesh)
{
  py::array_t<double> V({py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3)});
  auto v = V.mutable_unchecked<2>();
  for(Mesh::Vertex_index x : mesh.vertices())
  {
    const K::Point_3& p = mesh.point(x);
    for(int k = 0; k < 3; ++k) v(py::ssize_t(x), k) = p[k];
  }
  return V;
}

py::array_t<std::int64_t> face_array(const Mesh& mesh)
{
  py::array_t<std::int64_t> F({py::ssize_t(mesh.number_of_faces()), py::ssize_t(3)});
  auto t = F.mutable_unchecked<2>();
  for(Mesh::Face_index f : mesh.faces())
  {
    Mesh::Halfedge_index h = mesh.halfedge(f);
    for(int k = 0; k < 3; ++k, h = mesh.next(h)) t(py::ssize_t(f), k) = std::int64_t(mesh.target(h));
  }
  return F;
}

py::array_t<std::int64_t> edge_array(const Mesh& mesh)
{
  py::array_t<std::int64_t> E({py::ssize_t(mesh.number_of_edges()), py::ssize_t(2)});
  auto t = E.mutable_unchecked<2>();
  for(Mesh::Edge_index e : mesh.edges())
  {
    const Mesh::Halfedge_index h = mesh.halfedge(e);
    t(py::ssize_t(e), 0) = std::int64_t(mesh.source(h));
    t(py::ssize_t(e), 1) = std::int64_t(mesh.target(h));
  }
  return E;
}

py::dict report_dict(const CGAL::Surface_winding_numbers::Solve_report& r)
{
  py::dict d, times;
#define SWN_REPORT(F) d[#F] = r.F;
  SWN_REPORT(success) SWN_REPORT(error) SWN_REPORT(invalid_input)
  SWN_REPORT(vertices) SWN_REPORT(edges) SWN_REPORT(faces) SWN_REPORT(components)
  SWN_REPORT(border_edges) SWN_REPORT(border_loops) SWN_REPORT(genus)
  SWN_REPORT(euler_characteristic) SWN_REPORT(orientable)
  SWN_REPORT(nonmanifold_vertices) SWN_REPORT(nonmanifold_edges) SWN_REPORT(nonorientable_edges)
  SWN_REPORT(curve_edges) SWN_REPORT(interior_endpoints) SWN_REPORT(dropped_curve_edges) SWN_REPORT(inconsistent_curve_vertices)
  SWN_REPORT(homology_correction) SWN_REPORT(hodge_projection) SWN_REPORT(reduced_residual) SWN_REPORT(lp_ran)
  SWN_REPORT(jump_laplacian_reused) SWN_REPORT(jump_laplacian_update_rank) SWN_REPORT(residual_warm_started) SWN_REPORT(lp_variables) SWN_REPORT(lp_rows) SWN_REPORT(lp_objective)
  SWN_REPORT(degenerate_weights) SWN_REPORT(min_label) SWN_REPORT(max_label) SWN_REPORT(nonbounding_closing_units)
#undef SWN_REPORT
#define SWN_TIME(F) times[#F] = r.time_##F;
  SWN_TIME(setup) SWN_TIME(jump_laplace) SWN_TIME(hodge) SWN_TIME(residual) SWN_TIME(second_solve)
  SWN_TIME(labels) SWN_TIME(total) SWN_TIME(mesh) SWN_TIME(output_maps)
#undef SWN_TIME
  d["times"] = times;
  return d;
}

void raise_failure(const CGAL::Surface_winding_numbers::Solve_report& r)
{
  if(r.invalid_input) throw py::value_error(r.error);
  throw std::runtime_error(r.error);
}

Solve_options solve_options(const py::dict& d)
{
  Solve_options o;
  o.epsilon = d["epsilon"].cast<double>();
  o.lp_solver = d["lp_solver"].cast<std::string>();
  o.linear_solver = d["linear_solver"].cast<std::string>();
  o.reduced_residual = d["reduced_residual"].cast<bool>();
  o.filter_nonbounding_loops = d["filter_nonbounding_loops"].cast<bool>();
  o.completed_homology_class = d["completed_homology_class"].cast<bool>();
  o.concurrency = d["concurrency"].cast<bool>();
  o.verbose = d["verbose"].cast<bool>();
  o.anchor_face = d["anchor_face"].cast<std::int64_t>();
  o.confidence = d["confidence"].cast<bool>();
  return o;
}

py::tuple chain_halfedges(const Mesh& mesh, const std::vector<int>& chain)
{
  std::vector<std::pair<Mesh::Halfedge_index, int>> curve;
  for(Mesh::Edge_index e : mesh.edges())
    if(const int c = chain[std::size_t(e)])
      curve.emplace_back(c > 0 ? mesh.halfedge(e) : mesh.opposite(mesh.halfedge(e)), c > 0 ? c : -c);
  py::array_t<std::int64_t> halfedges({py::ssize_t(curve.size()), py::ssize_t(2)});
  py::array_t<std::int64_t> multiplicities(py::ssize_t(curve.size()));
  auto h = halfedges.mutable_unchecked<2>();
  auto m = multiplicities.mutable_unchecked<1>();
  for(std::size_t k = 0; k < curve.size(); ++k)
  {
    h(py::ssize_t(k), 0) = std::int64_t(mesh.source(curve[k].first));
    h(py::ssize_t(k), 1) = std::int64_t(mesh.target(curve[k].first));
    m(py::ssize_t(k)) = curve[k].second;
  }
  return py::make_tuple(halfedges, multiplicities);
}

py::list string_list(const std::vector<std::string>& strings)
{
  py::list l;
  for(const std::string& s : strings) l.append(s);
  return l;
}

} // namespace swn_python

PYBIND11_MODULE(_swn, m)
{
  namespace py = pybind11;
  namespace IO = CGAL::Surface_winding_numbers::IO;
  m.doc() = "Surface winding numbers (Feng, Gillespie and Crane 2023): the compiled part of the package swn";
  m.attr("__version__") = SWN_PYTHON_VERSION;

  // InputError(ValueError): the tool's readers' Input_error, with its file, line (None if not on a line)
  // and reason. The type lives as long as the process (the reference is never given back).
  static PyObject* input_error = py::exception<IO::Input_error>(m, "InputError", PyExc_ValueError).release().ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const IO::Input_error& e)
    {
      py::object error = py::reinterpret_borrow<py::object>(input_error)(e.what());
      error.attr("file") = e.file;
      error.attr("line") = e.line ? py::object(py::int_(e.line)) : py::object(py::none());
      error.attr("reason") = e.reason;
      PyErr_SetObject(input_error, error.ptr());
    }
  });

  m.attr("lp_solvers") = swn_python::string_list(IO::lp_solver_names());
  m.attr("linear_solvers") = swn_python::string_list(IO::linear_solver_names());
  // one solve of curves (and dual chains) on (V, F): as a triangle mesh when it is an oriented 2-manifold
  // triangle mesh, no dual chain is given and `soup` is false, else as a polygon soup. `polygon_soup` in the
  // result says why it was solved as a soup ("" for a mesh); `warnings` are the input's.
  m.def("_winding_numbers", [](py::handle V, py::handle F, const swn_python::Index_array& vertices,
                               const swn_python::Index_array& offsets, const swn_python::Index_array& multiplicities,
                               const swn_python::Index_array& dual_pairs, bool soup, const py::dict& options) {
    const swn_python::Curve_arrays curves{vertices, offsets, multiplicities};
    const swn_python::Solve_options o = swn_python::solve_options(options);
    const IO::Triangle_soup input = swn_python::soup_from_arrays(V, F);
    swn_python::Mesh mesh;
    IO::Mesh_read_info info;
    std::string why;
    try
    {
      py::gil_scoped_release release;
      why = IO::soup_to_mesh_or_problem(input, mesh, info, "", o.concurrency);
    }
    catch(const IO::Input_error& e)
    {
      throw py::value_error(e.reason);
    }
    if(why.empty() && dual_pairs.size() > 0) why = "dual chains are given";
    if(why.empty() && soup) why = "soup=True";
    py::dict result;
    if(why.empty())
    {
      result = swn_python::solve_on_mesh(mesh, curves, o);
      result["warnings"] = swn_python::string_list(info.warnings);
    }
    else
    {
      mesh.clear();
      result = swn_python::solve_on_soup(input, curves, dual_pairs, o);
      py::list warnings = swn_python::string_list(info.warnings);
      for(py::handle w : py::list(result["warnings"])) warnings.append(w);
      result["warnings"] = warnings;
    }
    result["polygon_soup"] = why;
    return result;
  }, py::arg("V"), py::arg("F"), py::arg("vertices"), py::arg("offsets"), py::arg("multiplicities"),
     py::arg("dual_pairs"), py::arg("soup"), py::arg("options"));

  swn_python::bind_solver(m);
  swn_python::bind_readers(m);
  swn_python::bind_curves(m);
  swn_python::bind_selection(m);
}
