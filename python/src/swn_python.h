// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The Python module `swn._swn`: what its three source files share. module.cpp converts between numpy
// arrays and a Surface_mesh and registers the exceptions, solver.cpp binds the solver, readers.cpp the
// tool's mesh and curve readers and its conforming cut.

#ifndef SWN_PYTHON_H
#define SWN_PYTHON_H

#include "swn_io/mesh_soup.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

namespace swn_python {

namespace py = pybind11;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Surface_winding_numbers::IO::Triangle_soup Triangle_soup;

/// The soup of the arrays `V` (n x 3 numbers) and `F` (m x 3 integers, or a sequence of m polygons of
/// vertex indices): needs the GIL. Throws `TypeError` / `ValueError` on arrays of the wrong kind or shape,
/// a face that is not a triangle, a negative index or a non-finite coordinate.
Triangle_soup soup_from_arrays(py::handle V, py::handle F);

/// The mesh of a soup: vertex `i` is `soup.points[i]`, face `j` is `soup.triangles[j]`, and `halfedge(j)`
/// points to its first vertex (the tool's `triangle_soup_to_mesh()`, which checks the soup). Runs without
/// the GIL. Throws `ValueError` with the reader's message (an index out of range, a repeated vertex, a
/// nonmanifold edge or vertex, inconsistent orientation, no face); `warnings` gets its warnings.
void mesh_from_soup(const Triangle_soup& soup, Mesh& mesh, std::vector<std::string>& warnings);

/// n x 3 float64: the points of the vertices, by index
py::array_t<double> vertex_array(const Mesh& mesh);
/// m x 3 int64: the vertices of every face, from `target(halfedge(f))` on (the file's order for a mesh read by
/// the tool's readers or built by `mesh_from_soup()`)
py::array_t<std::int64_t> face_array(const Mesh& mesh);
/// E x 2 int64: source and target of the reference halfedge `halfedge(e)` of every edge, by edge index
py::array_t<std::int64_t> edge_array(const Mesh& mesh);
/// a Python list of str
py::list string_list(const std::vector<std::string>& strings);

/// `Solver` (solver.cpp)
void bind_solver(py::module_& m);
/// `read_mesh`, `read_curve`, `load` (readers.cpp)
void bind_readers(py::module_& m);

} // namespace swn_python

#endif
