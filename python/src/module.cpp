// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The module `swn._swn`: numpy arrays to and from a Surface_mesh, the exception `InputError`, and the
// registration of the solver (solver.cpp) and of the readers (readers.cpp). The Python package `swn`
// (python/swn/__init__.py) wraps it.

#include "swn_python.h"

#include <CGAL/Surface_winding_numbers/Solve_report.h>

#include <array>
#include <cstddef>
#include <string>

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

// the binding takes triangle meshes: polygons are refused with the message of the tool's readers
std::string face_size_message(std::size_t face, std::size_t n)
{
  if(n < 3) return IO::internal::face_arity_message(face, n);
  return "face " + std::to_string(face) + " has " + std::to_string(n) + " vertices: only triangle meshes are supported";
}

void add_triangles(const py::array& F, Triangle_soup& soup)
{
  if(!is_integer_array(F))
    throw py::type_error("F must hold integer vertex indices, not " + std::string(py::str(F.dtype())));
  if(F.ndim() != 2) throw py::value_error("F must be an (m, 3) array of vertex indices, not of shape " + shape_of(F));
  if(F.shape(1) != 3) throw py::value_error(face_size_message(0, std::size_t(F.shape(1))));
  const auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(F);
  const auto t = f.unchecked<2>();
  soup.triangles.resize(std::size_t(t.shape(0)));
  for(py::ssize_t j = 0; j < t.shape(0); ++j)
    for(py::ssize_t k = 0; k < 3; ++k)
    {
      if(t(j, k) < 0)
        throw py::value_error("face " + std::to_string(j) + " refers to vertex " + std::to_string(t(j, k)) + " (a negative index)");
      soup.triangles[std::size_t(j)][std::size_t(k)] = std::size_t(t(j, k));
    }
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
  const auto vd = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v).unchecked<2>();
  soup.points.resize(std::size_t(vd.shape(0)));
  for(py::ssize_t i = 0; i < vd.shape(0); ++i)
  {
    std::array<double, 3>& p = soup.points[std::size_t(i)];
    p = {vd(i, 0), vd(i, 1), vd(i, 2)};
    try
    {
      IO::internal::check_finite_point(p, "", 0, std::size_t(i));
    }
    catch(const IO::Input_error& e)
    {
      throw py::value_error(e.reason);
    }
  }

  if(py::isinstance<py::array>(F)) add_triangles(py::reinterpret_borrow<py::array>(F), soup);
  else
  {
    // a sequence of polygons: one integer array if all are triangles, else one polygon at a time
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
    if(f && a.ndim() == 2 && a.shape(1) == 3 && is_integer_array(a)) add_triangles(a, soup);
    else if(f && a.size() == 0) {}   // no face: refused by mesh_from_soup()
    else
    {
      std::size_t j = 0;
      for(py::handle polygon : F)
      {
        if(!PySequence_Check(polygon.ptr()))
          throw py::type_error("face " + std::to_string(j) + " is not a sequence of vertex indices");
        const py::sequence s = py::reinterpret_borrow<py::sequence>(polygon);
        if(s.size() != 3) throw py::value_error(face_size_message(j, s.size()));
        soup.triangles.push_back({face_vertex(s[0], j), face_vertex(s[1], j), face_vertex(s[2], j)});
        ++j;
      }
    }
  }
  soup.point_lines.assign(soup.points.size(), 0);
  soup.triangle_lines.assign(soup.triangles.size(), 0);
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

  swn_python::bind_solver(m);
  swn_python::bind_readers(m);
}
