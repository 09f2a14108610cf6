// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_H
#define CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_H

#include <CGAL/Surface_winding_numbers/Residual_problem.h>
#include <CGAL/Surface_winding_numbers/internal/boykov_kolmogorov_flow.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>
#include <CGAL/Surface_winding_numbers/internal/warm_push_relabel.h>

#include <lemon/cost_scaling.h>
#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <future>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersTraitsClasses

Exact solver of the residual problem (paper Eq. 11, `Residual_problem`) as a minimum-cost
circulation, with the network flow algorithms of LEMON (<https://lemon.cs.elte.hu>, Boost Software
License).

Eq. 11 minimizes a sum of convex piecewise-linear functions of the differences `sigma[left] -
sigma[right]` (a minimum-cost tension problem on the dual graph). Its linear programming dual is a
minimum-cost circulation in which every arc of the problem becomes two to four parallel network arcs:
two of capacity `cost[a]` (the slopes of `|J|`) and, for each finite bound, one penalty arc of a
capacity larger than any flow of an optimal basic circulation, so that the penalty is exact. The
optimal node potentials of the circulation are an optimal `sigma`. The solver

- contracts the arcs whose two bounds are equal (the jump is fixed) with a union-find that keeps
  the offsets between the shifts of the merged faces; a cycle of fixed arcs whose jumps do not add
  up fails;
- fixes the gauge of each connected component of the dual graph along a breadth-first spanning
  tree (the jump is 0 on the tree), so that only the arcs that close a nonzero cycle of `s` keep a
  nonzero cost;
