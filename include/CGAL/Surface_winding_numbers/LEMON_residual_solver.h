// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_H
#define CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_H

#include <CGAL/Surface_winding_numbers/LEMON_residual_solver_options.h>
#include <CGAL/Surface_winding_numbers/Residual_problem.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/integer_network.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/multilevel.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/network_simplex.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/warm_start.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersTraitsClasses

Exact solver of the residual problem (paper Eq. 11, `Residual_problem`) as a minimum-cost
circulation, with the network simplex of LEMON (<https://lemon.cs.elte.hu>, Boost Software License).

Eq. 11 minimizes a sum of convex piecewise-linear functions of the differences `sigma[left] -
sigma[right]` (a minimum-cost tension problem on the dual graph). Its linear programming dual is a
minimum-cost circulation whose optimal node potentials are an optimal `sigma`. The solver

- contracts the arcs whose two bounds are equal (the jump is fixed), and fails if the fixed jumps do
  not add up around a cycle;
- fixes the gauge of each connected component along a breadth-first spanning tree, so that only the
  arcs that close a nonzero cycle of `s` keep a nonzero cost;
- scales jumps and bounds by \f$ 2^k \f$ and the weights by \f$ 2^m \f$ and rounds them to 64-bit
  integers: \f$ k \le 42 \f$ is the largest exponent for which no node potential can exceed
  \f$ 2^{59} \f$ (jumps are then exact to \f$ 2^{-43} \approx 1.1 \cdot 10^{-13} \f$), and the
  weights add up to at most \f$ 2^{58} \f$;
- solves the circulation either by network simplex on the whole problem (`Options::NETWORK_SIMPLEX`)
  or, by default, on a hierarchy of contracted problems (`Options::MULTILEVEL`): network simplex on
  the coarsest level, then on each finer level on a band around the jumps of the coarser answer,
  every level certified optimal by a maximum flow within the subdifferentials (push-relabel, then
  Boykov-Kolmogorov from Boost.Graph beyond a work budget); where a certificate is refused, its
  minimum cut gives exact steepest-descent steps and, on the finest level, bands around the cut to
  re-solve. If the finest level is not certified after `Options::max_refinements` bands, the whole
  problem goes to network simplex (`Statistics::fallback`): the answer is always an optimum of the
  whole problem;
- checks every answer exactly: network simplex's by the duality certificate (in 128-bit integers
  where the compiler has them), the multilevel's by the balanced flow of the last certificate;
- recovers `sigma` from the potentials and shifts each component so that its face listed in
  `gauge_faces` gets 0.

`solve_residual()` returns `false`, and `error()` says why, if the problem is malformed (sizes,
indices, a negative or non-finite cost, bounds with `lower > upper`), if fixed arcs contradict each
other, if the data are too large for the integer scaling, or if the problem is infeasible (then
`sigma` holds the solution of least penalized violation, and `statistics().max_violation` tells by
how much it violates the bounds).

Speed: see `benchmark/RESULTS.md` in the source tree; on the authors' DoubleTorusWithLoops (35k faces)
it solves in a fraction of a second where GLPK's simplex takes minutes, with the same objective.
The class is not copyable: pass it with `std::ref()` to the named parameter `lp_solver`.

\cgalModels `SurfaceWindingNumbersResidualSolver`
*/
class LEMON_residual_solver
{
public:
  /// the settings (see `LEMON_residual_solver_options`)
  typedef LEMON_residual_solver_options Options;
  /// what the last solve did (see `LEMON_residual_solver_statistics`)
  typedef LEMON_residual_solver_statistics Statistics;
  /// the algorithms (see `LEMON_residual_solver_options::Algorithm`)
  typedef Options::Algorithm Algorithm;

  /// creates a solver with the given options
  explicit LEMON_residual_solver(const Options& options = Options()) { set_options(options); }
  LEMON_residual_solver(const LEMON_residual_solver&) = delete;
  LEMON_residual_solver& operator=(const LEMON_residual_solver&) = delete;

  /// a name for logs and summaries
  static const char* name() { return "lemon"; }

  /// the options of the next solves
  const Options& options() const { return ctx_.options; }
  /// sets the options of the next solves (sizes below their minimum are raised to it: at least 1
  /// coarsest node, 2 nodes per cluster, radii of 0)
  void set_options(const Options& options)
  {
    ctx_.options = options;
    Options& o = ctx_.options;
    o.coarsest_nodes = (std::max)(std::size_t(1), o.coarsest_nodes);
    o.cluster_size = (std::max)(std::size_t(2), o.cluster_size);
    o.band_radius = (std::max)(0, o.band_radius);
    o.finest_band_radius = (std::max)(0, o.finest_band_radius);
  }

