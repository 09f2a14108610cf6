// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The Python module `swn._swn`: what its source files share. module.cpp converts between numpy arrays,
// soups and a Surface_mesh, registers the exceptions and binds `_winding_numbers()` (either route),
// solver.cpp binds the solver on a triangle mesh, soup.cpp solves polygon soups, readers.cpp binds the
// tool's mesh and curve readers and its conforming cut, curves.cpp the library's curves off the mesh,
// selection.cpp its selection cleanup.

#ifndef SWN_PYTHON_H
#define SWN_PYTHON_H

#include "swn_io/mesh_soup.h"

#include <CGAL/Surface_winding_numbers/Label_confidence.h>
#include <CGAL/Surface_winding_numbers/Solve_report.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace swn_python {

namespace py = pybind11;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Surface_winding_numbers::IO::Triangle_soup Triangle_soup;

typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

/// The soup of the arrays `V` (n x 3 numbers) and `F` (m x k integers, k >= 3, or a sequence of m polygons
/// of vertex indices): needs the GIL. Arrays of float32/float64 coordinates and of int32/int64/uint32/uint64
/// indices are read in place, in any memory order. Throws `TypeError` / `ValueError` on arrays of the wrong
/// kind or shape, a face of fewer than three vertices, a negative index or a non-finite coordinate.
Triangle_soup soup_from_arrays(py::handle V, py::handle F);

/// The mesh of a soup: vertex `i` is `soup.points[i]`, face `j` is `soup.triangles[j]`, and `halfedge(j)`
/// points to its first vertex (the tool's `triangle_soup_to_mesh()`, which checks the soup). Runs without
/// the GIL. Throws `ValueError` with the reader's message (an index out of range, a repeated vertex, a
/// nonmanifold edge or vertex, inconsistent orientation, no face); `warnings` gets its warnings.
void mesh_from_soup(const Triangle_soup& soup, Mesh& mesh, std::vector<std::string>& warnings);

/// the mesh of the arrays `V` and `F` (soup_from_arrays() then, without the GIL, mesh_from_soup())
void mesh_from_arrays(py::handle V, py::handle F, Mesh& mesh, std::vector<std::string>& warnings);

/// n x 3 float64: the points of the vertices, by index
py::array_t<double> vertex_array(const Mesh& mesh);
/// m x 3 int64: the vertices of every face, from `target(halfedge(f))` on (the file's order for a mesh read by
/// the tool's readers or built by `mesh_from_soup()`)
py::array_t<std::int64_t> face_array(const Mesh& mesh);
/// E x 2 int64: source and target of the reference halfedge `halfedge(e)` of every edge, by edge index
py::array_t<std::int64_t> edge_array(const Mesh& mesh);
/// a Python list of str
py::list string_list(const std::vector<std::string>& strings);
/// the chain `chain[e]` on the edges `e` of `mesh` (by edge index, signed along `halfedge(e)`) as halfedges
/// (k x 2 int64 vertex pairs, along the curve) and their multiplicities (k int64, positive), in edge order
py::tuple chain_halfedges(const Mesh& mesh, const std::vector<int>& chain);

/// the settings of a solve (validated by swn/__init__.py): the library's named parameters, and the
/// residual and sparse solvers by the names of `IO::lp_solver_names()` and `IO::linear_solver_names()`
struct Solve_options
{
  double epsilon = 0.01;
  std::string lp_solver, linear_solver;
  bool reduced_residual = false, filter_nonbounding_loops = true, concurrency = true, verbose = false;
  /// the residual problem on the class of the curve completed by shortest paths (named parameter completed_homology_class)
  bool completed_homology_class = false;
  /// the face whose label is 0 in its component (named parameter label_anchor_face); -1: none
  std::int64_t anchor_face = -1;
  /// compute the per-region confidence (named parameters label_confidence, region_map, ...)
  bool confidence = false;
};
/// the options of the dict `d` (keys: the fields' names)
Solve_options solve_options(const py::dict& d);

/// the curves given as vertex polylines `vertices[offsets[i]:offsets[i+1]]`, each `multiplicities[i]` times
struct Curve_arrays
{
  Index_array vertices, offsets, multiplicities;
};

/// the report as a dict, its fields under their C++ names, the timings (time_X) in a dict `times`
py::dict report_dict(const CGAL::Surface_winding_numbers::Solve_report& r);
/// the confidence outputs as a dict (the fields of swn.LabelConfidence): per face or polygon, the flip cost of
/// its region, its region and its second-best label; per region, its `Label_region`
py::dict confidence_dict(const CGAL::Surface_winding_numbers::Label_confidence& c, const std::vector<double>& face_cost,
                         const std::vector<std::size_t>& region, const std::vector<int>& second_best);
/// the library's failure as a Python exception with its message: ValueError for bad input, RuntimeError
/// for a failed solver step
[[noreturn]] void raise_failure(const CGAL::Surface_winding_numbers::Solve_report& r);

/// a 1D numpy array of `values`
template <class T>
py::array_t<T> array_of(const std::vector<T>& values)
{
  py::array_t<T> a(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

/// a one-shot solve on the triangle mesh `mesh` (solver.cpp): the dict of `Solver._solve()`, with `edges`
py::dict solve_on_mesh(const Mesh& mesh, const Curve_arrays& curves, const Solve_options& options);
/// a solve on the polygon soup (soup.cpp): labels per polygon, w per corner, the chains on the soup's edges
/// (their order: first appearance, faces and their sides in order, oriented as in the first face), with
/// `edges` and `warnings`
py::dict solve_on_soup(const Triangle_soup& soup, const Curve_arrays& curves, const Index_array& dual_pairs,
                       const Solve_options& options);

/// `Solver` (solver.cpp)
void bind_solver(py::module_& m);
/// `read_mesh`, `read_curve`, `load` (readers.cpp)
void bind_readers(py::module_& m);
/// `_polylines_to_chain`, `_stamp_polylines` (curves.cpp)
void bind_curves(py::module_& m);
/// `_clean_face_selection`, `_clean_edge_selection` (selection.cpp)
void bind_selection(py::module_& m);

} // namespace swn_python

#endif
