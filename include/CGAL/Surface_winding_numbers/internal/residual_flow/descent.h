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

// The line searches of a descent step on both sides of a barrier S.
struct Descent
{
  std::vector<std::size_t> piece;   // node -> the smallest node of its piece (of S, or of its complement)
  std::vector<Int> step;            // by piece (its smallest node): how far it moves (0: it does not)
  double decrease[2] = {0, 0};      // of the (scaled) cost, approximately: [1] raising S's pieces, [0] lowering the complement's
  std::size_t pieces[2] = {0, 0};   // the pieces of the complement [0] and of S [1]
  std::size_t moved[2] = {0, 0};    // those that move
};

// The exact line search on every connected piece of S (raised) and of its complement (lowered),
// from one pass over the arcs: the pieces by union-find along the arcs that do not cross S, the
// slopes and breakpoints from the arcs that do. No arc joins two pieces of one side, so the cost
// along their shifts is a sum of one convex piecewise-linear function per piece: each piece with a
// negative slope moves by its own t > 0, the breakpoint where its slope stops being negative.
// Raising S and lowering its complement move the tension of a crossing arc the same way (up if its
// L is in S), so each crossing arc adds the same slope and breakpoints to the piece at either end.
inline void descent_by_pieces(const Level& lv, Int U, const std::vector<Int>& pi, const std::vector<char>& S, Descent& d)
{
  Union_find sets(lv.n);
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
    for_each_kink(e, [&](Int b) {
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

// One step of steepest descent along the barrier S of a refused certificate (the source side of a
// minimum cut: raising pi on S lowers the cost at the steepest rate among all sets), piece by piece:
// the pieces of S rise, or those of its complement fall (the same tensions, up to the gauge),
// whichever lowers the cost more. The cost drops strictly; false (pi unchanged) if no piece has a
// negative slope. `decrease` gets the (scaled) decrease of the cost.
inline bool descend_along_barrier(Context& ctx, const Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& S,
                                  double& decrease)
{
  Descent d;
  descent_by_pieces(lv, U, pi, S, d);
  const double up = d.decrease[1], down = d.decrease[0];
  if(!(up > 0) && !(down > 0)) return false;
  const char side = up >= down ? 1 : 0;
  const bool raise = side == 1;
  decrease = raise ? up : down;
  ctx.stats.descent_pieces += d.moved[int(side)];
  ctx.stats.descent_lowerings += raise ? 0 : 1;
  if(std::ostream* log = ctx.log())
    *log << "[swn] multilevel: " << (raise ? "barrier" : "its complement") << " in " << d.pieces[int(side)] << " piece(s), "
         << d.moved[int(side)] << " " << (raise ? "raised" : "lowered") << " (decrease " << decrease << ")\n";
  for(std::size_t v = 0; v < lv.n; ++v)
    if(S[v] == side) pi[v] += raise ? d.step[d.piece[v]] : -d.step[d.piece[v]];
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