- scales costs and jumps by \f$ 2^k \f$ and the weights `cost[a]` by \f$ 2^m \f$ and rounds them to
  64-bit integers (LEMON's algorithms need integer data): \f$ k \f$ is the largest exponent up to
  42 for which no node potential can exceed \f$ 2^{59} \f$, and, for cost scaling, the costs
  multiplied by 16 times the number of nodes (as `lemon::CostScaling` does internally) stay below
  \f$ 2^{60} \f$ (\f$ k = 42 \f$ with network simplex, 39 with cost scaling at 35k faces and
  jumps of order 1). \f$ m \f$ makes the sum of all capacities at most \f$ 2^{58} \f$. The jump
  of every arc is then exact up to \f$ 2^{-k-1} \f$ (\f$ 1.1 \cdot 10^{-13} \f$ at
  \f$ k = 42 \f$), and each weight up to \f$ 2^{-m-1} \f$ in absolute value;
- solves the circulation with LEMON's `NetworkSimplex`, either on the whole problem
  (`NETWORK_SIMPLEX`) or on a hierarchy of contracted problems whose answer is then certified by a
  maximum flow (`MULTILEVEL`, the default; see `default_algorithm()`), or, on request, with
  `CostScaling` (see `Algorithm`); checks that each flow is a circulation within the capacities
  and, where the compiler has 128-bit integers, the exact duality certificate (the penalized
  objective of the potentials equals minus the cost of the flow), and fails if a check fails;
- recovers `sigma` from the potentials (differences taken in integers before the conversion), and
  shifts each component so that its face listed in `gauge_faces` gets 0; faces without any
  constraining arc get 0 (up to the offsets of fixed arcs).

`solve_residual()` returns `false`, and `error()` says why, if the problem is malformed (sizes,
indices, a negative or non-finite cost, bounds with `lower > upper`), if fixed arcs contradict each
other, if the data are too large for the integer scaling, if no algorithm returned a certified
optimum, or if the problem is infeasible. In the last case `sigma` holds the solution of least
penalized violation, and `statistics().max_violation` tells by how much it violates the bounds.

On the demo double torus with loops (35k faces) the residual problem takes 0.15 s with the default
algorithm (`MULTILEVEL`), 0.42 s with `NETWORK_SIMPLEX` and 117 to 250 s with GLPK's dual simplex
on the same machine; the objectives agree to \f$ 10^{-11} \f$ (see `benchmark/residual_solvers.md`
in the source tree). The class is not copyable: pass it with `std::ref()` to the named parameter
`lp_solver`.

\cgalModels `SurfaceWindingNumbersResidualSolver`
*/
class LEMON_residual_solver
{
public:
  /*!
  The minimum-cost flow algorithm of LEMON run on the circulation.

  \warning The cost scaling variants are for experiments only. In LEMON 1.3.1 (Debian's
  `liblemon-dev`) the price refinement heuristic of `lemon::CostScaling`, used by all three
  methods, can index its rank buckets out of bounds (a heap buffer overflow, found with
  AddressSanitizer on random networks of 3 to 8 nodes) and can loop forever (`PUSH` on such random
  networks; `AUGMENT` and `PARTIAL_AUGMENT` on a residual problem of 4 faces, a cycle with one
  curve arc).
  `NETWORK_SIMPLEX` passed the same random tests (40,000 networks, checked against
  `lemon::CycleCanceling` and the duality certificate, clean under AddressSanitizer).
  */
  enum Algorithm
  {
    NETWORK_SIMPLEX,               ///< `lemon::NetworkSimplex` on the whole problem, pivot rule `BLOCK_SEARCH`
    COST_SCALING_PUSH,             ///< `lemon::CostScaling`, method `PUSH` (see the warning)
    COST_SCALING_AUGMENT,          ///< `lemon::CostScaling`, method `AUGMENT` (see the warning)
    COST_SCALING_PARTIAL_AUGMENT,  ///< `lemon::CostScaling`, method `PARTIAL_AUGMENT` (see the warning)
    MULTILEVEL                     ///< `NETWORK_SIMPLEX` on a hierarchy of contracted problems, certified by a maximum flow (the default; see below)
  };

  /// What the last call to `solve_residual()` did.
  struct Statistics
  {
    std::size_t faces = 0;               ///< faces of the problem
    std::size_t arcs = 0;                ///< arcs of the problem
    std::size_t fixed_arcs = 0;          ///< arcs with `lower == upper`, contracted
    std::size_t constant_arcs = 0;       ///< arcs whose two faces were merged by the contraction (constant jump)
    std::size_t nodes = 0;               ///< nodes of the network (faces after contraction)
    std::size_t network_arcs = 0;        ///< arcs of the network
    std::size_t nonzero_cost_arcs = 0;   ///< problem arcs whose scaled jump `s` is nonzero after gauge fixing
    int cost_exponent = 0;               ///< jumps and costs are scaled by 2^cost_exponent
    int capacity_exponent = 0;           ///< weights are scaled by 2^capacity_exponent
    Algorithm algorithm = NETWORK_SIMPLEX;   ///< the algorithm whose result was used
    bool fallback = false;               ///< the first algorithm failed and the other one was used
    bool certified = false;              ///< the exact duality certificate of the scaled problem held
    std::size_t levels = 0;              ///< `MULTILEVEL`: levels of the hierarchy (1: the problem itself)
    std::size_t refinements = 0;         ///< `MULTILEVEL`: band problems solved on the finest level
    std::size_t descent_steps = 0;       ///< `MULTILEVEL`: steps along the barriers of refused certificates (every level)
    std::size_t descent_pieces = 0;      ///< `MULTILEVEL`: connected pieces that those steps moved, each by its own line search (at least `descent_steps`)
    std::size_t descent_lowerings = 0;   ///< `MULTILEVEL`: steps that lowered pieces of a barrier's complement rather than raising pieces of the barrier
    std::size_t largest_band = 0;        ///< `MULTILEVEL`: nodes of the largest problem given to network simplex
    std::size_t split_bands = 0;         ///< `MULTILEVEL`: first bands solved in two halves (see `set_split_bands()`)
    std::size_t routed_levels = 0;       ///< `MULTILEVEL`: levels whose carried-down flow was routed inside the coarser regions (see `set_carried_flow_routing()`)
    std::size_t certificates = 0;        ///< `MULTILEVEL`: maximum flows run (every level, every refinement)
    std::size_t max_flow_fallbacks = 0;  ///< `MULTILEVEL`: maximum flows that Boykov-Kolmogorov finished (push-relabel over its budget, or slower in a race, see `set_concurrent_max_flows()`)
    double objective = 0;                ///< Eq. 11 objective of `sigma`, recomputed with the original data
    double max_violation = 0;            ///< largest violation of the bounds by `sigma`
    double time_build = 0;               ///< seconds: checks, contraction, gauge, scaling, network
    double time_solve = 0;               ///< seconds: LEMON (graph, algorithm) and the certificate
    double time_recover = 0;             ///< seconds: sigma from the potentials, objective and violation
  };

  /*!
  the algorithm used by default: `MULTILEVEL`.

  The optimal shifts are constant over large regions and the jumps concentrate on a few curves (the
  completion of the curve and the nonbounding loops). `MULTILEVEL` builds a hierarchy of
  contracted problems (clusters of up to 16 faces joined by free arcs without jump share one shift;
  parallel arcs merge), solves the coarsest one (at most 2000 nodes) with `NETWORK_SIMPLEX`, and on
  each finer level re-solves only a band of nodes around the jumps of the coarser answer (every
  connected piece of the rest contracted to one node; along the curve, where the jumps do not move,
  only their faces, see `set_narrow_curve_bands()`; a large band is cut in two halves solved at once
  on two threads, see `set_split_bands()`). The optimal flows of these network simplex
  runs are carried down the hierarchy (on each level of 100,000 nodes or more, the imbalances left
  by sharing a coarse arc's flow among its fine arcs are routed inside each cluster and each small
  region of the coarser levels first, see `set_carried_flow_routing()`), and on each level a maximum
  flow completes them into
  a circulation within the subdifferentials of the objective (push-relabel on the flat arrays of
  `internal::Warm_push_relabel`, handed over to Boost.Graph's Boykov-Kolmogorov beyond a work
  budget, see `set_max_flow_budget()`; after a descent step on levels of 500,000 nodes or more both
  run at once on two threads, see `set_concurrent_max_flows()`):
  that circulation is an exact certificate that the answer is optimal for the whole problem, and it
  is checked independently (bounds and conservation, in integers). When no such circulation
  exists, the minimum cut is a set of faces whose shifts can all rise with a negative slope of the
  objective (the steepest such set): the shifts of each connected piece of that set rise by the
  amount that minimizes the objective along that direction (an exact line search over the
  breakpoints of the arcs that cross the piece's border; no arc joins two pieces, so each piece
  has its own), or those of each piece of its complement fall, whichever lowers the objective
  more (`statistics().descent_pieces`, `statistics().descent_lowerings`), and the certificate is
  tried again from its previous flow, on the
  maximum-flow graphs of the level's first certificate (kept until the level is done). These
  descent steps are taken on every level (at most `descent_steps()` per level, see
  `set_descent_steps()`). When the steps zigzag between two sets (the same decreases, alternately), one
  step goes along the sum of the two, and after 16 repeated decreases the level stops descending.
  If the certificate of the finest level is still refused, a band around
  the border of the set (and only there) is re-solved by network simplex, which lowers the
  objective, and the certificate is tried again. After `max_refinements` such bands (see
  `set_multilevel_parameters()`), the whole problem goes to `NETWORK_SIMPLEX`
  (`statistics().fallback`): the answer is always an optimum of the whole problem.

  Measured on the demo double torus with loops and its subdivisions (35k, 140k, 560k faces; see
  `benchmark/residual_solvers.md`): `MULTILEVEL` 0.27, 2.1 and 19 s, `NETWORK_SIMPLEX` 0.47, 14.6
  and 204 s, same objectives. Most of `MULTILEVEL`'s time is the maximum flow of the certificate.
  */
  static Algorithm default_algorithm() { return MULTILEVEL; }

  /// creates a solver that uses `default_algorithm()`
  LEMON_residual_solver() : algorithm_(default_algorithm()) {}
  /// creates a solver that uses `algorithm`
  explicit LEMON_residual_solver(Algorithm algorithm) : algorithm_(algorithm) {}
  LEMON_residual_solver(const LEMON_residual_solver&) = delete;
  LEMON_residual_solver& operator=(const LEMON_residual_solver&) = delete;

  /// a name for logs and summaries
  static const char* name() { return "lemon"; }

  /// sets the algorithm of the next solves
  void set_algorithm(Algorithm a) { algorithm_ = a; }
  /// the algorithm of the next solves
  Algorithm algorithm() const { return algorithm_; }
  /// if `true`, a failed or uncertified solve is repeated with the other kind of algorithm
  /// (`NETWORK_SIMPLEX` after cost scaling, `COST_SCALING_PUSH` after network simplex). Default:
  /// `false` (a failure of network simplex has not been seen; cost scaling has the defects listed
  /// at `Algorithm`).
  void set_fallback(bool b) { fallback_ = b; }
  /// largest violation of the bounds accepted (default `1e-9`; raised to \f$ 2^{1-k} \f$ when the
  /// scaling exponent `k` is small)
  void set_feasibility_tolerance(double t) { tolerance_ = t; }
  /// messages on standard error
  void set_verbose(bool b) { verbose_ = b; }
  /*!
  parameters of `MULTILEVEL`: the hierarchy stops at `coarsest_nodes` nodes (default 2000), clusters
  have at most `cluster_size` nodes (default 16), bands reach `band_radius` arcs (default 3) beyond
  the jumps on the coarse levels and around the barriers of refused certificates (see
  `set_finest_band_radius()` for the first band of the finest level), and at most
  `max_refinements` bands (default 16) are re-solved on the finest level before the whole problem
  is handed to `NETWORK_SIMPLEX`. They change the running time, never the optimum.
  */
  void set_multilevel_parameters(std::size_t coarsest_nodes, std::size_t cluster_size, int band_radius,
                                 std::size_t max_refinements)
  {
    coarsest_nodes_ = (std::max)(std::size_t(1), coarsest_nodes);
    cluster_size_ = (std::max)(std::size_t(2), cluster_size);
    band_radius_ = (std::max)(0, band_radius);
    max_refinements_ = max_refinements;
  }
  /// the parameters of `MULTILEVEL` (see `set_multilevel_parameters()`)
  std::size_t coarsest_nodes() const { return coarsest_nodes_; }
  /// \copydoc coarsest_nodes()
  std::size_t cluster_size() const { return cluster_size_; }
  /// \copydoc coarsest_nodes()
  int band_radius() const { return band_radius_; }
  /// \copydoc coarsest_nodes()
  std::size_t max_refinements() const { return max_refinements_; }
  /// radius, in arcs beyond the jumps carried down from level 1, of the first band solved on the
  /// finest level of `MULTILEVEL` (default 8). Changes the running time, never the optimum.
  void set_finest_band_radius(int radius) { finest_band_radius_ = (std::max)(0, radius); }
  /// the radius of the first band of the finest level (see `set_finest_band_radius()`)
  int finest_band_radius() const { return finest_band_radius_; }
  /*!
  largest number of descent steps that `MULTILEVEL` takes on each level along the barriers of
  refused certificates before it re-solves bands (default 1000; 0: bands only). A step costs one
  line search and one certificate started from the previous flow; on the finest level of the
  benchmark it replaces the band refinements. Changes the running time, never the optimum.
  */
  void set_descent_steps(std::size_t steps) { descent_steps_ = steps; }
  /// the largest number of descent steps per level (see `set_descent_steps()`)
  std::size_t descent_steps() const { return descent_steps_; }
  /*!
  work budget of the push-relabel maximum flow in the certificate of `MULTILEVEL`, in arc scans per
  node and arc of the level (default 200). Push-relabel is the faster algorithm on most
  certificates; beyond the budget, Boykov-Kolmogorov finishes the flow from where push-relabel
  stopped (`statistics().max_flow_fallbacks`). 0: Boykov-Kolmogorov only; a negative value: no
  budget. Changes the running time, never the answer. (Until 2026-12-03 the budget was capped at
  \f$ 2 \cdot 10^8 \f$ scans on levels of more than a million nodes and arcs; since push-relabel
  uses the gap heuristic, the first certificate of such a level costs it less than the cap's
  hand-over to Boykov-Kolmogorov, see `benchmark/residual_solvers.md`.)
  */
  void set_max_flow_budget(double work_per_element) { push_relabel_budget_ = work_per_element; }
  /// the work budget of the push-relabel maximum flow (see `set_max_flow_budget()`)
  double max_flow_budget() const { return push_relabel_budget_; }
  /*!
  if `enable` (the default), the certificates of `MULTILEVEL` that follow a descent step, on levels
  of at least `min_nodes` nodes (default 500,000), run push-relabel and Boykov-Kolmogorov at once,
  on two threads, from the same flow, and keep the flow of the first to finish (the other is
  stopped at once). Push-relabel keeps its work budget (`set_max_flow_budget()`; 0:
  Boykov-Kolmogorov only), beyond which it stops and leaves the memory bandwidth to
  Boykov-Kolmogorov. Otherwise push-relabel runs first within its budget and Boykov-Kolmogorov
  finishes the flow from where it stopped (also when no second thread can be started).
  Measured (`benchmark/residual_solvers.md`): after a descent step, neither algorithm is the
  faster one on every certificate of a large level, and a race costs at most the time of the
  faster one; on the first certificate of a level, Boykov-Kolmogorov runs much faster from where
  push-relabel stopped than from the carried-down flow, and on levels below 500,000 nodes the two
  threads slow each other down more than they gain. The answer does not depend on which one
  finishes first (a refused certificate's barrier is the set of faces that cannot reach a missing
  inflow, the same for every maximum flow). Changes the running time, never the answer.
  */
  void set_concurrent_max_flows(bool enable, std::size_t min_nodes = 500000)
  {
    concurrent_max_flows_ = enable;
    concurrent_max_flow_nodes_ = min_nodes;
  }
  /// whether certificates on large levels race the two maximum flows (see `set_concurrent_max_flows()`)
  bool concurrent_max_flows() const { return concurrent_max_flows_; }
  /// the smallest level, in nodes, on which they do (see `set_concurrent_max_flows()`)
  std::size_t concurrent_max_flow_nodes() const { return concurrent_max_flow_nodes_; }
  /*!
  on problems of at most `max_nodes` faces (default 1,000,000; 0: none), the first band of each
  level of `MULTILEVEL` grows only around the jumps off the curve (the completions of its gaps, which
  move from level to level); the jumps on the curve (arcs with bounds), which stay in place, bring
  only their two faces. The bands shrink (chain5_r0_g15's first finest band from 21,324 to 15,028
  nodes), and so does network simplex's time; where the certificate that follows has more to
  repair, it costs more. Measured (`benchmark/residual_solvers.md`): residual 15 % faster summed over the 30 slowest
  cases of the benchmark (23k-188k faces), 40 % faster on DoubleTorusWithLoops subdivided twice
  (559k faces), about 10 % slower at 1.15M faces, where the first certificate of the finest level
  dominates (hence the default bound). Changes the running time, never the optimum.
  */
  void set_narrow_curve_bands(std::size_t max_nodes) { narrow_curve_band_nodes_ = max_nodes; }
  /// the largest problem, in faces, whose first bands are narrow along the curve (see `set_narrow_curve_bands()`)
  std::size_t narrow_curve_band_nodes() const { return narrow_curve_band_nodes_; }

  /*!
  the first band of a level of `MULTILEVEL` (the band around the jumps of the coarser answer) with at
  least `min_nodes` nodes (default 5,000; 0: never) is cut in two halves by a breadth-first level of
  its largest connected part (or, if no part holds half of it, by giving whole parts to either half).
  That level, and the pieces of the outside that touch both halves, keep their shifts; the two halves
  (with the pieces that touch only them) are independent problems, solved by network simplex at once
  on two threads (one after the other if no thread can be started), and then a band of
  `band_radius()` arcs around the cut is solved as well. Network simplex costs more than linearly in
  the size of the band, and the certificates and descent steps that follow repair what the cut costs.
  Measured (`benchmark/residual_solvers.md`): residual alone 10-26 % faster on five of seven of the
  slowest cases of the benchmark (23k-188k faces), about the same on the other two; 13.0 -> 10.4 s on
  1.15M faces (genus 10). Changes the running time, never the optimum.
  */
  void set_split_bands(std::size_t min_nodes) { split_band_nodes_ = min_nodes; }
  /// the smallest first band that is solved in two halves (see `set_split_bands()`)
  std::size_t split_band_nodes() const { return split_band_nodes_; }

  /*!
  the flow carried down to a level of `MULTILEVEL` with at least `min_nodes` nodes (default 100,000;
  0: every level) is first routed inside the clusters of the coarser levels, along their arcs without
  jump, by augmenting paths within a work budget; on smaller levels the certificate's push-relabel
  settles all of the imbalances. Measured (`benchmark/residual_solvers.md`): on ten cases of 23k-188k
  faces the residual took 3-13 % less without the routing below 100,000 nodes (7 % more on a case of
  114k faces), and 3-5 % more without it on the 1.07M-node finest level of a problem of genus 10.
  Changes the running time, never the optimum.
  */
  void set_carried_flow_routing(std::size_t min_nodes) { routing_nodes_ = min_nodes; }
  /// the smallest level whose carried-down flow is routed (see `set_carried_flow_routing()`)
  std::size_t carried_flow_routing_nodes() const { return routing_nodes_; }

  /// why the last solve failed (empty after a success)
  const std::string& error() const { return error_; }
  /// what the last solve did
  const Statistics& statistics() const { return stats_; }

  /*!
  solves `P`: writes one shift per face to `sigma` (resized to `P.number_of_faces`).
  \returns `true` on success; `false` with a reason in `error()` otherwise.
  */
  bool solve_residual(const Residual_problem& P, std::vector<double>& sigma)
  {
    error_.clear();
    stats_ = Statistics();
    try
    {
      return solve_impl(P, sigma);
    }
    catch(const std::exception& e)
    {
      return fail(std::string("LEMON residual solver: ") + e.what());
    }
  }

private:
  typedef long long Int;
  typedef lemon::SmartDigraph Graph;
#ifdef __SIZEOF_INT128__
  __extension__ typedef __int128 Wide;   // exact certificate, large costs inside cost scaling
  static constexpr bool has_wide = true;
#else
  typedef long double Wide;
  static constexpr bool has_wide = false;
#endif

  // a problem arc after contraction: jump J = s + sigma[L] - sigma[R] over the contracted nodes
  struct Work_arc
  {
    std::size_t L, R;
    double s, w, lo, up;
    bool tree;
  };

  // the network handed to LEMON (and kept for the certificate)
  struct Network
  {
    std::vector<std::size_t> tail, head;
    std::vector<Int> cap, cost;
    std::vector<std::size_t> owner;   // the problem arc of each network arc (MULTILEVEL)
    std::size_t current = 0;
    void add(std::size_t t, std::size_t h, Int c, Int k)
    {
      if(c <= 0) return;
      tail.push_back(t); head.push_back(h); cap.push_back(c); cost.push_back(k); owner.push_back(current);
    }
  };

  bool fail(const std::string& why)
  {
    error_ = why;
    if(verbose_) std::cerr << "[swn] " << why << "\n";
    return false;
  }

  static double seconds(std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  static const char* algorithm_name(Algorithm a)
  {
    switch(a)
    {
      case COST_SCALING_PUSH: return "CostScaling/PUSH";
      case COST_SCALING_AUGMENT: return "CostScaling/AUGMENT";
      case COST_SCALING_PARTIAL_AUGMENT: return "CostScaling/PARTIAL_AUGMENT";
      case NETWORK_SIMPLEX: return "NetworkSimplex/BLOCK_SEARCH";
      case MULTILEVEL: return "Multilevel/NetworkSimplex+MaxFlow";
    }
    return "?";
  }

  // weighted union-find: sigma[f] = sigma[parent[f]] + offset[f]
  struct Union_find
  {
    std::vector<std::size_t> parent, size;
    std::vector<double> offset;
    std::vector<std::size_t> path;
    explicit Union_find(std::size_t n) : parent(n), size(n, 1), offset(n, 0.)
    {
      for(std::size_t i = 0; i < n; ++i) parent[i] = i;
    }
    // root of f; o = sigma[f] - sigma[root]
    std::size_t find(std::size_t f, double& o)
    {
      path.clear();
      while(parent[f] != f) { path.push_back(f); f = parent[f]; }
      // compress from the top: offsets become relative to the root
      for(std::size_t i = path.size(); i-- > 0;)
      {
        const std::size_t x = path[i];
        if(parent[x] != f) offset[x] += offset[parent[x]];
        parent[x] = f;
      }
      o = path.empty() ? 0. : offset[path.front()];
      return f;
    }
    // imposes sigma[a] - sigma[b] = d; returns false and the gap if a and b are already joined
    bool join(std::size_t a, std::size_t b, double d, double& gap)
    {
      double oa, ob;
      const std::size_t ra = find(a, oa), rb = find(b, ob);
      if(ra == rb) { gap = (oa - ob) - d; return false; }
      // sigma[ra] - sigma[rb] = d - oa + ob
      const double x = d - oa + ob;
      if(size[ra] <= size[rb]) { parent[ra] = rb; offset[ra] = x; size[rb] += size[ra]; }
      else { parent[rb] = ra; offset[rb] = -x; size[ra] += size[rb]; }
      return true;
    }
  };

  bool check_input(const Residual_problem& P)
  {
    const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
    if(P.right.size() != na || P.s.size() != na || P.cost.size() != na || P.lower.size() != na || P.upper.size() != na)
      return fail("the residual problem has arrays of different sizes");
    for(std::size_t a = 0; a < na; ++a)
    {
      const std::string at = " at arc " + std::to_string(a);
      if(P.left[a] >= nf || P.right[a] >= nf) return fail("the residual problem has a face index out of range" + at);
      if(!std::isfinite(P.s[a])) return fail("the residual problem has a non-finite jump s" + at);
      if(!(P.cost[a] >= 0) || !std::isfinite(P.cost[a])) return fail("the residual problem has a negative or non-finite cost" + at);
      if(std::isnan(P.lower[a]) || std::isnan(P.upper[a]) || !(P.lower[a] <= P.upper[a]) ||
         P.lower[a] == std::numeric_limits<double>::infinity() || P.upper[a] == -std::numeric_limits<double>::infinity())
        return fail("the residual problem has empty or invalid bounds" + at);
    }
    for(std::size_t f : P.gauge_faces)
      if(f >= nf) return fail("the residual problem has a gauge face out of range");
    return true;
  }

  bool solve_impl(const Residual_problem& P, std::vector<double>& sigma)
  {
    const auto t_build = std::chrono::steady_clock::now();
    const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
    stats_.faces = nf;
    stats_.arcs = na;
    sigma.assign(nf, 0.);
    if(!check_input(P)) return false;
    if(nf == 0) { stats_.certified = true; return true; }

    // 1. contract the fixed arcs: sigma[L] - sigma[R] = lower - s
    Union_find uf(nf);
    double worst_gap = 0;
    for(std::size_t a = 0; a < na; ++a)
    {
      if(!(P.lower[a] == P.upper[a])) continue;
      ++stats_.fixed_arcs;
      double gap = 0;
      if(!uf.join(P.left[a], P.right[a], P.lower[a] - P.s[a], gap)) worst_gap = (std::max)(worst_gap, std::abs(gap));
    }
    if(!(worst_gap <= tolerance_))
      return fail("the arcs with a fixed jump (lower == upper) contradict each other around a cycle by " +
                  std::to_string(worst_gap));
    std::vector<std::size_t> node_of_root(nf, npos), face_node(nf);
    std::vector<double> face_offset(nf);
    std::size_t nn = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = uf.find(f, face_offset[f]);
      if(node_of_root[r] == npos) node_of_root[r] = nn++;
      face_node[f] = node_of_root[r];
    }
    stats_.nodes = nn;
    if(nn > std::size_t((std::numeric_limits<int>::max)() / 2) || na > std::size_t((std::numeric_limits<int>::max)() / 4))
      return fail("the residual problem is too large for LEMON's graphs (int indices)");

    // 2. the remaining arcs over the contracted nodes
    std::vector<Work_arc> arcs;
    arcs.reserve(na);
    double constant_violation = 0;
    for(std::size_t a = 0; a < na; ++a)
    {
      if(P.lower[a] == P.upper[a]) continue;
      const std::size_t L = face_node[P.left[a]], R = face_node[P.right[a]];
      const double s = P.s[a] + face_offset[P.left[a]] - face_offset[P.right[a]];
      if(L == R)
      {
        ++stats_.constant_arcs;   // constant jump s: only its bounds matter
        constant_violation = (std::max)(constant_violation, (std::max)(P.lower[a] - s, s - P.upper[a]));
        continue;
      }
      if(P.cost[a] == 0 && !P.is_bounded(a)) continue;   // no effect on anything
      arcs.push_back(Work_arc{L, R, s, P.cost[a], P.lower[a], P.upper[a], false});
    }
    if(!(constant_violation <= tolerance_))
      return fail("the residual problem is infeasible: an arc whose faces are joined by fixed arcs violates its bounds by " +
                  std::to_string(constant_violation));

    // 3. gauge: breadth-first forest, jump 0 on the tree arcs; components rooted at gauge faces first
    std::vector<std::size_t> first(nn + 1, 0), adj(2 * arcs.size());
    for(const Work_arc& e : arcs) { ++first[e.L + 1]; ++first[e.R + 1]; }
    for(std::size_t v = 0; v < nn; ++v) first[v + 1] += first[v];
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(std::size_t i = 0; i < arcs.size(); ++i) { adj[fill[arcs[i].L]++] = i; adj[fill[arcs[i].R]++] = i; }
    }
    std::vector<double> sigma0(nn, 0.);
    std::vector<std::size_t> component(nn, npos), roots, queue;
    queue.reserve(nn);
    auto grow = [&](std::size_t root) {
      if(component[root] != npos) return;
      const std::size_t c = roots.size();
      roots.push_back(root);
      component[root] = c;
      queue.clear();
      queue.push_back(root);
      for(std::size_t q = 0; q < queue.size(); ++q)
      {
        const std::size_t x = queue[q];
        for(std::size_t k = first[x]; k < first[x + 1]; ++k)
        {
          Work_arc& e = arcs[adj[k]];
          const std::size_t y = e.L == x ? e.R : e.L;
          if(component[y] != npos) continue;
          component[y] = c;
          // J = s + sigma0[L] - sigma0[R] = 0
          sigma0[y] = e.L == x ? sigma0[x] + e.s : sigma0[x] - e.s;
          e.tree = true;
          queue.push_back(y);
        }
      }
    };
    for(std::size_t f : P.gauge_faces) grow(face_node[f]);
    for(std::size_t v = 0; v < nn; ++v) grow(v);

    // 4. integer scaling
    std::vector<double> st(arcs.size());
    double B = 1, wsum = 0;
    for(std::size_t i = 0; i < arcs.size(); ++i)
    {
      const Work_arc& e = arcs[i];
      st[i] = e.tree ? 0. : e.s + sigma0[e.L] - sigma0[e.R];
      double bound = 0;
      if(std::isfinite(e.lo)) bound = (std::max)(bound, std::abs(e.lo));
      if(std::isfinite(e.up)) bound = (std::max)(bound, std::abs(e.up));
      B = (std::max)(B, std::abs(st[i]) + bound);
      wsum += e.w;
    }
    // largest cost exponents: node potentials stay below 2^60 (network simplex); cost scaling also
    // multiplies the costs by (nodes + 1) * 16 internally, kept below 2^60 (beyond 2^62 its AUGMENT
    // method was seen to loop)
    const double lognB = std::log2(double(nn + 1) * B);
    const int k_simplex = (std::min)(max_cost_exponent, int(std::floor(59. - lognB)));
    const int k_scaling = (std::min)(k_simplex, int(std::floor(56. - lognB)));
    if(k_scaling < 12)
      return fail("the residual problem's jumps are too large for the 64-bit integer scaling (largest |s| + |bound| " +
                  std::to_string(B) + " on " + std::to_string(nn) + " nodes)");
    const int m = wsum > 0 ? (std::max)(-1000, (std::min)(1000, int(std::floor(57. - std::log2(wsum))))) : 0;
    stats_.capacity_exponent = m;

    auto to_int = [](double x, int e) { return Int(std::llround(std::ldexp(x, e))); };
    std::vector<Int> w_hat(arcs.size());
    Int finite_caps = 0;
    for(std::size_t i = 0; i < arcs.size(); ++i)
    {
      w_hat[i] = to_int(arcs[i].w, m);
      finite_caps += 2 * w_hat[i];
    }
    const Int U = finite_caps + 1;   // exceeds every flow of an optimal basic circulation: exact penalty

    // 5. the network for the cost exponent k: J^ = s^ + pi[L] - pi[R]; reduced cost c + pi[tail] - pi[head]
    //    R->L cost x - s^ has reduced cost x - J^ (active when J^ > x), L->R cost s^ - x has J^ - x.
    auto build = [&](int k, Network& net) {
      net = Network();
      net.tail.reserve(3 * arcs.size()); net.head.reserve(3 * arcs.size());
      net.cap.reserve(3 * arcs.size()); net.cost.reserve(3 * arcs.size());
      stats_.nonzero_cost_arcs = 0;
      for(std::size_t i = 0; i < arcs.size(); ++i)
      {
        const Work_arc& e = arcs[i];
        const Int sh = to_int(st[i], k);
        if(sh != 0) ++stats_.nonzero_cost_arcs;
        const bool has_up = std::isfinite(e.up), has_lo = std::isfinite(e.lo);
        const Int up = has_up ? to_int(e.up, k) : 0, lo = has_lo ? to_int(e.lo, k) : 0;
        const bool merge_up = has_up && up == 0, merge_lo = has_lo && lo == 0;
        net.add(e.R, e.L, w_hat[i] + (merge_up ? U : 0), -sh);   // w (J)_+
        net.add(e.L, e.R, w_hat[i] + (merge_lo ? U : 0), sh);    // w (-J)_+
        if(has_up && !merge_up) net.add(e.R, e.L, U, up - sh);   // U (J - up)_+
        if(has_lo && !merge_lo) net.add(e.L, e.R, U, sh - lo);   // U (lo - J)_+
      }
      stats_.network_arcs = net.cap.size();
      stats_.cost_exponent = k;
    };
    Algorithm a = algorithm_;
    if(!has_wide_large_cost() && a != NETWORK_SIMPLEX) a = NETWORK_SIMPLEX;
    if(a == MULTILEVEL)
    {
      stats_.time_build = seconds(t_build);
      const auto t_solve = std::chrono::steady_clock::now();
      std::vector<Int_arc> iarcs(arcs.size());
      for(std::size_t i = 0; i < arcs.size(); ++i)
      {
        const Work_arc& e = arcs[i];
        Int_arc& x = iarcs[i];
        x.L = e.L; x.R = e.R;
        x.sh = to_int(st[i], k_simplex);
        x.w = w_hat[i];
        x.has_lo = std::isfinite(e.lo); x.has_up = std::isfinite(e.up);
        x.lo = x.has_lo ? to_int(e.lo, k_simplex) : 0;
        x.up = x.has_up ? to_int(e.up, k_simplex) : 0;
      }
      stats_.cost_exponent = k_simplex;
      std::vector<Int> pi;
      std::string why;
      if(multilevel(nn, std::move(iarcs), U, pi, why))
      {
        stats_.time_solve = seconds(t_solve);
        stats_.algorithm = a;
        return recover(P, sigma, nn, pi, sigma0, roots, component, face_node, face_offset, k_simplex);
      }
      // not certified (or out of the integer range of the certificate): network simplex on the whole
      if(verbose_) std::cerr << "[swn] LEMON " << algorithm_name(a) << ": " << why << "; solving with " << algorithm_name(NETWORK_SIMPLEX) << "\n";
      stats_.fallback = true;
      a = NETWORK_SIMPLEX;
    }
    int k = a == NETWORK_SIMPLEX ? k_simplex : k_scaling;
    Network net;
    build(k, net);
    stats_.time_build = seconds(t_build);

    // 6. solve, certify, fall back
    const auto t_solve = std::chrono::steady_clock::now();
    std::vector<Int> pi(nn, 0), flow;
    if(!net.cap.empty())
    {
      std::string why;
      bool ok = run(a, nn, net, pi, flow, why) && certify(net, pi, flow, why);
      if(!ok && fallback_)
      {
        const Algorithm b = a == NETWORK_SIMPLEX && has_wide_large_cost() ? COST_SCALING_PUSH : NETWORK_SIMPLEX;
        if(b != a)
        {
          if(verbose_) std::cerr << "[swn] LEMON " << algorithm_name(a) << ": " << why << "; trying " << algorithm_name(b) << "\n";
          const int kb = b == NETWORK_SIMPLEX ? k_simplex : k_scaling;
          if(kb != k) { k = kb; build(k, net); }
          std::string why2;
          ok = run(b, nn, net, pi, flow, why2) && certify(net, pi, flow, why2);
          stats_.fallback = true;
          a = b;
          if(!ok) why += "; " + std::string(algorithm_name(b)) + ": " + why2;
        }
      }
      stats_.algorithm = a;
      if(!ok) return fail("LEMON residual solver: " + why);
    }
    else
      stats_.certified = true;
    stats_.time_solve = seconds(t_solve);
    return recover(P, sigma, nn, pi, sigma0, roots, component, face_node, face_offset, k);
  }

  // 7. sigma = sigma0 + (pi - pi[root]) / 2^k on the nodes, plus the offsets of the contraction;
  //    the first gauge face of each component gets 0
  bool recover(const Residual_problem& P, std::vector<double>& sigma, std::size_t nn, const std::vector<Int>& pi,
               const std::vector<double>& sigma0, const std::vector<std::size_t>& roots,
               const std::vector<std::size_t>& component, const std::vector<std::size_t>& face_node,
               const std::vector<double>& face_offset, int k)
  {
    const std::size_t nf = P.number_of_faces;
    const double tolerance = (std::max)(tolerance_, std::ldexp(1., 1 - k));
    const auto t_recover = std::chrono::steady_clock::now();
    std::vector<double> node_sigma(nn);
    for(std::size_t v = 0; v < nn; ++v)
      node_sigma[v] = sigma0[v] + std::ldexp(double(pi[v] - pi[roots[component[v]]]), -k);
    for(std::size_t f = 0; f < nf; ++f) sigma[f] = node_sigma[face_node[f]] + face_offset[f];
    // gauge faces get 0 (the first gauge face of each component)
    std::vector<double> shift(roots.size(), 0.);
    std::vector<char> shifted(roots.size(), 0);
    for(std::size_t f : P.gauge_faces)
    {
      const std::size_t c = component[face_node[f]];
      if(shifted[c]) continue;
      shifted[c] = 1;
      shift[c] = sigma[f];
    }
    for(std::size_t f = 0; f < nf; ++f) sigma[f] -= shift[component[face_node[f]]];
    stats_.objective = P.objective(sigma);
    stats_.max_violation = P.max_violation(sigma);
    stats_.time_recover = seconds(t_recover);
    if(verbose_)
      std::cerr << "[swn] LEMON " << algorithm_name(stats_.algorithm) << (stats_.fallback ? " (fallback)" : "") << ": "
                << stats_.nodes << " nodes, " << stats_.network_arcs << " arcs (" << stats_.fixed_arcs
                << " fixed arcs contracted, " << stats_.nonzero_cost_arcs << " nonzero costs after gauge), scale 2^"
                << k << " / 2^" << stats_.capacity_exponent << ", objective " << stats_.objective << ", violation " << stats_.max_violation
                << (stats_.certified ? ", certified" : "") << "; build " << stats_.time_build << " s, solve "
                << stats_.time_solve << " s\n";
    if(!(stats_.max_violation <= tolerance))
      return fail("the residual problem is infeasible: the least-violation solution violates the bounds by " +
                  std::to_string(stats_.max_violation));
    return true;
  }

  // ---- MULTILEVEL --------------------------------------------------------------------------
  // The optimal shifts are constant over large regions and the jumps concentrate on a few curves
  // (the completed curve and the nonbounding loops), so the problem is solved on a hierarchy of
  // contracted problems: clusters of nodes joined by free arcs without jump share one shift; the
  // coarsest problem is solved whole, and each finer level only re-solves a band of nodes around
  // the jumps of the coarser answer, with the rest of each level contracted (its jumps kept). The
  // answer of the finest level is then certified on the whole problem by a circulation within the
  // subdifferentials (a maximum flow); where there is none, the barrier it returns marks where
  // to widen the band, and the band is re-solved. Everything is exact in the scaled integers.

  // a problem arc in scaled integers: J = sh + pi[L] - pi[R], cost w |J|, bounds lo <= J <= up
  struct Int_arc
  {
    std::size_t L, R;
    Int sh, w, lo, up;
    bool has_lo, has_up;
  };

  // the circulation network of a list of arcs (the layout of step 5): J = sh + pi[L] - pi[R];
  // reduced cost c + pi[tail] - pi[head]: R->L with cost x - sh is active when J > x, L->R with
  // cost sh - x when J < x
  static void make_network(const std::vector<Int_arc>& arcs, Int U, Network& net)
  {
    net = Network();
    net.tail.reserve(3 * arcs.size()); net.head.reserve(3 * arcs.size());
    net.cap.reserve(3 * arcs.size()); net.cost.reserve(3 * arcs.size());
    for(const Int_arc& e : arcs)
    {
      net.current = std::size_t(&e - arcs.data());
      const bool merge_up = e.has_up && e.up == 0, merge_lo = e.has_lo && e.lo == 0;
      net.add(e.R, e.L, e.w + (merge_up ? U : 0), -e.sh);          // w (J)_+
      net.add(e.L, e.R, e.w + (merge_lo ? U : 0), e.sh);           // w (-J)_+
      if(e.has_up && !merge_up) net.add(e.R, e.L, U, e.up - e.sh);   // U (J - up)_+
      if(e.has_lo && !merge_lo) net.add(e.L, e.R, U, e.sh - e.lo);   // U (lo - J)_+
    }
  }

  // node -> incident arcs (those for which `keep` holds)
  struct Adjacency
  {
    std::vector<std::size_t> first, arc;
    Adjacency(std::size_t n, const std::vector<Int_arc>& arcs) : Adjacency(n, arcs, [](const Int_arc&) { return true; }) {}
    template <class Keep>
    Adjacency(std::size_t n, const std::vector<Int_arc>& arcs, Keep keep) : first(n + 1, 0)
    {
      for(const Int_arc& e : arcs)
        if(keep(e)) { ++first[e.L + 1]; ++first[e.R + 1]; }
      for(std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
      arc.resize(first[n]);
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(std::size_t i = 0; i < arcs.size(); ++i)
        if(keep(arcs[i])) { arc[fill[arcs[i].L]++] = i; arc[fill[arcs[i].R]++] = i; }
    }
  };

  // what the certificates of a level keep from one to the next: the maximum flows' graphs (built by
  // the first certificate, reused by those that follow the descent steps, which only change
  // capacities), the bounds and the adjacency. Allocating them anew for every certificate cost a
  // quarter of the time on the finest level of 1.15M faces (page faults).
  struct Certificate_workspace
  {
    std::vector<Int> lower, upper, x0, supply;
    std::unique_ptr<internal::Warm_push_relabel<Int>> push_relabel;
    std::unique_ptr<internal::Boykov_kolmogorov_flow<Int>> boykov_kolmogorov;
    std::unique_ptr<Adjacency> adjacency;
  };

  struct Level
  {
    std::size_t n = 0;
    std::vector<Int_arc> arcs;
    std::vector<std::size_t> parent;      // node -> node of the next coarser level
    std::vector<std::size_t> component;   // node -> its connected component's first node
    std::vector<std::size_t> arc_parent;  // arc -> arc of the next coarser level (npos inside a cluster)
    std::vector<signed char> arc_sign;    // -1 where the coarser arc runs the other way
    std::vector<Int> x;                   // a flow within the subdifferentials at the level's answer
    // the certificates' buffers (the maximum flows fill their own parts, one thread each)
    mutable std::unique_ptr<Certificate_workspace> workspace;
  };

  static bool contractible(const Int_arc& e) { return !e.has_lo && !e.has_up && e.sh == 0; }

  // numbers the connected pieces of the nodes v with inside(v), joined by the level's arcs between
  // two such nodes: every such v with id[v] == npos gets its piece's number, counted from `first` in
  // the order of the pieces' first nodes; returns the next number
  template <class Inside>
  static std::size_t number_pieces(const Level& lv, const Adjacency& adj, Inside inside, std::vector<std::size_t>& id,
                                   std::size_t first)
  {
    std::vector<std::size_t> queue;
    std::size_t n = first;
    for(std::size_t r = 0; r < lv.n; ++r)
    {
      if(id[r] != npos || !inside(r)) continue;
      id[r] = n;
      queue.assign(1, r);
      for(std::size_t q = 0; q < queue.size(); ++q)
        for(std::size_t k = adj.first[queue[q]]; k < adj.first[queue[q] + 1]; ++k)
        {
          const Int_arc& e = lv.arcs[adj.arc[k]];
          const std::size_t y = e.L == queue[q] ? e.R : e.L;
          if(id[y] == npos && inside(y)) { id[y] = n; queue.push_back(y); }
        }
      ++n;
    }
    return n;
  }

  static void find_components(Level& lv)
  {
    const Adjacency adj(lv.n, lv.arcs);
    std::vector<std::size_t> piece(lv.n, npos);
    std::vector<std::size_t> first_node(number_pieces(lv, adj, [](std::size_t) { return true; }, piece, 0), npos);
    lv.component.resize(lv.n);
    for(std::size_t v = 0; v < lv.n; ++v)
    {
      if(first_node[piece[v]] == npos) first_node[piece[v]] = v;
      lv.component[v] = first_node[piece[v]];
    }
  }

  // clusters of at most `cap` nodes grown breadth first over contractible arcs; a node joins a
  // cluster only if all its arcs into the cluster are contractible (then every jump inside the
  // cluster is 0 when its nodes share one shift). Returns the number of clusters.
  static std::size_t cluster_nodes(const Level& lv, std::size_t cap, std::vector<std::size_t>& cluster)
  {
    const Adjacency adj(lv.n, lv.arcs);
    cluster.assign(lv.n, npos);
    std::size_t nc = 0;
    std::vector<std::size_t> members;
    for(std::size_t seed = 0; seed < lv.n; ++seed)
    {
      if(cluster[seed] != npos) continue;
      const std::size_t c = nc++;
      cluster[seed] = c;
      members.assign(1, seed);
      for(std::size_t q = 0; q < members.size() && members.size() < cap; ++q)
        for(std::size_t k = adj.first[members[q]]; k < adj.first[members[q] + 1] && members.size() < cap; ++k)
        {
          const Int_arc& e = lv.arcs[adj.arc[k]];
          const std::size_t y = e.L == members[q] ? e.R : e.L;
          if(cluster[y] != npos || !contractible(e)) continue;
          bool ok = true;
          for(std::size_t j = adj.first[y]; j < adj.first[y + 1] && ok; ++j)
          {
            const Int_arc& f = lv.arcs[adj.arc[j]];
            ok = cluster[f.L == y ? f.R : f.L] != c || contractible(f);
          }
          if(!ok) continue;
          cluster[y] = c;
          members.push_back(y);
        }
    }
    return nc;
  }

  // the next coarser level: clusters become nodes; arcs inside a cluster vanish (their jump is 0),
  // parallel contractible arcs merge (their weights add)
  static Level coarsen(Level& lv, std::size_t nc)
  {
    Level next;
    next.n = nc;
    lv.arc_parent.assign(lv.arcs.size(), npos);
    lv.arc_sign.assign(lv.arcs.size(), 1);
    std::vector<std::size_t> free_arcs;   // fine arcs that become contractible coarse arcs
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const Int_arc& e = lv.arcs[i];
      const std::size_t L = lv.parent[e.L], R = lv.parent[e.R];
      if(L == R) continue;
      if(contractible(e))
      {
        if(L > R) lv.arc_sign[i] = -1;   // w |pi[L] - pi[R]| is symmetric
        free_arcs.push_back(i);
      }
      else
      {
        lv.arc_parent[i] = next.arcs.size();
        next.arcs.push_back(e);
        next.arcs.back().L = L;
        next.arcs.back().R = R;
      }
    }
    auto key = [&](std::size_t i) {
      const std::size_t L = lv.parent[lv.arcs[i].L], R = lv.parent[lv.arcs[i].R];
      return std::make_pair((std::min)(L, R), (std::max)(L, R));
    };
    std::sort(free_arcs.begin(), free_arcs.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    for(std::size_t i = 0; i < free_arcs.size();)
    {
      const auto k = key(free_arcs[i]);
      Int_arc x = lv.arcs[free_arcs[i]];
      x.L = k.first;
      x.R = k.second;
      x.w = 0;
      for(; i < free_arcs.size() && key(free_arcs[i]) == k; ++i)
      {
        x.w += lv.arcs[free_arcs[i]].w;
        lv.arc_parent[free_arcs[i]] = next.arcs.size();
      }
      next.arcs.push_back(x);
    }
    find_components(next);
    return next;
  }

  // the flow of a coarser level carried to the arcs of this one: a bundle's flow is shared in
  // proportion to the weights (so |x| <= w when the bundle's |X| <= its weight; the units lost to
  // rounding go to arcs with room left, so that the shares add up to X exactly), then routed inside
  // each cluster and region of the coarser levels on large levels (balance_inside_regions())
  static void prolong_flow(Level& lv, const Level& coarse)
  {
    lv.x.assign(lv.arcs.size(), 0);
    std::vector<Int> given(coarse.arcs.size(), 0);   // the part of each coarse flow shared so far
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const std::size_t a = lv.arc_parent[i];
      if(a == npos) continue;
      const Int X = lv.arc_sign[i] * coarse.x[a];
      if(contractible(lv.arcs[i]) && coarse.arcs[a].w > 0)
        lv.x[i] = Int(Wide(X) * Wide(lv.arcs[i].w) / Wide(coarse.arcs[a].w));
      else
        lv.x[i] = X;
      given[a] += lv.arc_sign[i] * lv.x[i];
    }
    // the rounding remainders (fewer units than the bundle has arcs), one unit per arc with room
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const std::size_t a = lv.arc_parent[i];
      if(a == npos || given[a] == coarse.x[a]) continue;
      const Int unit = lv.arc_sign[i] * (coarse.x[a] > given[a] ? 1 : -1);   // in the fine arc's sense
      const Int to = lv.x[i] + unit;
      if(contractible(lv.arcs[i]) && (to > lv.arcs[i].w || to < -lv.arcs[i].w)) continue;
      lv.x[i] = to;
      given[a] += lv.arc_sign[i] * unit;
    }
  }

  // the shares of the bundles leave imbalances at the nodes of each cluster that add up to the
  // coarse node's (0: the coarse flow is a circulation); they are routed along the arcs inside the
  // cluster, whose jump is 0 (subdifferential [-w, w]), by augmenting paths, then along the arcs
  // inside the clusters of clusters (each region of a coarser level adds up to 0 as well), and so
  // on up the hierarchy, while the regions have at most 512 nodes of the level on average and the
  // searches of a region level stay within 16 arc scans per arc of the level. What remains is left
  // to the maximum flow of the certificate, which would otherwise have to route every imbalance of the
  // level. On the 1.15M-face level of benchmark/residual_solvers.md the imbalanced nodes go from
  // 584,000 to 26,000 in 1.5 s, and the first certificate took 12.5 s instead of 19-21 s (before
  // push-relabel had the gap heuristic). The budget: on a 751k-face level the searches of the 4th
  // and 5th region levels cost 196 and 302 scans per arc (2 and 4.8 s) for 21,800 -> 6,100
  // imbalanced nodes, more than they saved the certificate (residual 25.2 s; 15.3 s with the budget).
  // (Until 2026-12-03 the first certificate's flow of a level, after its band solve, was routed so
  // too, within the subdifferentials: once push-relabel had the gap heuristic, that made chain10's
  // first finest certificate slower, 3.4-3.5 s against 2.8-2.9 s, and no other case faster.)
  // Levels of fewer than set_carried_flow_routing() nodes are left to push-relabel whole.
  void balance_inside_regions(const std::vector<Level>& levels, std::size_t l, std::vector<Int>& x)
  {
    const Level& lv = levels[l];
    if(lv.n < routing_nodes_) return;
    ++stats_.routed_levels;
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<Int> excess;
    node_supply(lv, x, excess);
    auto imbalanced = [&] { return lv.n - std::size_t(std::count(excess.begin(), excess.end(), Int(0))); };
    const std::size_t before = verbose_ ? imbalanced() : 0;
    std::vector<std::size_t> region = lv.parent;
    const std::size_t work_limit = max_routing_work * lv.arcs.size();
    std::size_t depth = 0, work = 0;
    for(std::size_t c = l + 1;; ++c)   // region[v]: v's node on level c
    {
      work = route_inside_regions(lv, region, levels[c].n, excess, x, work_limit);
      ++depth;
      // regions of more than max_routing_region nodes on average, or searches over their budget:
      // the coarser regions cost more than they save the certificate
      if(work > work_limit || c + 1 >= levels.size() || lv.n > max_routing_region * levels[c + 1].n) break;
      for(std::size_t v = 0; v < lv.n; ++v) region[v] = levels[c].parent[region[v]];
    }
    if(verbose_)
      std::cerr << "[swn] multilevel: flow carried down on level " << l << ": " << before << " imbalanced nodes, "
                << imbalanced() << " after routing inside the regions of " << depth << " coarser level(s)"
                << (work > work_limit ? ", the last one stopped by its budget" : "") << " (" << seconds(t0) << " s)\n";
  }

  // augmenting paths inside each region (region[v] < nr), from every excess to the deficits
  // (breadth first, along arcs inside the region with room left: their jump is 0, so their flow
  // may lie anywhere in [-w, w]); stops once more than `work_limit` arcs were scanned. Returns the
  // arcs scanned.
  static std::size_t route_inside_regions(const Level& lv, const std::vector<std::size_t>& region, std::size_t nr,
                                   std::vector<Int>& excess, std::vector<Int>& x, std::size_t work_limit)
  {
    // the nodes of each region that have an excess, and the arcs inside the regions at each node
    std::vector<std::size_t> first(nr + 1, 0), member;
    for(std::size_t v = 0; v < lv.n; ++v)
      if(excess[v] > 0) ++first[region[v] + 1];
    for(std::size_t c = 0; c < nr; ++c) first[c + 1] += first[c];
    member.resize(first[nr]);
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(std::size_t v = 0; v < lv.n; ++v)
        if(excess[v] > 0) member[fill[region[v]]++] = v;
    }
    if(member.empty()) return 0;
    std::size_t work = 0;
    const Adjacency inside(lv.n, lv.arcs, [&](const Int_arc& e) { return region[e.L] == region[e.R] && contractible(e); });
    // room on arc i from its end `from` to the other: its flow may lie anywhere in [-w, w] (jump 0)
    auto room = [&](std::size_t i, std::size_t from) {
      const Int_arc& e = lv.arcs[i];
      return from == e.L ? e.w - x[i] : x[i] + e.w;
    };
    // a search that finds no deficit marks what it reached as dead: a set that cannot reach a deficit
    // never will (an augmenting path never enters it, so no arc out of it gains room)
    std::vector<std::size_t> pred_arc(lv.n, npos), queue;
    std::vector<char> seen(lv.n, 0), dead(lv.n, 0);
    for(std::size_t s : member)
      while(excess[s] > 0 && !dead[s])
      {
        if(work > work_limit) return work;
        // breadth-first search for a deficit in the region along arcs with room
        queue.assign(1, s);
        seen[s] = 1;
        std::size_t t = npos;
        for(std::size_t q = 0; q < queue.size() && t == npos; ++q)
        {
          const std::size_t u = queue[q];
          work += inside.first[u + 1] - inside.first[u];
          for(std::size_t j = inside.first[u]; j < inside.first[u + 1]; ++j)
          {
            const std::size_t i = inside.arc[j];
            const std::size_t y = lv.arcs[i].L == u ? lv.arcs[i].R : lv.arcs[i].L;
            if(seen[y] || dead[y] || room(i, u) <= 0) continue;
            seen[y] = 1;
            pred_arc[y] = i;
            queue.push_back(y);
            if(excess[y] < 0) { t = y; break; }
          }
        }
        for(std::size_t u : queue) { seen[u] = 0; if(t == npos) dead[u] = 1; }
        if(t == npos) break;
        Int d = (std::min)(excess[s], -excess[t]);
        for(std::size_t y = t; y != s;)
        {
          const std::size_t i = pred_arc[y];
          const std::size_t u = lv.arcs[i].L == y ? lv.arcs[i].R : lv.arcs[i].L;
          d = (std::min)(d, room(i, u));
          y = u;
        }
        for(std::size_t y = t; y != s;)
        {
          const std::size_t i = pred_arc[y];
          const std::size_t u = lv.arcs[i].L == y ? lv.arcs[i].R : lv.arcs[i].L;
          x[i] += u == lv.arcs[i].L ? d : -d;
          y = u;
        }
        excess[s] -= d;
        excess[t] += d;
      }
    return work;
  }

  // one-sided derivatives of f(J) = w |J| + U dist(J, [lo, up])
  static Int right_slope(const Int_arc& e, Int J, Int U)
  {
    Int d = J >= 0 ? e.w : -e.w;
    if(e.has_up && J >= e.up) d += U;
    if(e.has_lo && J < e.lo) d -= U;
    return d;
  }
  static Int left_slope(const Int_arc& e, Int J, Int U)
  {
    Int d = J > 0 ? e.w : -e.w;
    if(e.has_up && J > e.up) d += U;
    if(e.has_lo && J <= e.lo) d -= U;
    return d;
  }
  static Int tension(const Int_arc& e, const std::vector<Int>& pi) { return e.sh + pi[e.L] - pi[e.R]; }
  // calls f(b) once for every tension b where the cost of arc e has a kink: 0 and its bounds
  template <class F>
  static void for_each_kink(const Int_arc& e, F f)
  {
    f(Int(0));
    if(e.has_lo && e.lo != 0) f(e.lo);
    if(e.has_up && e.up != 0 && !(e.has_lo && e.up == e.lo)) f(e.up);
  }

  // network simplex on a whole (small) problem, with the exact duality certificate; x gets the
  // optimal flow of each problem arc (from L to R in the sense of the subdifferential: f'-(J) <= x
  // <= f'+(J), a circulation)
  bool solve_whole(std::size_t n, const std::vector<Int_arc>& arcs, Int U, std::vector<Int>& pi, std::vector<Int>& x,
                   std::string& why)
  {
    stats_.largest_band = (std::max)(stats_.largest_band, n);
    if(!network_simplex_with_flows(n, arcs, U, pi, x, why)) return false;
    if(!arcs.empty()) stats_.certified = has_wide;   // as certify() does
    return true;
  }

  // network simplex on `arcs` over n nodes, its optimum checked by duality (duality_holds()): the
  // potentials pi and, per arc, the flow x (R->L arcs carry x > 0). Touches no member: two threads
  // may run it at once (set_split_bands()).
  bool network_simplex_with_flows(std::size_t n, const std::vector<Int_arc>& arcs, Int U, std::vector<Int>& pi,
                                  std::vector<Int>& x, std::string& why) const
  {
    x.assign(arcs.size(), 0);
    Network net;
    make_network(arcs, U, net);
    if(net.cap.empty()) { pi.assign(n, 0); return true; }
    std::vector<Int> flow;
    if(!(run(NETWORK_SIMPLEX, n, net, pi, flow, why) && duality_holds(net, pi, flow, why))) return false;
    for(std::size_t k = 0; k < flow.size(); ++k)
    {
      const Int_arc& e = arcs[net.owner[k]];
      x[net.owner[k]] += net.tail[k] == e.R ? flow[k] : -flow[k];
    }
    return true;
  }

  // pi[v] -= pi[first node of v's component]: keeps the potentials small across refinements
  static void normalize(const Level& lv, std::vector<Int>& pi)
  {
    for(std::size_t v = 0; v < lv.n; ++v)
      if(lv.component[v] != v) pi[v] -= pi[lv.component[v]];
    for(std::size_t v = 0; v < lv.n; ++v)
      if(lv.component[v] == v) pi[v] = 0;
  }

  // re-solves, exactly, the band of nodes within `radius` arcs of a seed (and, if `around_jumps`, of
  // every nonzero jump), every connected piece of the rest being contracted to one node: the unknowns
  // are the changes of pi, so the band problem's jumps are the current tensions. An arc inside a
  // piece keeps its jump (both ends shift together).
  bool refine(Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& seed, int radius, bool around_jumps,
              bool narrow_on_curve, std::string& why)
  {
    const Adjacency adj(lv.n, lv.arcs);
    std::vector<int> dist(lv.n, -1);
    std::vector<std::size_t> queue;
    // on the curve (arcs with bounds) the jumps stay where they are from level to level, so with
    // narrow curve bands only the jumps off the curve (the completions, which move) grow a band
    const bool narrow = around_jumps && narrow_on_curve;
    auto on_curve = [](const Int_arc& e) { return e.has_lo || e.has_up; };
    if(around_jumps)
      for(const Int_arc& e : lv.arcs)
        if(tension(e, pi) != 0 && !(narrow && on_curve(e)))
        {
          if(dist[e.L] < 0) { dist[e.L] = 0; queue.push_back(e.L); }
          if(dist[e.R] < 0) { dist[e.R] = 0; queue.push_back(e.R); }
        }
    for(std::size_t v = 0; v < seed.size(); ++v)
      if(seed[v] && dist[v] < 0) { dist[v] = 0; queue.push_back(v); }
    for(std::size_t q = 0; q < queue.size(); ++q)
    {
      const std::size_t x = queue[q];
      if(dist[x] >= radius) continue;
      for(std::size_t k = adj.first[x]; k < adj.first[x + 1]; ++k)
      {
        const Int_arc& e = lv.arcs[adj.arc[k]];
        const std::size_t y = e.L == x ? e.R : e.L;
        if(dist[y] < 0) { dist[y] = dist[x] + 1; queue.push_back(y); }
      }
    }
    if(narrow)   // the faces of the jumps on the curve, without neighbours (after the search, so
                 // that they do not stop it)
      for(const Int_arc& e : lv.arcs)
        if(tension(e, pi) != 0 && on_curve(e))
        {
          if(dist[e.L] < 0) dist[e.L] = 0;
          if(dist[e.R] < 0) dist[e.R] = 0;
        }
    if(around_jumps && split_band_nodes_ > 0)
    {
      std::size_t nb = 0;
      for(int d : dist) nb += d >= 0 ? 1 : 0;
      if(nb >= split_band_nodes_)
      {
        std::vector<char> seam;
        if(solve_band_in_halves(lv, adj, dist, U, pi, seam, why))   // then the band around the cut
          return std::find(seam.begin(), seam.end(), 1) == seam.end() || refine(lv, U, pi, seam, band_radius_, false, false, why);
        if(!why.empty()) return false;
      }
    }
    // band nodes first, then one node per connected piece of the rest
    std::vector<std::size_t> id(lv.n, npos);
    std::size_t n = 0;
    for(std::size_t v = 0; v < lv.n; ++v)
      if(dist[v] >= 0) id[v] = n++;
    const std::size_t band = n;
    n = number_pieces(lv, adj, [&](std::size_t v) { return dist[v] < 0; }, id, band);
    std::vector<Int_arc> sub;
    std::vector<std::size_t> level_arc;
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const Int_arc& e = lv.arcs[i];
      if(dist[e.L] < 0 && dist[e.R] < 0) continue;   // inside a contracted piece: jump unchanged
      Int_arc x = e;
      x.L = id[e.L];
      x.R = id[e.R];
      x.sh = tension(e, pi);
      sub.push_back(x);
      level_arc.push_back(i);
    }
    std::vector<Int> delta, x;
    const auto t0 = std::chrono::steady_clock::now();
    if(!solve_whole(n, sub, U, delta, x, why)) return false;
    if(verbose_)
      std::cerr << "[swn] multilevel: band of " << band << " nodes (" << n << " with the pieces, " << sub.size()
                << " arcs) solved in " << seconds(t0) << " s\n";
    for(std::size_t v = 0; v < lv.n; ++v) pi[v] += delta[id[v]];
    // the band's optimal flow is exact on its arcs; the arcs inside the pieces keep theirs
    lv.x.resize(lv.arcs.size(), 0);
    for(std::size_t k = 0; k < sub.size(); ++k) lv.x[level_arc[k]] = x[k];
    normalize(lv, pi);
    return true;
  }

  // set_split_bands(): the band (dist >= 0) cut in two halves A and B by a breadth-first level S of
  // its largest part; S and the pieces of the outside that touch both halves keep their shifts (one
  // ground node in each half's problem); A and B, each with the pieces that touch only it, solved by
  // network simplex at once on two threads. seam: S (possibly empty). False with `why` empty if the
  // band does not split (pi and the flows unchanged), with `why` set if network simplex failed.
  bool solve_band_in_halves(Level& lv, const Adjacency& adj, const std::vector<int>& dist, Int U, std::vector<Int>& pi,
                            std::vector<char>& seam, std::string& why)
  {
    const auto t0 = std::chrono::steady_clock::now();
    auto in_band = [&](std::size_t v) { return dist[v] >= 0; };
    // the band's connected parts; the largest one cut by a breadth-first level (from a far node) so
    // that A holds about half of the band, the other parts going to B (A takes whole parts first if
    // the largest is less than half)
    std::vector<std::size_t> part(lv.n, npos);
    const std::size_t nparts = number_pieces(lv, adj, in_band, part, 0);
    std::vector<std::size_t> part_size(nparts, 0);
    std::size_t nb_total = 0;
    for(std::size_t v = 0; v < lv.n; ++v) if(in_band(v)) { ++part_size[part[v]]; ++nb_total; }
    const std::size_t largest = std::size_t(std::max_element(part_size.begin(), part_size.end()) - part_size.begin());
    std::vector<char> side(lv.n, 0);   // 1: A, 2: B, 3: ground (S or a piece touching both)
    std::size_t na = 0, nbn = 0, ns = 0;
    if(2 * part_size[largest] <= nb_total)
    {
      // whole parts, largest first into A until half
      std::vector<std::size_t> order(nparts);
      for(std::size_t p = 0; p < nparts; ++p) order[p] = p;
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return part_size[a] > part_size[b]; });
      std::vector<char> part_side(nparts, 2);
      std::size_t in_a = 0;
      for(std::size_t p : order)
        if(2 * (in_a + part_size[p]) <= nb_total + part_size[p]) { part_side[p] = 1; in_a += part_size[p]; }
      for(std::size_t v = 0; v < lv.n; ++v)
        if(in_band(v)) { side[v] = part_side[part[v]]; (side[v] == 1 ? na : nbn) += 1; }
    }
    else
    {
      std::vector<long> level(lv.n, -1);
      std::vector<std::size_t> queue;
      std::size_t start = npos;
      for(std::size_t v = 0; v < lv.n && start == npos; ++v) if(in_band(v) && part[v] == largest) start = v;
      auto bfs = [&](std::size_t root) {
        std::fill(level.begin(), level.end(), -1);
        queue.assign(1, root);
        level[root] = 0;
        for(std::size_t q = 0; q < queue.size(); ++q)
        {
          const std::size_t x = queue[q];
          for(std::size_t k = adj.first[x]; k < adj.first[x + 1]; ++k)
          {
            const Int_arc& e = lv.arcs[adj.arc[k]];
            const std::size_t y = e.L == x ? e.R : e.L;
            if(level[y] < 0 && in_band(y)) { level[y] = level[x] + 1; queue.push_back(y); }
          }
        }
        return queue.back();
      };
      bfs(bfs(start));
      const long cut = level[queue[nb_total / 2]];
      for(std::size_t v = 0; v < lv.n; ++v)
      {
        if(!in_band(v)) continue;
        if(level[v] < 0 || level[v] > cut) { side[v] = 2; ++nbn; }
        else if(level[v] < cut) { side[v] = 1; ++na; }
        else { side[v] = 3; ++ns; }
      }
    }
    if(na == 0 || nbn == 0) return false;
    // pieces of the outside
    std::vector<std::size_t> piece(lv.n, npos);
    const std::size_t np = number_pieces(lv, adj, [&](std::size_t v) { return !in_band(v); }, piece, 0);
    std::vector<char> touch(np, 0);
    for(const Int_arc& e : lv.arcs)
    {
      if(!in_band(e.L) && in_band(e.R)) touch[piece[e.L]] |= side[e.R] == 1 ? 1 : side[e.R] == 2 ? 2 : 0;
      if(!in_band(e.R) && in_band(e.L)) touch[piece[e.R]] |= side[e.L] == 1 ? 1 : side[e.L] == 2 ? 2 : 0;
    }
    // the ground: one node of each subproblem; A, B: band nodes then pieces
    std::vector<std::size_t> id(lv.n, npos);
    std::size_t cnt[3] = {0, 1, 1};   // node 0 of each subproblem is the ground
    std::vector<std::size_t> piece_id(np, npos);
    std::vector<char> piece_side(np, 3);
    for(std::size_t p = 0; p < np; ++p)
      piece_side[p] = touch[p] == 1 ? 1 : touch[p] == 2 ? 2 : 3;
    auto side_of = [&](std::size_t v) { return in_band(v) ? side[v] : piece_side[piece[v]]; };
    for(std::size_t v = 0; v < lv.n; ++v)
      if(in_band(v) && side[v] != 3) id[v] = cnt[side[v]]++;
    for(std::size_t p = 0; p < np; ++p)
      if(piece_side[p] != 3) piece_id[p] = cnt[piece_side[p]]++;
    auto node = [&](std::size_t v) -> std::size_t {
      const char s = side_of(v);
      if(s == 3) return 0;
      return in_band(v) ? id[v] : piece_id[piece[v]];
    };
    std::vector<Int_arc> sub[3];
    std::vector<std::size_t> level_arc[3];
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const Int_arc& e = lv.arcs[i];
      if(!in_band(e.L) && !in_band(e.R)) continue;   // inside a piece (or between pieces: none)
      const char sl = side_of(e.L), sr = side_of(e.R);
      if(sl == 3 && sr == 3) continue;   // fixed on both ends
      const char s = sl == 3 ? sr : sl;
      if(sl != 3 && sr != 3 && sl != sr) return false;   // cannot happen: S separates
      Int_arc x = e;
      x.L = node(e.L);
      x.R = node(e.R);
      x.sh = tension(e, pi);
      sub[int(s)].push_back(x);
      level_arc[int(s)].push_back(i);
    }
    std::vector<Int> delta[3], flow[3];
    std::string why_b;
    bool ok_b = false;
    auto solve = [&](int s, std::string& w) { return network_simplex_with_flows(cnt[s], sub[s], U, delta[s], flow[s], w); };
    std::future<void> other;
    try { other = std::async(std::launch::async, [&] { ok_b = solve(2, why_b); }); }
    catch(const std::system_error&) {}   // no second thread: one after the other
    const bool ok_a = solve(1, why);
    if(other.valid()) other.get();
    else ok_b = solve(2, why_b);
    if(!ok_a) return false;
    if(!ok_b) { why = why_b; return false; }
    for(std::size_t v = 0; v < lv.n; ++v)
    {
      const char s = side_of(v);
      if(s == 3) continue;
      pi[v] += delta[int(s)][node(v)] - delta[int(s)][0];
    }
    lv.x.resize(lv.arcs.size(), 0);
    for(int s = 1; s <= 2; ++s)
      for(std::size_t k = 0; k < sub[s].size(); ++k) lv.x[level_arc[s][k]] = flow[s][k];
    normalize(lv, pi);
    seam.assign(lv.n, 0);
    for(std::size_t v = 0; v < lv.n; ++v) if(in_band(v) && side[v] == 3) seam[v] = 1;
    stats_.largest_band = (std::max)(stats_.largest_band, (std::max)(cnt[1], cnt[2]));
    ++stats_.split_bands;
    if(verbose_)
      std::cerr << "[swn] multilevel: band in halves of " << cnt[1] << " and " << cnt[2] << " nodes (seam " << ns
                << ", pieces " << np << ") solved in " << seconds(t0) << " s\n";
    return true;
  }

  // a maximum-flow problem from the flow x0 within [lower, upper]: residual capacities both ways,
  // and the imbalance of x0 at every node (`supply`) as its terminal capacity. The arcs are added
  // the first time and only given new capacities afterwards (the graph of the level is kept).
  template <class Max_flow>
  static void load_max_flow(Max_flow& mf, const Level& lv, const std::vector<Int>& lower,
                            const std::vector<Int>& upper, const std::vector<Int>& x0, const std::vector<Int>& supply)
  {
    const bool reload = mf.number_of_arcs() == lv.arcs.size() && !lv.arcs.empty();
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)   // x = x0 + flow L->R
    {
      if(reload) mf.reset_arc(i, upper[i] - x0[i], x0[i] - lower[i]);
      else mf.add_arc(lv.arcs[i].L, lv.arcs[i].R, upper[i] - x0[i], x0[i] - lower[i]);
    }
    for(std::size_t v = 0; v < lv.n; ++v) mf.set_terminal(v, supply[v]);
  }

  // the imbalance of the flow x at every node (x leaves L and enters R); it fits in Int (checked
  // in multilevel(): every node's arcs' capacities add up to less than the largest Int)
  static void node_supply(const Level& lv, const std::vector<Int>& x, std::vector<Int>& supply)
  {
    supply.assign(lv.n, Int(0));
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      supply[lv.arcs[i].L] -= x[i];
      supply[lv.arcs[i].R] += x[i];
    }
  }

  // the barrier of a refused certificate, from the flow x it ended with (a maximum flow, or the
  // maximum preflow of push-relabel): the nodes that cannot reach, along residual arcs, a node that
  // still lacks inflow. It is the same set for every maximum flow (the source side of the minimum cut
  // nearest to the sink), so the descent does not depend on which algorithm finished the flow.
  static void mark_barrier(const Level& lv, const std::vector<Int>& lower, const std::vector<Int>& upper,
                           const std::vector<Int>& x, std::vector<char>& barrier)
  {
    std::vector<Int> inflow;
    node_supply(lv, x, inflow);
    const Adjacency& adj = level_adjacency(lv);
    std::vector<char> reaches(lv.n, 0);
    std::vector<std::size_t> queue;
    for(std::size_t v = 0; v < lv.n; ++v)
      if(inflow[v] < 0) { reaches[v] = 1; queue.push_back(v); }
    for(std::size_t q = 0; q < queue.size(); ++q)
    {
      const std::size_t v = queue[q];
      for(std::size_t k = adj.first[v]; k < adj.first[v + 1]; ++k)
      {
        const std::size_t i = adj.arc[k];
        const Int_arc& e = lv.arcs[i];
        // u reaches v if the residual arc u -> v has capacity: L -> R while x < upper, R -> L while x > lower
        const std::size_t u = e.R == v ? e.L : e.R;
        const bool open = e.R == v ? x[i] < upper[i] : x[i] > lower[i];
        if(open && !reaches[u]) { reaches[u] = 1; queue.push_back(u); }
      }
    }
    barrier.assign(lv.n, 0);
    for(std::size_t v = 0; v < lv.n; ++v) barrier[v] = reaches[v] ? 0 : 1;
  }

  // the adjacency of a level, built once and kept with its certificates' workspace
  static const Adjacency& level_adjacency(const Level& lv)
  {
    Certificate_workspace& ws = *lv.workspace;
    if(!ws.adjacency) ws.adjacency.reset(new Adjacency(lv.n, lv.arcs));
    return *ws.adjacency;
  }

  // Boykov-Kolmogorov (Boost.Graph) from the flow x, which it completes; true if balanced. Throws
  // internal::Max_flow_stopped (x unchanged) if `stop` is raised first.
  static bool boykov_kolmogorov(const Level& lv, const std::vector<Int>& lower, const std::vector<Int>& upper,
                                std::vector<Int>& x, const std::vector<Int>& supply, const std::atomic<bool>* stop)
  {
    std::unique_ptr<internal::Boykov_kolmogorov_flow<Int>>& bk = lv.workspace->boykov_kolmogorov;
    if(!bk) bk.reset(new internal::Boykov_kolmogorov_flow<Int>(lv.n));
    load_max_flow(*bk, lv, lower, upper, x, supply);
    bool balanced = false;
    try { balanced = bk->run(stop); }
    catch(const internal::Max_flow_stopped&) { throw; }   // the graph stays valid
    catch(...) { bk.reset(); throw; }                     // out of memory, say: built anew next time
    for(std::size_t i = 0; i < x.size(); ++i) x[i] += bk->flow(i);
    return balanced;
  }

  // push-relabel (internal::Warm_push_relabel) from the flow x0 within its budget, stopped early if
  // `stop` is raised: x gets the flow it ends with and, on a CUT, `barrier` the nodes that cannot
  // reach a deficit (the set mark_barrier() finds)
  typename internal::Warm_push_relabel<Int>::Outcome
  push_relabel(const Level& lv, const std::vector<Int>& lower, const std::vector<Int>& upper, const std::vector<Int>& x0,
               const std::vector<Int>& supply, std::vector<Int>& x, std::vector<char>& barrier,
               const std::atomic<bool>* stop) const
  {
    typedef internal::Warm_push_relabel<Int> Push_relabel;
    std::unique_ptr<Push_relabel>& pr = lv.workspace->push_relabel;
    if(!pr) pr.reset(new Push_relabel(lv.n));
    load_max_flow(*pr, lv, lower, upper, x0, supply);
    typename Push_relabel::Outcome outcome;
    try { outcome = pr->run(push_relabel_work_limit(lv), stop); }
    catch(...) { pr.reset(); throw; }
    x = x0;
    for(std::size_t i = 0; i < x.size(); ++i) x[i] += pr->flow(i);
    if(outcome == Push_relabel::CUT)
      for(std::size_t v = 0; v < lv.n; ++v) barrier[v] = pr->source_side(v) ? 1 : 0;
    return outcome;
  }

  // the work budget of push-relabel on a level, in arc scans: set_max_flow_budget() per element
  std::size_t push_relabel_work_limit(const Level& lv) const
  {
    const double budget = push_relabel_budget_ * double(lv.n + 2 * lv.arcs.size());
    return push_relabel_budget_ < 0 || budget >= 1e18 ? (std::numeric_limits<std::size_t>::max)() : std::size_t(budget);
  }

  // push-relabel (this thread, within its budget) and Boykov-Kolmogorov (a second thread) on the
  // same maximum flow from x0; the first to finish raises the flag that stops the other. x gets the
  // winner's flow and `balanced` its answer. False if there was no winner (no second thread could
  // be started, or Boykov-Kolmogorov failed while push-relabel went over its budget).
  bool race_max_flows(const Level& lv, const std::vector<Int>& lower, const std::vector<Int>& upper,
                      const std::vector<Int>& x0, const std::vector<Int>& supply, std::vector<Int>& x, bool& balanced,
                      std::vector<char>& barrier, bool& barrier_marked)
  {
    typedef internal::Warm_push_relabel<Int> Push_relabel;
    std::atomic<bool> done(false);
    std::vector<Int> x_bk;
    bool bk_balanced = false, bk_won = false;
    const auto t0 = std::chrono::steady_clock::now();
    std::future<void> bk;
    try
    {
      bk = std::async(std::launch::async, [&] {
        try
        {
          std::vector<Int> flow = x0;
          const bool b = boykov_kolmogorov(lv, lower, upper, flow, supply, &done);
          if(!done.exchange(true)) { bk_won = true; bk_balanced = b; x_bk.swap(flow); }
        }
        catch(const internal::Max_flow_stopped&) {}
        catch(const std::exception&) {}   // out of memory, say: push-relabel finishes on its own
      });
    }
    catch(const std::system_error&) { return false; }
    typename Push_relabel::Outcome outcome = Push_relabel::STOPPED;
    bool pr_won = false;
    {
      // if push-relabel throws (memory), the other thread is stopped before the exception leaves
      struct Stop_on_throw
      {
        std::atomic<bool>& flag;
        bool armed;
        ~Stop_on_throw() { if(armed) flag.store(true); }
      } stop_on_throw{done, true};
      std::vector<Int> x_pr;
      std::vector<char> cut(lv.n, 0);
      // over its budget, push-relabel leaves the memory bandwidth to Boykov-Kolmogorov and waits
      outcome = push_relabel(lv, lower, upper, x0, supply, x_pr, cut, &done);
      stop_on_throw.armed = false;
      if(outcome != Push_relabel::STOPPED && outcome != Push_relabel::OVER_BUDGET && !done.exchange(true))
      {
        pr_won = true;
        x.swap(x_pr);
        barrier.swap(cut);
      }
    }
    bk.get();   // joins
    if(!pr_won && !bk_won) return false;
    if(pr_won) { balanced = outcome == Push_relabel::BALANCED; barrier_marked = outcome == Push_relabel::CUT; }
    else { balanced = bk_balanced; x.swap(x_bk); ++stats_.max_flow_fallbacks; }
    if(verbose_)
      std::cerr << "[swn] multilevel: " << (pr_won ? "push-relabel" : "Boykov-Kolmogorov") << " finished first, in "
                << seconds(t0) << " s\n";
    return true;
  }

  // optimality of pi on a level: true if a circulation x with f'-(J) <= x <= f'+(J) exists on every
  // arc; otherwise false, with the nodes of a barrier (a set whose shifts can all rise with a
  // negative slope of the cost) marked in `barrier`. As a maximum flow started from the level's flow
  // lv.x clamped to the bounds (the flows carried down the hierarchy are nearly balanced), by
  // push-relabel (internal::Warm_push_relabel), fast while the imbalances are local, and by
  // Boykov-Kolmogorov (Boost.Graph), faster on some large certificates:
  //  * after a descent step on levels of at least concurrent_max_flow_nodes_ nodes (if
  //    set_concurrent_max_flows()), both run at once on two threads from the same flow, and the
  //    first to finish stops the other;
  //  * otherwise push-relabel within a work budget, then Boykov-Kolmogorov from where it stopped.
  // The barrier does not depend on which one finished (mark_barrier()). lv.x gets the flow found
  // (balanced on success).
  bool repair_flow(Level& lv, Int U, const std::vector<Int>& pi, std::vector<char>& barrier, bool after_descent)
  {
    const std::size_t n = lv.n, na = lv.arcs.size();
    if(!lv.workspace) lv.workspace.reset(new Certificate_workspace());
    Certificate_workspace& ws = *lv.workspace;
    std::vector<Int>& lower = ws.lower;
    std::vector<Int>& upper = ws.upper;
    std::vector<Int>& x0 = ws.x0;
    lower.resize(na); upper.resize(na); x0.resize(na);
    for(std::size_t i = 0; i < na; ++i)
    {
      const Int_arc& e = lv.arcs[i];
      const Int J = tension(e, pi);
      lower[i] = left_slope(e, J, U);
      upper[i] = right_slope(e, J, U);
      const Int start = i < lv.x.size() ? lv.x[i] : 0;
      x0[i] = (std::min)(upper[i], (std::max)(lower[i], start));
    }
    // the band solved on the level changed the flows on its arcs, which leaves imbalances at the
    // border of the pieces: push-relabel settles them (see balance_inside_regions() on why they are
    // no longer routed inside the regions first)
    node_supply(lv, x0, ws.supply);
    barrier.assign(n, 0);
    ++stats_.certificates;
    typedef internal::Warm_push_relabel<Int> Push_relabel;
    const auto t_pr = std::chrono::steady_clock::now();
    std::vector<Int>& x = lv.x;   // the flow found replaces the level's
    bool balanced = false, barrier_marked = false;
    if(!(concurrent_max_flows_ && after_descent && n >= concurrent_max_flow_nodes_ && push_relabel_budget_ != 0 &&
         race_max_flows(lv, lower, upper, x0, ws.supply, x, balanced, barrier, barrier_marked)))
    {
      typename Push_relabel::Outcome outcome = Push_relabel::OVER_BUDGET;
      x = x0;
      if(push_relabel_budget_ != 0)
      {
        outcome = push_relabel(lv, lower, upper, x0, ws.supply, x, barrier, nullptr);
        balanced = outcome == Push_relabel::BALANCED;
        barrier_marked = outcome == Push_relabel::CUT;
      }
      if(outcome == Push_relabel::OVER_BUDGET)
      {
        if(push_relabel_budget_ != 0) ++stats_.max_flow_fallbacks;
        const auto t_bk = std::chrono::steady_clock::now();
        std::vector<Int> supply;   // of push-relabel's preflow
        node_supply(lv, x, supply);
        balanced = boykov_kolmogorov(lv, lower, upper, x, supply, nullptr);
        if(verbose_)
          std::cerr << "[swn] multilevel: push-relabel over budget after " << std::chrono::duration<double>(t_bk - t_pr).count()
                    << " s, Boykov-Kolmogorov " << seconds(t_bk) << " s\n";
      }
    }
    if(!balanced && !barrier_marked) mark_barrier(lv, lower, upper, x, barrier);
    if(!balanced) return false;
    // check the certificate independently: bounds and conservation of the flow
    for(std::size_t i = 0; i < na; ++i)
      if(x[i] < lower[i] || x[i] > upper[i]) return false;
    std::vector<Int>& balance = ws.supply;
    node_supply(lv, x, balance);
    for(const Int b : balance)
      if(b != 0) return false;
    return true;
  }

  // one step of steepest descent along the barrier S of a refused certificate (the source side of
  // a minimum cut: raising pi on S lowers the cost, at the steepest rate among all sets), piece by
  // piece. No arc joins two connected pieces of S, so the cost along their shifts is a sum of one
  // convex piecewise-linear function per piece, and every piece that holds excess the maximum flow
  // could not route has a negative slope: each such piece rises by its own t > 0, an exact line
  // search over the breakpoints of the arcs that cross its border (t is the breakpoint where the
  // slope stops being negative). The same holds for the pieces of the complement of S, lowered
  // (the same tensions as raising S, up to the gauge), where the pieces that still lack inflow have
  // a negative slope; the step takes the side whose pieces lower the cost more. One common t for
  // all of S, stopped by the nearest breakpoint of any piece, took 32 steps (21 on the finest level)
  // on a problem of 1.15M faces where this takes 10 (6; benchmark/residual_solvers.md). The cost
  // drops strictly; false (pi unchanged) if no piece has a negative slope at t = 0. `decrease` gets
  // the (scaled) decrease of the cost.
  bool descend_along_barrier(const Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& S, double& decrease)
  {
    Descent d;
    descent_by_pieces(lv, U, pi, S, d);
    const double up = d.decrease[1], down = d.decrease[0];
    if(!(up > 0) && !(down > 0)) return false;
    const char side = up >= down ? 1 : 0;
    const bool raise = side == 1;
    decrease = raise ? up : down;
    stats_.descent_pieces += d.moved[side];
    stats_.descent_lowerings += raise ? 0 : 1;
    if(verbose_)
      std::cerr << "[swn] multilevel: " << (raise ? "barrier" : "its complement") << " in " << d.pieces[side] << " piece(s), "
                << d.moved[side] << " " << (raise ? "raised" : "lowered") << " (decrease " << (raise ? up : down)
                << ", the other side " << (raise ? down : up) << ")\n";
    for(std::size_t v = 0; v < lv.n; ++v)
      if(S[v] == side) pi[v] += raise ? d.step[d.piece[v]] : -d.step[d.piece[v]];
    return true;
  }

  // one step along d = 1_A + 1_B, the sum of the last two barriers, when the descent zigzags
  // between them (the valley between two alternating cuts): pi rises by t on A and B and by 2t on
  // their intersection, with the exact line search over the kinks of the arcs whose tension moves
  // (by (d[L] - d[R]) t). False (pi unchanged) if the cost does not drop for any t >= 1.
  bool descend_along_two_barriers(const Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& A,
                                  const std::vector<char>& B, double& decrease) const
  {
    std::vector<std::pair<Wide, Wide>> kinks;   // (2t, rise of the slope in t)
    Wide slope = 0;
    for(const Int_arc& e : lv.arcs)
    {
      const int r = (A[e.L] + B[e.L]) - (A[e.R] + B[e.R]);
      if(r == 0) continue;
      const Int J = tension(e, pi);
      slope += r > 0 ? Wide(r) * Wide(right_slope(e, J, U)) : Wide(r) * Wide(left_slope(e, J, U));
      for_each_kink(e, [&](Int b)
      {
        const Wide t2 = 2 * (Wide(b) - Wide(J)) / r;   // exact: r is +-1 or +-2
        if(t2 > 0) kinks.emplace_back(t2, Wide(r > 0 ? r : -r) * (Wide(right_slope(e, b, U)) - Wide(left_slope(e, b, U))));
      });
    }
    if(slope >= 0) return false;
    std::sort(kinks.begin(), kinks.end());
    Wide d = slope, t2 = 0;
    decrease = 0;
    for(std::size_t k = 0; k < kinks.size() && d < 0; ++k)
    {
      decrease -= double(d) * double(kinks[k].first - t2) / 2;
      t2 = kinks[k].first;
      d += kinks[k].second;
    }
    const Int t = Int(t2 / 2);   // the slope is negative up to t2 / 2, so any integer t in [1, t2 / 2] lowers the cost
    if(t < 1) return false;
    for(std::size_t v = 0; v < lv.n; ++v) pi[v] += Int(A[v] + B[v]) * t;
    return true;
  }

  // the line searches of descend_along_barrier() on both sides of S at once
  struct Descent
  {
    std::vector<std::size_t> piece;   // node -> the smallest node of its piece (of S, or of its complement)
    std::vector<Int> step;            // by piece (its smallest node): how far it moves (0: it does not)
    double decrease[2] = {0, 0};      // of the (scaled) cost, approximately: [1] raising S's pieces, [0] lowering the complement's
    std::size_t pieces[2] = {0, 0};   // the pieces of the complement [0] and of S [1]
    std::size_t moved[2] = {0, 0};    // those that move
  };

  // the exact line search of descend_along_barrier() on every connected piece of S (raised) and of
  // its complement (lowered), from one pass over the arcs: the pieces by union-find along the arcs
  // that do not cross S, the slopes and breakpoints from the arcs that do. Raising S and lowering
  // its complement move the tension of a crossing arc the same way (up if its L is in S), so each
  // crossing arc adds the same slope and breakpoints to the piece at either end. (Two breadth-first
  // searches and two passes over the arcs, one per side, were a tenth of the residual on a case of
  // 46k faces with 22 descent steps.)
  void descent_by_pieces(const Level& lv, Int U, const std::vector<Int>& pi, const std::vector<char>& S, Descent& d) const
  {
    internal::Union_find sets(lv.n);
    std::vector<std::size_t> crossing;
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const Int_arc& e = lv.arcs[i];
      if(S[e.L] != S[e.R]) crossing.push_back(i);
      else sets.unite(e.L, e.R);
    }
    std::vector<std::size_t>& root = d.piece;
    root.resize(lv.n);
    for(std::size_t v = 0; v < lv.n; ++v)
    {
      root[v] = sets.find(v);
      if(root[v] == v) ++d.pieces[S[v] ? 1 : 0];
    }
    struct Kink
    {
      std::size_t piece;
      Int t;       // 0: the slope of the piece at t = 0
      Wide rise;   // of the slope at t (at t = 0: the slope)
      bool operator<(const Kink& o) const { return piece != o.piece ? piece < o.piece : t < o.t; }
    };
    std::vector<Kink> kinks;
    for(const std::size_t i : crossing)
    {
      const Int_arc& e = lv.arcs[i];
      const Int J = tension(e, pi);
      const bool rises = S[e.L] != 0;   // J = sh + pi[L] - pi[R]
      const Wide slope = rises ? Wide(right_slope(e, J, U)) : -Wide(left_slope(e, J, U));
      const std::size_t ends[2] = {root[e.L], root[e.R]};   // one piece of S, one of its complement
      for(const std::size_t c : ends) kinks.push_back(Kink{c, 0, slope});
      // the kinks of the arc's cost (at 0 and at the bounds) ahead of J, the same for both pieces
      for_each_kink(e, [&](Int b)
      {
        const Int t = rises ? b - J : J - b;
        if(t <= 0) return;
        const Wide rise = Wide(right_slope(e, b, U)) - Wide(left_slope(e, b, U));
        for(const std::size_t c : ends) kinks.push_back(Kink{c, t, rise});
      });
    }
    std::sort(kinks.begin(), kinks.end());
    d.step.assign(lv.n, 0);
    for(std::size_t k = 0; k < kinks.size();)
    {
      const std::size_t c = kinks[k].piece;
      Wide slope = 0;
      for(; k < kinks.size() && kinks[k].piece == c && kinks[k].t == 0; ++k) slope += kinks[k].rise;
      Wide dv = slope;
      Int t = 0;
      double gain = 0;
      for(; k < kinks.size() && kinks[k].piece == c; ++k)
      {
        if(dv >= 0) continue;
        gain -= double(dv) * double(kinks[k].t - t);
        t = kinks[k].t;
        dv += kinks[k].rise;
      }
      if(slope < 0 && t > 0)
      {
        const int side = S[c] ? 1 : 0;
        d.step[c] = t;
        d.decrease[side] += gain;
        ++d.moved[side];
      }
    }
  }

  bool multilevel(std::size_t nn, std::vector<Int_arc> arcs, Int U, std::vector<Int>& pi, std::string& why)
  {
    std::vector<Level> levels(1);
    levels[0].n = nn;
    levels[0].arcs = std::move(arcs);
    find_components(levels[0]);
    {
      // the maximum flow's capacities (up to 2 (U + w) per arc) and supplies (their sums at a node)
      // must fit in 63 bits
      const Adjacency adj(nn, levels[0].arcs);
      std::size_t max_degree = 0;
      for(std::size_t v = 0; v < nn; ++v) max_degree = (std::max)(max_degree, adj.first[v + 1] - adj.first[v]);
      if(Wide(max_degree + 1) * (Wide(U) + Wide(U)) >= Wide((std::numeric_limits<Int>::max)()))
      { why = "a node has too many arcs for the certificate's integer range"; return false; }
    }
    while(levels.back().n > coarsest_nodes_)
    {
      std::vector<std::size_t> cluster;
      const std::size_t nc = cluster_nodes(levels.back(), cluster_size_, cluster);
      if(10 * nc > 8 * levels.back().n) break;   // coarsening stalls
      levels.back().parent = std::move(cluster);
      Level next = coarsen(levels.back(), nc);
      levels.push_back(std::move(next));
    }
    stats_.levels = levels.size();
    if(!solve_whole(levels.back().n, levels.back().arcs, U, pi, levels.back().x, why)) return false;
    if(levels.size() == 1) return true;   // certified by the duality of network simplex
    normalize(levels.back(), pi);
    const std::vector<char> no_seed;
    const bool narrow = levels.front().n <= narrow_curve_band_nodes_;   // set_narrow_curve_bands()
    for(std::size_t l = levels.size() - 1; l-- > 0;)
    {
      std::vector<Int> fine(levels[l].n);
      for(std::size_t v = 0; v < levels[l].n; ++v) fine[v] = pi[levels[l].parent[v]];
      pi.swap(fine);
      prolong_flow(levels[l], levels[l + 1]);
      balance_inside_regions(levels, l, levels[l].x);
      if(!refine(levels[l], U, pi, no_seed, l == 0 ? finest_band_radius_ : band_radius_, true, narrow, why)) return false;
      std::vector<Int>().swap(levels[l + 1].x);
      levels[l + 1].workspace.reset();
      // every level: descent steps along the barriers of refused certificates; then, on the
      // finest level only, bands around the barriers until the certificate holds (band refinements
      // on the coarse levels did not pay off)
      const std::size_t rounds = l == 0 ? max_refinements_ : 0;
      if(certify_level(levels, l, U, pi, rounds, why)) { if(l == 0) { stats_.certified = true; return true; } }
      else if(!why.empty()) return false;
    }
    why = "the multilevel answer was not certified after " + std::to_string(max_refinements_) + " refinements";
    return false;
  }

  // repairs the flow of level l; while the certificate is refused, takes up to descent_steps_
  // steepest-descent steps along its barriers, then re-solves bands around the barriers, at most
  // `rounds` times; true if the flow is a certificate of optimality on the level. `why` is set on
  // errors only.
  bool certify_level(std::vector<Level>& levels, std::size_t l, Int U, std::vector<Int>& pi, std::size_t rounds,
                     std::string& why)
  {
    Level& lv = levels[l];
    std::vector<char> barrier;
    std::size_t descents = 0, round = 0, repeats = 0;
    double decrease = 0, previous[2] = {-1, -1};   // of this step and of the two before
    std::vector<char> previous_barrier;
    bool after_descent = false;
    for(;;)
    {
      const auto t0 = std::chrono::steady_clock::now();
      const bool certified = repair_flow(lv, U, pi, barrier, after_descent);
      after_descent = false;
      if(verbose_)
      {
        std::size_t nb = 0;
        for(char c : barrier) nb += c;
        std::cerr << "[swn] multilevel: level " << l << " of " << levels.size() << " (" << lv.n << " nodes), largest band "
                  << stats_.largest_band << ", certificate " << (certified ? "found" : "refused") << " in " << seconds(t0)
                  << " s" << (certified ? std::string() : ", barrier of " + std::to_string(nb) + " nodes") << "\n";
      }
      if(certified) return true;
      if(descents < descent_steps_ && repeats < zigzag_steps && descend_along_barrier(lv, U, pi, barrier, decrease))
      {
        ++descents;
        ++stats_.descent_steps;
        after_descent = true;
        // a zigzag: every step lowers the cost by what the step two before did, the descent
        // alternating between two barriers by small steps (seen on regular tori with a long gap:
        // 1000 such steps, then bands anyway); after zigzag_steps of them the bands take over
        repeats = std::abs(decrease - previous[1]) <= 1e-9 * decrease ? repeats + 1 : 0;
        previous[1] = previous[0];
        previous[0] = decrease;
        double valley = 0;
        if(repeats >= 2 && previous_barrier.size() == barrier.size() &&
           descend_along_two_barriers(lv, U, pi, barrier, previous_barrier, valley))
        {
          ++descents;
          ++stats_.descent_steps;
          repeats = 0;
          if(verbose_) std::cerr << "[swn] multilevel: a step along the last two barriers (decrease " << valley << ")\n";
        }
        previous_barrier = barrier;
        if(verbose_ && repeats == zigzag_steps)
          std::cerr << "[swn] multilevel: level " << l << ": the descent zigzags between two barriers, no more steps\n";
        continue;
      }
      if(round >= rounds) return false;
      if(l == 0) ++stats_.refinements;
      // a band around the arcs that cross the barrier only: every piece of the rest lies on one side
      // of the barrier and stays free to shift, so the descent along the barrier is within reach of
      // the band problem, which therefore lowers the objective. (Bands around every jump as well,
      // as on the first solve of a level, cost 2-10x more network simplex time for fewer rounds.)
      std::vector<char> seed(lv.n, 0);
      for(const Int_arc& e : lv.arcs)
        if(barrier[e.L] != barrier[e.R]) seed[e.L] = seed[e.R] = 1;
      const std::vector<Int> before = pi;
      if(!refine(lv, U, pi, seed, band_radius_ + int(round), false, false, why)) return false;
      ++round;
      if(pi == before)   // cannot happen in exact arithmetic: the barrier is a descent direction
      {
        why = "a refinement around the barrier of the certificate did not move the shifts";
        return false;
      }
    }
  }

  static bool has_wide_large_cost()
  {
    return has_wide && std::numeric_limits<Wide>::is_specialized && std::numeric_limits<Wide>::is_integer &&
           std::numeric_limits<Wide>::max() > Wide(std::numeric_limits<Int>::max());
  }

  template <class Solver>
  static void read_solution(const Graph& g, const Solver& solver, std::size_t nn, std::size_t narcs,
                            std::vector<Int>& pi, std::vector<Int>& flow)
  {
    pi.assign(nn, 0);
    flow.assign(narcs, 0);
    for(Graph::NodeIt v(g); v != lemon::INVALID; ++v) pi[std::size_t(g.id(v))] = solver.potential(v);
    for(Graph::ArcIt a(g); a != lemon::INVALID; ++a) flow[std::size_t(g.id(a))] = solver.flow(a);
  }

  bool run(Algorithm algorithm, std::size_t nn, const Network& net, std::vector<Int>& pi, std::vector<Int>& flow,
           std::string& why) const
  {
    Graph g;
    g.reserveNode(int(nn));
    g.reserveArc(int(net.cap.size()));
    for(std::size_t v = 0; v < nn; ++v) g.addNode();
    for(std::size_t i = 0; i < net.cap.size(); ++i) g.addArc(g.nodeFromId(int(net.tail[i])), g.nodeFromId(int(net.head[i])));
    Graph::ArcMap<Int> cap(g), cost(g);
    for(Graph::ArcIt a(g); a != lemon::INVALID; ++a)
    {
      cap[a] = net.cap[std::size_t(g.id(a))];
      cost[a] = net.cost[std::size_t(g.id(a))];
    }
    if(algorithm == NETWORK_SIMPLEX)
    {
      lemon::NetworkSimplex<Graph, Int, Int> ns(g);
      ns.upperMap(cap).costMap(cost);
      const auto status = ns.run(lemon::NetworkSimplex<Graph, Int, Int>::BLOCK_SEARCH);
      if(status != lemon::NetworkSimplex<Graph, Int, Int>::OPTIMAL)
      {
        why = std::string(algorithm_name(algorithm)) + " did not find an optimum (status " + std::to_string(int(status)) + ")";
        return false;
      }
      read_solution(g, ns, nn, net.cap.size(), pi, flow);
      return true;
    }
    return run_cost_scaling<Wide>(g, cap, cost, algorithm, nn, net.cap.size(), pi, flow, why);
  }

  template <class Large>
  static bool run_cost_scaling(const Graph& g, const Graph::ArcMap<Int>& cap, const Graph::ArcMap<Int>& cost,
                               Algorithm algorithm, std::size_t nn, std::size_t narcs, std::vector<Int>& pi,
                               std::vector<Int>& flow, std::string& why)
  {
    if constexpr(std::numeric_limits<Large>::is_integer)
    {
      typedef typename lemon::CostScaling<Graph, Int, Int>::template SetLargeCost<Large>::Create CS;
      CS cs(g);
      cs.upperMap(cap).costMap(cost);
      const typename CS::Method method = algorithm == COST_SCALING_PUSH      ? CS::PUSH
                                         : algorithm == COST_SCALING_AUGMENT ? CS::AUGMENT
                                                                             : CS::PARTIAL_AUGMENT;
      const typename CS::ProblemType status = cs.run(method, 16);
      if(status != CS::OPTIMAL)
      {
        why = std::string(algorithm_name(algorithm)) + " did not find an optimum (status " + std::to_string(int(status)) + ")";
        return false;
      }
      read_solution(g, cs, nn, narcs, pi, flow);
      return true;
    }
    else
    {
      (void)g; (void)cap; (void)cost; (void)algorithm; (void)nn; (void)narcs; (void)pi; (void)flow;
      why = "cost scaling needs a 128-bit integer type";
      return false;
    }
  }

  // exact duality certificate of the scaled circulation: the flow is a feasible circulation and
  // sum cap * max(0, -reduced cost) (the penalized tension objective of pi) == -sum cost * flow
  bool certify(const Network& net, const std::vector<Int>& pi, const std::vector<Int>& flow, std::string& why)
  {
    stats_.certified = false;
    if(!duality_holds(net, pi, flow, why)) return false;
    stats_.certified = has_wide;
    return true;
  }

  // the flow is a circulation within the capacities, and (where the compiler has 128-bit integers)
  // its cost equals the dual objective of pi: both optimal
  static bool duality_holds(const Network& net, const std::vector<Int>& pi, const std::vector<Int>& flow, std::string& why)
  {
    std::vector<Wide> balance(pi.size(), Wide(0));
    Wide primal = 0, dual = 0;
    for(std::size_t i = 0; i < net.cap.size(); ++i)
    {
      const Int x = flow[i];
      if(x < 0 || x > net.cap[i]) { why = "the flow violates a capacity"; return false; }
      balance[net.tail[i]] -= Wide(x);
      balance[net.head[i]] += Wide(x);
      const Wide rc = Wide(net.cost[i]) + Wide(pi[net.tail[i]]) - Wide(pi[net.head[i]]);
      if(rc < 0) primal -= Wide(net.cap[i]) * rc;
      dual += Wide(net.cost[i]) * Wide(x);
    }
    for(const Wide& b : balance)
      if(b != 0) { why = "the flow is not a circulation"; return false; }
    if(has_wide && primal != -dual)
    {
      why = "the duality certificate failed (the potentials are not optimal)";
      return false;
    }
    return true;
  }

  static constexpr std::size_t npos = std::size_t(-1);
  static constexpr std::size_t max_routing_region = 512;   // balance_inside_regions()
  static constexpr std::size_t max_routing_work = 16;      // balance_inside_regions(): arc scans per arc and region level
  // Beyond 2^42 the scaled jumps start to carry the rounding noise of the doubles (the gauge-fixed
  // jumps are sums of differences of values of order 1..100, whose ulp is 2^-52..2^-46): on the
  // demo torus 155 arcs keep a nonzero cost at 2^42, 256 at 2^44, 463 at 2^46. That noise only
  // makes network simplex slower.
  static constexpr int max_cost_exponent = 42;

  Algorithm algorithm_;
  std::size_t coarsest_nodes_ = 2000, cluster_size_ = 16, max_refinements_ = 16;
  int band_radius_ = 3;
  double push_relabel_budget_ = 200;
  bool concurrent_max_flows_ = true;
  std::size_t split_band_nodes_ = 5000;
  std::size_t routing_nodes_ = 100000;
  std::size_t concurrent_max_flow_nodes_ = 500000;
  std::size_t narrow_curve_band_nodes_ = 1000000;
  std::size_t descent_steps_ = 1000;
  static constexpr std::size_t zigzag_steps = 16;   // steps in a row that repeat the decrease of the one two before
  int finest_band_radius_ = 8;
  bool fallback_ = false;
  bool verbose_ = false;
  double tolerance_ = 1e-9;
  std::string error_;
  Statistics stats_;
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
