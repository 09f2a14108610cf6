// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Steepest-descent steps along the barrier of a refused certificate, with exact line searches.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_DESCENT_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_DESCENT_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// One step of steepest descent along the barrier S of a refused certificate (the source side of a
// minimum cut: raising pi on S lowers the cost at the steepest rate among all sets), piece by piece.
// No arc joins two connected pieces of S, so the cost along their shifts is a sum of one convex
// piecewise-linear function per piece, and every piece that holds excess the maximum flow could not
// route has a negative slope: each such piece rises by its own t > 0, an exact line search over the
// breakpoints of the arcs that cross its border (t is the breakpoint where the slope stops being
// negative). The pieces come from a union-find along the arcs inside S, the slopes and breakpoints
// from the arcs that leave it. The cost drops strictly; false (pi unchanged) if no piece has a
// negative slope. `decrease` gets the (scaled) decrease of the cost.
inline bool descend_along_barrier(Context& ctx, const Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& S,
                                  double& decrease)
{
  Union_find sets(lv.n);
  std::vector<std::size_t> crossing;
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)
  {
    const Int_arc& e = lv.arcs[i];
    if(S[e.L] != S[e.R]) crossing.push_back(i);
    else if(S[e.L]) sets.unite(e.L, e.R);
  }
  struct Kink
  {
    std::size_t piece;   // its smallest node
    Int t;               // 0: the slope of the piece at t = 0
    Wide rise;           // of the slope at t (at t = 0: the slope)
    bool operator<(const Kink& o) const { return piece != o.piece ? piece < o.piece : t < o.t; }
  };
  std::vector<Kink> kinks;
  for(const std::size_t i : crossing)
  {
    const Int_arc& e = lv.arcs[i];
    const Int J = tension(e, pi);
    const bool rises = S[e.L] != 0;   // J = sh + pi[L] - pi[R]
    const std::size_t piece = sets.find(rises ? e.L : e.R);
    kinks.push_back(Kink{piece, 0, rises ? Wide(right_slope(e, J, U)) : -Wide(left_slope(e, J, U))});
    // the kinks of the arc's cost (at 0 and at the bounds) ahead of J
    for_each_kink(e, [&](Int b) {
      const Int t = rises ? b - J : J - b;
      if(t > 0) kinks.push_back(Kink{piece, t, Wide(right_slope(e, b, U)) - Wide(left_slope(e, b, U))});
    });
  }
  std::sort(kinks.begin(), kinks.end());
  std::vector<Int> step(lv.n, 0);   // by piece
  std::size_t moved = 0;
  decrease = 0;
  for(std::size_t k = 0; k < kinks.size();)
  {
    const std::size_t c = kinks[k].piece;
    Wide slope = 0;
    for(; k < kinks.size() && kinks[k].piece == c && kinks[k].t == 0; ++k) slope += kinks[k].rise;
    Wide d = slope;
    Int t = 0;
    double gain = 0;
    for(; k < kinks.size() && kinks[k].piece == c; ++k)
      if(d < 0)
      {
        gain -= double(d) * double(kinks[k].t - t);
        t = kinks[k].t;
        d += kinks[k].rise;
      }
    if(slope < 0 && t > 0) { step[c] = t; ++moved; decrease += gain; }
  }
  if(moved == 0) return false;
  ctx.stats.descent_pieces += moved;
  if(std::ostream* log = ctx.log()) *log << "[swn] multilevel: descent step, " << moved << " piece(s) of the barrier raised\n";
  for(std::size_t v = 0; v < lv.n; ++v)
    if(S[v]) pi[v] += step[sets.find(v)];
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
