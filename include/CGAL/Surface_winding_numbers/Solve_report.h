// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_SOLVE_REPORT_H
#define CGAL_SURFACE_WINDING_NUMBERS_SOLVE_REPORT_H

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Surface_winding_numbers {

/// \ingroup PkgSurfaceWindingNumbersRef
/// Exception thrown inside the package when the input cannot be processed (face with a repeated vertex,
/// chain on a border edge, non-finite coordinates, degenerate face, ...). The functions returning
/// `bool` catch it and copy its message to `Solve_report::error`.
struct Invalid_input : std::runtime_error
{
  /// builds the exception; `what()` returns `what`
  explicit Invalid_input(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSurfaceWindingNumbersRef
/// Exception thrown inside the package when a numerical step fails (factorization, linear program).
struct Solver_failure : std::runtime_error
{
  /// builds the exception; `what()` returns `what`
  explicit Solver_failure(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSurfaceWindingNumbersRef
/// Outcome of a linear program solve, as reported by a model of `SurfaceWindingNumbersLPTraits`.
enum class LP_status { OPTIMAL, INFEASIBLE, UNBOUNDED, FAILED };

/// \ingroup PkgSurfaceWindingNumbersRef
/// What a solve did: filled by `Surface_winding_numbers_solver::solve()` and, through the named
/// parameter `report`, by `CGAL::surface_winding_numbers()`.
struct Solve_report
{
  /// \name Outcome
  /// @{

  bool success = false;              ///< `true` iff all outputs were written
  std::string error;                 ///< why the solve failed (empty on success)
  bool invalid_input = false;        ///< the failure came from the input (`Invalid_input`), not from a solver
  /// @}
  /// \name Mesh
  /// @{

  /// numbers of vertices, edges and faces of the mesh
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t components = 0;        ///< connected components of the mesh
  std::size_t border_edges = 0;      ///< edges with a single incident face
  std::size_t border_loops = 0;      ///< closed loops of border edges (boundary components)
  /// Euler characteristic V - E + F of the mesh (the sum over its components; isolated vertices do not
  /// count). Triangulating faces of more than three sides does not change it.
  long euler_characteristic = 0;
  /// `true` iff the faces of every component can be oriented so that each edge with exactly two faces
  /// is traversed once each way (`false` for a Moebius strip; edges with more than two faces are not
  /// considered). Faces that are not consistently oriented as given (`nonorientable_edges`) do not make
  /// an orientable surface nonorientable.
  bool orientable = true;
  /// sum of the genera \f$ g = (2 - \chi - b) / 2 \f$ of the components (\f$ b \f$: border loops),
  /// defined when every component is an orientable 2-manifold, closed or with border; -1 where it is
  /// not (a nonorientable or a nonmanifold component: see `euler_characteristic` and `orientable`)
  int genus = 0;
  std::size_t nonmanifold_vertices = 0; ///< vertices whose faces form more than one fan, or on a nonmanifold edge
  std::size_t nonmanifold_edges = 0; ///< edges with more than two incident faces
  /// edges whose two faces traverse them the same way (a nonorientable gluing; curves there are dual
  /// chains, see \ref SWNNonmanifold)
  std::size_t nonorientable_edges = 0;
  /// @}
  /// \name Curve
  /// @{

  std::size_t curve_edges = 0;       ///< edges with a nonzero chain value
  std::size_t interior_endpoints = 0;///< vertices not on the border where the chain has a boundary
  /// curve edges dropped because they touch a nonmanifold vertex (paper Sec. 2.2; the gaps are closed
  /// like any other)
  std::size_t dropped_curve_edges = 0;
  /// on a nonorientable surface: vertices where a curve passes through but its normal flips (the curve
  /// is not orientable there, paper Fig. 9: the labels near it are not meaningful)
  std::size_t inconsistent_curve_vertices = 0;
  /// @}
  /// \name Steps that ran
  /// @{

  bool homology_correction = false;  ///< `false` when every component is a disk or a sphere (one solve)
  bool hodge_projection = false;     ///< `true` when the harmonic part was projected (open curves)
  bool reduced_residual = false;     ///< the residual came from the reduced problem of Sec. 6
  bool lp_ran = false;               ///< the residual function (Eq. 11) was computed
  /// `true` when the residual function started from the last solve's answer
  /// (`Surface_winding_numbers_solver` with its default LEMON solver: `LEMON_residual_solver_options::warm_start`)
  bool residual_warm_started = false;
  /// `true` when the jump Laplacian was not factorized for this curve: the solver's kept
  /// factorization of the mesh's 0-form Laplacian served, as it is (a curve without interior
  /// endpoints) or with a low-rank update for the interior endpoints (`jump_laplacian_update_rank`)
  bool jump_laplacian_reused = false;
  /// the rank of that update: the interior endpoints and their neighbours (0 without one). Above
  /// 96, and where taking the endpoints out splits a component, the jump Laplacian is factorized anew
  std::size_t jump_laplacian_update_rank = 0;
  /// @}
  /// \name Residual linear program and weights
  /// @{

  /// numbers of variables and of rows of the residual linear program (0 if it did not run)
  std::size_t lp_variables = 0, lp_rows = 0;
  double lp_objective = 0;           ///< Eq. 11 objective, curve edges weighted by epsilon, lengths in units of the mean edge length
  std::size_t degenerate_weights = 0;///< cotangent weights clamped to [1e-3, 1e3]
  /// @}
  /// \name Labels
  /// @{

  /// smallest and largest label written (after normalization)
  int min_label = 0, max_label = 0;
  /// units of flow added to round(g) to close the nonbounding loops \f$ G \f$ (0 when rounding
  /// edge by edge already gave closed loops; see \ref SWNClosedG)
  std::size_t nonbounding_closing_units = 0;
  /// nonmanifold edges (more than two faces) whose faces do not all carry the same label, although
  /// nothing may jump there: the labels there depend on which flaps are taken as one sheet. This happens
  /// where a curve given as directed edges crosses a spine between two flaps whose faces traverse it the
  /// same way (not oriented as one sheet): the side of the curve that is higher is taken from each face's
  /// orientation, so it swaps at the spine (a dual chain does not depend on it); and where a flap the
  /// curve does not cover closes the region along another path than the flaps it covers, a near tie of
  /// Eq. 11 (\ref SWNNonmanifold).
  std::size_t nonmanifold_label_jumps = 0;
  /// @}
  /// \name Timings
  /// @{

  /// seconds spent in each step (setup, jump Laplace, Hodge, residual, second solve, labels) and in total
  /// (of these steps)
  double time_setup = 0, time_jump_laplace = 0, time_hodge = 0, time_residual = 0,
         time_second_solve = 0, time_labels = 0, time_total = 0;
  /// seconds the solver's construction spent on the mesh (its flat tables, cotangent weights and Hodge
  /// star; once per `Surface_winding_numbers_solver`, the same in each of its reports), and seconds
  /// spent writing the output property maps of this solve; neither is part of `time_total`
  double time_mesh = 0, time_output_maps = 0;
  /// @}
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
