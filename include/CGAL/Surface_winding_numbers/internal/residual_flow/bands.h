// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Bands of a level re-solved exactly by network simplex: the nodes near the jumps of the current
// answer (or near a barrier) are free, every connected piece of the rest is contracted to one node.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_BANDS_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_BANDS_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/network_simplex.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// The band: dist[v] >= 0 for the nodes within `radius` arcs of a seed (and, if `around_jumps`, of
// every arc with a nonzero jump). With `narrow`, the jumps on the curve (arcs with bounds, which stay
// in place from level to level) bring only their two faces, and only the jumps off the curve grow a
// band.
inline std::vector<int> band_distances(const Level& lv, const Adjacency& adj, const std::vector<Int>& pi,
                                       const std::vector<char>& seed, int radius, bool around_jumps, bool narrow)
{
  std::vector<int> dist(lv.n, -1);
  std::vector<std::size_t> queue;
  auto start = [&](std::size_t v) { if(dist[v] < 0) { dist[v] = 0; queue.push_back(v); } };
  auto on_curve = [](const Int_arc& e) { return e.has_lo || e.has_up; };
  if(around_jumps)
    for(const Int_arc& e : lv.arcs)
      if(tension(e, pi) != 0 && !(narrow && on_curve(e))) { start(e.L); start(e.R); }
  for(std::size_t v = 0; v < seed.size(); ++v)
    if(seed[v]) start(v);
  for(std::size_t q = 0; q < queue.size(); ++q)
  {
    const std::size_t x = queue[q];
    if(dist[x] >= radius) continue;
    adj.for_each_neighbour(lv.arcs, x, [&](std::size_t, std::size_t y) {
      if(dist[y] < 0) { dist[y] = dist[x] + 1; queue.push_back(y); }
    });
  }
  if(around_jumps && narrow)   // after the search, so that they do not stop it
    for(const Int_arc& e : lv.arcs)
      if(tension(e, pi) != 0 && on_curve(e))
      {
        if(dist[e.L] < 0) dist[e.L] = 0;
        if(dist[e.R] < 0) dist[e.R] = 0;
      }
  return dist;
}

// Re-solves, exactly, the band of nodes within `radius` arcs of a seed (and, if `around_jumps`, of
// every nonzero jump; `narrow`: see band_distances()), every connected piece of the rest being
// contracted to one node.
inline bool refine(Context& ctx, Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& seed, int radius,
                   bool around_jumps, bool narrow = false)
{
  const Adjacency& adj = lv.adjacency();
  const std::vector<int> dist = band_distances(lv, adj, pi, seed, radius, around_jumps, around_jumps && narrow);
  // band nodes first, then one node per connected piece of the rest
  std::vector<std::size_t> id(lv.n, npos);
  std::size_t n = 0;
  for(std::size_t v = 0; v < lv.n; ++v)
    if(dist[v] >= 0) id[v] = n++;
  const std::size_t band = n;
  n = number_pieces(lv.n, lv.arcs, adj, [&](std::size_t v) { return dist[v] < 0; }, id, band);
  // the unknowns are the changes of pi: the band problem's jumps are the current tensions; an arc
  // inside a contracted piece keeps its jump and is left out
  std::vector<Int_arc> sub;
  std::vector<std::size_t> level_arc;
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)
  {
    const Int_arc& e = lv.arcs[i];
    if(id[e.L] == id[e.R]) continue;
    Int_arc a = e;
    a.L = id[e.L];
    a.R = id[e.R];
    a.sh = tension(e, pi);
    sub.push_back(a);
    level_arc.push_back(i);
  }
  const auto t0 = std::chrono::steady_clock::now();
  ctx.stats.largest_band = (std::max)(ctx.stats.largest_band, n);
  std::vector<Int> delta, x;
  std::string why;
  if(!network_simplex_with_flows(n, sub, U, delta, x, why)) return ctx.fail(why);
  if(std::ostream* log = ctx.log())
    *log << "[swn] multilevel: band of " << band << " nodes (" << n << " with the pieces, " << sub.size()
         << " arcs) solved in " << seconds_since(t0) << " s\n";
  for(std::size_t v = 0; v < lv.n; ++v) pi[v] += delta[id[v]];
  // the band's optimal flows are exact on its arcs; the arcs left out keep theirs
  lv.x.resize(lv.arcs.size(), 0);
  for(std::size_t k = 0; k < sub.size(); ++k) lv.x[level_arc[k]] = x[k];
  normalize(lv, pi);
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
