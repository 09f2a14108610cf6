// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_OPTIONS_H
#define CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_OPTIONS_H

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersTraitsClasses

The settings of `LEMON_residual_solver` (its nested type `LEMON_residual_solver::Options`). None of them
changes the optimum: `algorithm` and the multilevel parameters change the running time only, and are
there so that tests can drive every part of the multilevel solver on small problems and so that a user
can fall back to the plain network simplex. The defaults are the measured best on the package's
benchmark (`benchmark/RESULTS.md` and `benchmark/residual_solvers.md` in the source tree).
*/
struct LEMON_residual_solver_options
{
  /// the way the minimum-cost circulation is solved
  enum Algorithm
  {
    NETWORK_SIMPLEX,  ///< `lemon::NetworkSimplex` (pivot rule `BLOCK_SEARCH`) on the whole problem
    MULTILEVEL        ///< network simplex on a hierarchy of contracted problems, certified optimal by a maximum flow (the default)
  };

  /// the algorithm (default `MULTILEVEL`; `NETWORK_SIMPLEX` is 2-10x slower beyond 30k faces)
  Algorithm algorithm = MULTILEVEL;
  /// `true` (the default): `MULTILEVEL` solves the two halves of large bands (see `split_band_nodes`)
  /// on two threads. The named parameter `concurrency` of the package's functions overrides it with
  /// `false` when it asks for a sequential run.
  bool concurrent = true;
  /// largest violation of the bounds accepted in the answer (default `1e-9`; raised to
  /// \f$ 2^{1-k} \f$ when the integer scaling exponent `k` is small)
  double feasibility_tolerance = 1e-9;
  /// messages on the steps and their timings to `std::cerr`
  bool verbose = false;
  /// `true`: a problem on the same graph as the last one solved (the same mesh, the same faces joined
  /// by fixed arcs) starts from the last answer, as `MULTILEVEL`'s finest level does from the coarser
  /// one: its jumps at the kinks of the cost and its flow are carried over, and only the finest level
  /// is certified and repaired; if that is not certified within `max_refinements` bands, the problem
  /// is solved afresh. The answer is an optimum of the new problem either way (where Eq. 11 has several
  /// optima it may be another one than a fresh solve's). The solver then keeps the last answer (about
  /// 70 bytes per face). Default `false`; `Surface_winding_numbers_solver` turns it on for its own solver.
  bool warm_start = false;

  /// \name Multilevel parameters
  /// Running time only, never the optimum. Tests shrink them to run the hierarchy, the bands, the
  /// descent steps and the band refinements on problems of a few dozen faces.
  /// @{

  /// the hierarchy of contracted problems stops at this many nodes (default 2000)
  std::size_t coarsest_nodes = 2000;
  /// largest number of nodes merged into one node of the next coarser level (default 16)
  std::size_t cluster_size = 16;
  /// radius, in arcs, of the bands re-solved around the jumps of the coarser answer on the coarse
  /// levels and around the barriers of refused certificates (default 3)
  int band_radius = 3;
  /// radius of the first band of the finest level (default 8)
  int finest_band_radius = 8;
  /// largest number of bands re-solved around the barrier of a refused certificate on the finest
  /// level before the whole problem goes to `NETWORK_SIMPLEX` (default 16)
  std::size_t max_refinements = 16;
  /// largest number of steepest-descent steps per level along the barriers of refused certificates
  /// (default 1000; 0: bands only)
  std::size_t descent_steps = 1000;
  /// work budget of the push-relabel maximum flow of a certificate, in arc scans per node and arc
  /// (default 200); beyond it Boykov-Kolmogorov finishes the flow. 0: Boykov-Kolmogorov only;
  /// negative: no budget
  double max_flow_budget = 200;
  /// first bands of at least this many nodes are cut in two halves solved side by side, on two
  /// threads if `concurrent` (default 5000; 0: never); on the 1.15M-face chain10 of the benchmark the
  /// residual is about 20 % longer without them
  std::size_t split_band_nodes = 5000;
  /// on problems of at most this many faces (default: no limit; 0: never) the first band of each level
  /// grows only around the jumps off the curve (the completions of its gaps, which move from level to
  /// level), and the jumps on the curve bring only their two faces: smaller bands, less network simplex
  /// (residual summed over the benchmark's 232 cases with handles 9.5 % lower, 1.15M-face chain10's
  /// 15 % lower)
  std::size_t narrow_curve_band_nodes = (std::numeric_limits<std::size_t>::max)();
  /// on levels of at least this many nodes (default 100,000; 0: every level) the flow carried down
  /// from the coarser level is first balanced inside the regions of the coarser levels, by
  /// augmenting paths within a work budget, before the certificate's maximum flow: about 20 % of the
  /// residual on the 1.15M-face chain10 of the benchmark; on smaller levels the maximum flow alone is
  /// faster
  std::size_t carried_flow_routing_nodes = 100000;
  /// @}
};

