// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The multilevel residual solver. The optimal shifts are constant over large regions and the jumps
// concentrate on a few curves (the completed curve and the nonbounding loops), so the problem is
// solved on a hierarchy of contracted problems: the coarsest is solved whole, and each finer level
// re-solves only a band around the jumps of the coarser answer. Every level is then certified by a
// maximum flow; where the certificate is refused, steepest-descent steps along its barriers and, on
// the finest level, bands around the barriers follow until it holds. Exact in the scaled integers.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_MULTILEVEL_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_MULTILEVEL_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/bands.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/descent.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/hierarchy.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/max_flow_certificate.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/network_simplex.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// steps in a row that repeat the decrease of the step two before: the descent zigzags between two
// barriers (seen on regular tori with a long gap, where 1000 small steps preceded the bands), and the
// bands take over
constexpr std::size_t zigzag_steps = 16;

// Certifies level l of the hierarchy: while the certificate is refused, up to descent_steps
// steepest-descent steps along its barriers, then (`rounds` times at most) bands around the barrier
// re-solved. True if the certificate holds; false with ctx.error set on errors only.
inline bool certify_level(Context& ctx, std::vector<Level>& levels, std::size_t l, Int U, std::vector<Int>& pi,
                          std::size_t rounds)
{
  Level& lv = levels[l];
  std::vector<char> barrier;
  std::size_t descents = 0, round = 0, repeats = 0;
  double decrease = 0, previous[2] = {-1, -1};   // of this step and of the two before
  for(;;)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const bool certified = certify_optimality(ctx, lv, U, pi, barrier);
    if(std::ostream* log = ctx.log())
      *log << "[swn] multilevel: level " << l << " of " << levels.size() << " (" << lv.n << " nodes), certificate "
           << (certified ? "found" : "refused") << " in " << seconds_since(t0) << " s\n";
    if(certified) return true;
    if(descents < ctx.options.descent_steps && repeats < zigzag_steps &&
       descend_along_barrier(ctx, lv, U, pi, barrier, decrease))
    {
      ++descents;
      ++ctx.stats.descent_steps;
      repeats = std::abs(decrease - previous[1]) <= 1e-9 * decrease ? repeats + 1 : 0;
      previous[1] = previous[0];
      previous[0] = decrease;
      continue;
    }
    if(round >= rounds) return false;
    if(l == 0) ++ctx.stats.refinements;
    // a band around the arcs that cross the barrier only: every piece of the rest lies on one side
    // of the barrier and stays free to shift, so the descent along the barrier is within reach of
    // the band problem, which therefore lowers the objective
    std::vector<char> seed(lv.n, 0);
    for(const Int_arc& e : lv.arcs)
      if(barrier[e.L] != barrier[e.R]) seed[e.L] = seed[e.R] = 1;
    const std::vector<Int> before = pi;
    if(!refine(ctx, lv, U, pi, seed, ctx.options.band_radius + int(round), false)) return false;
    ++round;
    if(pi == before)   // cannot happen in exact arithmetic: the barrier is a descent direction
      return ctx.fail("a refinement around the barrier of the certificate did not move the shifts");
  }
}

// The maximum flow's capacities (up to 2 (U + w) per arc) and supplies (their sums at a node) must
// fit in 63 bits; false (ctx.error set) if they may not.
inline bool fits_certificate_range(Context& ctx, std::size_t n, const std::vector<Int_arc>& arcs, Int U)
{
  std::vector<std::size_t> degree(n, 0);
  for(const Int_arc& e : arcs) { ++degree[e.L]; ++degree[e.R]; }
  const std::size_t max_degree = n == 0 ? 0 : *std::max_element(degree.begin(), degree.end());
  if(Wide(max_degree + 1) * (Wide(U) + Wide(U)) >= Wide((std::numeric_limits<Int>::max)()))
    return ctx.fail("a node has too many arcs for the certificate's integer range");
  return true;
}

// The multilevel solve of the integer problem (n nodes, arcs, penalty U): pi gets optimal
// potentials, and x (if given) the flow that certifies them. False (ctx.error set) if no certified
// optimum was found within max_refinements bands.
inline bool multilevel(Context& ctx, std::size_t n, std::vector<Int_arc> arcs, Int U, std::vector<Int>& pi,
                       std::vector<Int>* x = nullptr)
{
  if(!fits_certificate_range(ctx, n, arcs, U)) return false;
  std::vector<Level> levels = build_hierarchy(n, std::move(arcs), ctx.options);
  ctx.stats.levels = levels.size();
  if(!solve_whole(ctx, levels.back().n, levels.back().arcs, U, pi, levels.back().x)) return false;
  if(levels.size() == 1)   // certified by the duality of network simplex
  {
    if(x) x->swap(levels.back().x);
    return true;
  }
  normalize(levels.back(), pi);
  const std::vector<char> no_seed;
  const bool narrow = levels.front().n <= ctx.options.narrow_curve_band_nodes;
  for(std::size_t l = levels.size() - 1; l-- > 0;)
  {
    std::vector<Int> fine(levels[l].n);
    for(std::size_t v = 0; v < levels[l].n; ++v) fine[v] = pi[levels[l].parent[v]];
    pi.swap(fine);
    prolong_flow(levels[l], levels[l + 1]);
    balance_inside_regions(ctx, levels, l, levels[l].x);
    const int radius = (std::max)(0, l == 0 ? ctx.options.finest_band_radius : ctx.options.band_radius);
    if(!refine(ctx, levels[l], U, pi, no_seed, radius, true, narrow)) return false;
    std::vector<Int>().swap(levels[l + 1].x);
    levels[l + 1].workspace.reset();
    // bands around the barriers on the finest level only (on the coarse levels they did not pay)
    if(certify_level(ctx, levels, l, U, pi, l == 0 ? ctx.options.max_refinements : 0))
    {
      if(l == 0)
      {
        ctx.stats.certified = true;
        if(x) x->swap(levels[0].x);
        return true;
      }
    }
    else if(!ctx.error.empty()) return false;
  }
  return ctx.fail("the multilevel answer was not certified after " + std::to_string(ctx.options.max_refinements) +
                  " refinements");
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