  /// why the last solve failed (empty after a success)
  const std::string& error() const { return ctx_.error; }
  /// what the last solve did
  const Statistics& statistics() const { return ctx_.stats; }

  /*!
  solves `P`: writes one shift per face to `sigma` (resized to `P.number_of_faces`).
  \returns `true` on success; `false` with a reason in `error()` otherwise.
  */
  bool solve_residual(const Residual_problem& P, std::vector<double>& sigma)
  {
    return solve_residual(P, sigma, ctx_.options.concurrent);
  }

  /*!
  solves `P` as `solve_residual(P, sigma)` does, on the calling thread only if `concurrent` is `false`
  (whatever `options().concurrent` says). The package's functions call this with the setting of their
  named parameter `concurrency`.
  */
  bool solve_residual(const Residual_problem& P, std::vector<double>& sigma, bool concurrent)
  {
    const bool saved = ctx_.options.concurrent;
    ctx_.options.concurrent = saved && concurrent;
    ctx_.error.clear();
    ctx_.stats = Statistics();
    bool ok = false;
    try
    {
      ok = solve(P, sigma);
    }
    catch(const std::exception& e)
    {
      ok = ctx_.fail(std::string("LEMON residual solver: ") + e.what());
    }
    ctx_.options.concurrent = saved;
    return ok;
  }

private:
  bool solve(const Residual_problem& P, std::vector<double>& sigma)
  {
    namespace RF = internal::residual_flow;
    const auto t_build = std::chrono::steady_clock::now();
    Statistics& st = ctx_.stats;
    st.faces = P.number_of_faces;
    st.arcs = P.number_of_arcs();
    sigma.assign(P.number_of_faces, 0.);
    if(!RF::check_residual_problem(P, ctx_)) return false;
    if(P.number_of_faces == 0) { st.certified = true; return true; }
    RF::Integer_problem& ip = problem_;
    if(!RF::build_integer_problem(P, ctx_, ip)) return false;
    st.time_build = RF::seconds_since(t_build);

    const auto t_solve = std::chrono::steady_clock::now();
    std::vector<RF::Int> pi, x;
    // the multilevel solver's line searches and flow shares need 128-bit integers
    st.algorithm = RF::has_wide ? ctx_.options.algorithm : Options::NETWORK_SIMPLEX;
    bool solved = false;
    if(st.algorithm == Options::MULTILEVEL && ctx_.options.warm_start && warm_.matches(ip))
    {
      solved = st.warm_started = RF::warm_solve(ctx_, ip, warm_, pi, x);
      if(solved) { st.certified = true; st.levels = 1; }
      else if(std::ostream* log = ctx_.log())
        *log << "[swn] LEMON multilevel: the warm start was not certified"
             << (ctx_.error.empty() ? "" : " (" + ctx_.error + ")") << "; solving afresh\n";
      ctx_.error.clear();
    }
    if(!solved && st.algorithm == Options::MULTILEVEL && !RF::multilevel(ctx_, ip.nodes, ip.arcs, ip.U, pi, &x))
    {
      if(std::ostream* log = ctx_.log())
        *log << "[swn] LEMON multilevel: " << ctx_.error << "; solving the whole problem by network simplex\n";
      ctx_.error.clear();
      st.fallback = true;
      st.algorithm = Options::NETWORK_SIMPLEX;
    }
    if(st.algorithm == Options::NETWORK_SIMPLEX)
    {
      if(!RF::solve_whole(ctx_, ip.nodes, ip.arcs, ip.U, pi, x))
        return ctx_.fail("LEMON residual solver: " + ctx_.error);
    }
    st.time_solve = RF::seconds_since(t_solve);
    std::unique_ptr<RF::Certificate_workspace> workspace = std::move(warm_.workspace);   // kept by a warm solve
    warm_.clear();
    if(!RF::recover_sigma(P, ip, pi, ctx_, sigma)) return false;
    if(ctx_.options.warm_start && st.certified && x.size() == ip.arcs.size())
    {
      RF::keep_answer(warm_, ip, pi, std::move(x), st.capacity_exponent);
      if(st.warm_started) warm_.workspace = std::move(workspace);   // the same graph
    }
    return true;
  }

  internal::residual_flow::Context ctx_;
  internal::residual_flow::Warm_state warm_;   // the last answer (Options::warm_start)
  internal::residual_flow::Integer_problem problem_;   // the last problem: its storage serves the next
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