/*!
\ingroup PkgSurfaceWindingNumbersTraitsClasses

What the last call to `LEMON_residual_solver::solve_residual()` did (its nested type
`LEMON_residual_solver::Statistics`).
*/
struct LEMON_residual_solver_statistics
{
  std::size_t faces = 0;               ///< faces of the problem
  std::size_t arcs = 0;                ///< arcs of the problem
  std::size_t fixed_arcs = 0;          ///< arcs with `lower == upper`, contracted
  std::size_t constant_arcs = 0;       ///< arcs whose two faces were merged by the contraction (constant jump)
  std::size_t nodes = 0;               ///< nodes of the network (faces after contraction)
  std::size_t network_arcs = 0;        ///< arcs of the network (`NETWORK_SIMPLEX`)
  std::size_t nonzero_cost_arcs = 0;   ///< problem arcs whose scaled jump `s` is nonzero after gauge fixing
  int cost_exponent = 0;               ///< jumps and costs are scaled by 2^cost_exponent
  int capacity_exponent = 0;           ///< weights are scaled by 2^capacity_exponent
  LEMON_residual_solver_options::Algorithm algorithm = LEMON_residual_solver_options::NETWORK_SIMPLEX;   ///< the algorithm whose result was used
  bool fallback = false;               ///< `MULTILEVEL` was not certified and `NETWORK_SIMPLEX` solved the whole problem
  bool warm_started = false;           ///< `Options::warm_start`: the answer came from the last one, repaired on the finest level
  bool certified = false;              ///< the exact optimality certificate held (duality, or a balanced maximum flow)
  std::size_t levels = 0;              ///< `MULTILEVEL`: levels of the hierarchy (1: the problem itself)
  std::size_t refinements = 0;         ///< `MULTILEVEL`: bands re-solved around barriers on the finest level
  std::size_t descent_steps = 0;       ///< `MULTILEVEL`: steps along the barriers of refused certificates (every level)
  std::size_t descent_pieces = 0;      ///< `MULTILEVEL`: connected pieces moved by those steps, each by its own line search
  std::size_t largest_band = 0;        ///< `MULTILEVEL`: nodes of the largest problem given to network simplex
  std::size_t split_bands = 0;         ///< `MULTILEVEL`: bands solved in two halves
  std::size_t routed_levels = 0;       ///< `MULTILEVEL`: levels whose carried-down flow was balanced inside the coarser regions
  std::size_t certificates = 0;        ///< `MULTILEVEL`: maximum flows run (every level, every refinement)
  std::size_t max_flow_fallbacks = 0;  ///< `MULTILEVEL`: maximum flows that Boykov-Kolmogorov finished (push-relabel over its budget)
  double objective = 0;                ///< Eq. 11 objective of `sigma`, recomputed with the original data
  double max_violation = 0;            ///< largest violation of the bounds by `sigma`
  double time_build = 0;               ///< seconds: checks, contraction, gauge, scaling
  double time_solve = 0;               ///< seconds: the flow algorithms and the certificates
  double time_recover = 0;             ///< seconds: sigma from the potentials, objective and violation
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
