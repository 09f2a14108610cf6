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
#include <future>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// The band: dist[v] >= 0 for the nodes within `radius` arcs of a seed (and, if `around_jumps`, of
// every arc with a nonzero jump). With `narrow`, the jumps on the curve (arcs with bounds, which stay
// in place from level to level) bring only their two faces, and only the jumps off the curve (the
// completions of the gaps, which move) grow a band.
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

// The problem on the nodes `node(v)` (npos: fixed, outside the problem) over the arcs of lv with at
// least one end in it, whose jumps are the current tensions (the unknowns are the changes of pi).
// An arc with both ends fixed, or both in one contracted piece, keeps its jump and is left out.
struct Band_problem
{
  std::size_t n = 0;
  std::vector<Int_arc> arcs;
  std::vector<std::size_t> level_arc;   // arc -> its arc in lv
  std::vector<Int> delta, x;            // the optimal changes of pi and flows

  template <class Node>
  Band_problem(const Level& lv, const std::vector<Int>& pi, std::size_t nodes, Node node) : n(nodes)
  {
    for(std::size_t i = 0; i < lv.arcs.size(); ++i)
    {
      const Int_arc& e = lv.arcs[i];
      const std::size_t L = node(e.L), R = node(e.R);
      // both fixed, inside one contracted piece (jump unchanged), or an end outside the problem
      if(L == R || L == npos || R == npos) continue;
      Int_arc a = e;
      a.L = L;
      a.R = R;
      a.sh = tension(e, pi);
      arcs.push_back(a);
      level_arc.push_back(i);
    }
  }
  bool solve(Int U, std::string& why) { return network_simplex_with_flows(n, arcs, U, delta, x, why); }
  // the band's optimal flows are exact on its arcs; the arcs left out keep theirs
  void write_flows(Level& lv) const
  {
    lv.x.resize(lv.arcs.size(), 0);
    for(std::size_t k = 0; k < arcs.size(); ++k) lv.x[level_arc[k]] = x[k];
  }
};

// The band cut in two halves A and B (Statistics::split_bands; Options::split_band_nodes): the
// largest connected part of the band is cut by a breadth-first level S (from a far node) so that A
// holds about half of the band, the other parts going to B; if no part holds half, whole parts go to
// either half. S and the pieces of the outside that touch both halves keep their shifts; the halves,
// each with the pieces that touch only it, are independent problems, solved side by side (two
// threads if allowed). `seam` gets S. False with ctx.error empty if the band does not split.
inline bool solve_band_in_halves(Context& ctx, Level& lv, const Adjacency& adj, const std::vector<int>& dist, Int U,
                                 std::vector<Int>& pi, std::vector<char>& seam)
{
  auto in_band = [&](std::size_t v) { return dist[v] >= 0; };
  std::vector<std::size_t> part(lv.n, npos);
  const std::size_t nparts = number_pieces(lv.n, lv.arcs, adj, in_band, part, 0);
  std::vector<std::size_t> part_size(nparts, 0);
  std::size_t total = 0;
  for(std::size_t v = 0; v < lv.n; ++v) if(in_band(v)) { ++part_size[part[v]]; ++total; }
  const std::size_t largest = std::size_t(std::max_element(part_size.begin(), part_size.end()) - part_size.begin());
  std::vector<char> side(lv.n, 0);   // in the band: 1 (A), 2 (B) or 3 (S)
  if(2 * part_size[largest] <= total)
  {
    std::vector<std::size_t> order(nparts);
    for(std::size_t p = 0; p < nparts; ++p) order[p] = p;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return part_size[a] > part_size[b]; });
    std::vector<char> part_side(nparts, 2);
    std::size_t in_a = 0;
    for(std::size_t p : order)
      if(2 * (in_a + part_size[p]) <= total + part_size[p]) { part_side[p] = 1; in_a += part_size[p]; }
    for(std::size_t v = 0; v < lv.n; ++v) if(in_band(v)) side[v] = part_side[part[v]];
  }
  else
  {
    std::vector<long> level(lv.n, -1);
    std::vector<std::size_t> queue;
    auto bfs = [&](std::size_t root) {
      std::fill(level.begin(), level.end(), -1);
      queue.assign(1, root);
      level[root] = 0;
      for(std::size_t q = 0; q < queue.size(); ++q)
        adj.for_each_neighbour(lv.arcs, queue[q], [&](std::size_t, std::size_t y) {
          if(level[y] < 0 && in_band(y)) { level[y] = level[queue[q]] + 1; queue.push_back(y); }
        });
      return queue.back();
    };
    std::size_t start = 0;
    while(!(in_band(start) && part[start] == largest)) ++start;
    bfs(bfs(start));
    const long cut = level[queue[total / 2]];
    for(std::size_t v = 0; v < lv.n; ++v)
      if(in_band(v)) side[v] = level[v] < 0 || level[v] > cut ? 2 : level[v] < cut ? 1 : 3;
  }
  std::size_t count[4] = {0, 0, 0, 0};
  for(std::size_t v = 0; v < lv.n; ++v) ++count[int(side[v])];
  if(count[1] == 0 || count[2] == 0) return false;
  // the pieces of the outside go to the half they touch (3: both or none, fixed)
  std::vector<std::size_t> piece(lv.n, npos);
  const std::size_t np = number_pieces(lv.n, lv.arcs, adj, [&](std::size_t v) { return !in_band(v); }, piece, 0);
  std::vector<char> touch(np, 0);
  for(const Int_arc& e : lv.arcs)
  {
    if(!in_band(e.L) && in_band(e.R) && side[e.R] != 3) touch[piece[e.L]] |= side[e.R];
    if(!in_band(e.R) && in_band(e.L) && side[e.L] != 3) touch[piece[e.R]] |= side[e.L];
  }
  auto side_of = [&](std::size_t v) -> int { return in_band(v) ? side[v] : touch[piece[v]] == 0 ? 3 : touch[piece[v]]; };
  // node 0 of each half's problem is the ground (S and the fixed pieces); then band nodes, then pieces
  std::vector<std::size_t> id(lv.n, npos), piece_id(np, npos);
  std::size_t cnt[3] = {0, 1, 1};
  for(std::size_t v = 0; v < lv.n; ++v)
    if(in_band(v) && side[v] != 3) id[v] = cnt[int(side[v])]++;
  for(std::size_t p = 0; p < np; ++p)
    if(touch[p] == 1 || touch[p] == 2) piece_id[p] = cnt[int(touch[p])]++;
  auto node_in = [&](int s) {
    return [&, s](std::size_t v) -> std::size_t {
      const int sv = side_of(v);
      if(sv == 3) return 0;
      if(sv != s) return npos;   // the other half: not in this problem (no arc joins the halves)
      return in_band(v) ? id[v] : piece_id[piece[v]];
    };
  };
  Band_problem half[2] = {Band_problem(lv, pi, cnt[1], node_in(1)), Band_problem(lv, pi, cnt[2], node_in(2))};
  std::string why_b;
  bool ok_b = false;
  std::future<void> other;
  if(ctx.concurrent())
  {
    try { other = std::async(std::launch::async, [&] { ok_b = half[1].solve(U, why_b); }); }
    catch(const std::system_error&) {}   // no second thread: one after the other
  }
  std::string why;
  const bool ok_a = half[0].solve(U, why);
  if(other.valid()) other.get();
  else ok_b = half[1].solve(U, why_b);
  if(!ok_a) return ctx.fail(why);
  if(!ok_b) return ctx.fail(why_b);
  for(std::size_t v = 0; v < lv.n; ++v)
  {
    const int s = side_of(v);
    if(s == 3) continue;
    const Band_problem& h = half[s - 1];
    pi[v] += h.delta[node_in(s)(v)] - h.delta[0];
  }
  half[0].write_flows(lv);
  half[1].write_flows(lv);
  normalize(lv, pi);
  seam.assign(lv.n, 0);
  for(std::size_t v = 0; v < lv.n; ++v) seam[v] = in_band(v) && side[v] == 3;
  ctx.stats.largest_band = (std::max)(ctx.stats.largest_band, (std::max)(cnt[1], cnt[2]));
  ++ctx.stats.split_bands;
  if(std::ostream* log = ctx.log())
    *log << "[swn] multilevel: band in halves of " << cnt[1] << " and " << cnt[2] << " nodes (seam " << count[3]
         << ", pieces " << np << ")\n";
  return true;
}

// Re-solves, exactly, the band of nodes within `radius` arcs of a seed (and, if `around_jumps`, of
// every nonzero jump; `narrow`: see band_distances()), every connected piece of the rest being
// contracted to one node. A large first band (around_jumps) is solved in two halves first, then a
// band around the cut.
inline bool refine(Context& ctx, Level& lv, Int U, std::vector<Int>& pi, const std::vector<char>& seed, int radius,
                   bool around_jumps, bool narrow = false)
{
  const Adjacency& adj = lv.adjacency();
  const std::vector<int> dist = band_distances(lv, adj, pi, seed, radius, around_jumps, around_jumps && narrow);
  const std::size_t band = std::size_t(std::count_if(dist.begin(), dist.end(), [](int d) { return d >= 0; }));
  if(around_jumps && ctx.options.split_band_nodes > 0 && band >= ctx.options.split_band_nodes)
  {
    std::vector<char> seam;
    if(solve_band_in_halves(ctx, lv, adj, dist, U, pi, seam))
      return std::find(seam.begin(), seam.end(), 1) == seam.end() ||
             refine(ctx, lv, U, pi, seam, ctx.options.band_radius, false, false);
    if(!ctx.error.empty()) return false;
  }
  // band nodes first, then one node per connected piece of the rest
  std::vector<std::size_t> id(lv.n, npos);
  std::size_t n = 0;
  for(std::size_t v = 0; v < lv.n; ++v)
    if(dist[v] >= 0) id[v] = n++;
  n = number_pieces(lv.n, lv.arcs, adj, [&](std::size_t v) { return dist[v] < 0; }, id, band);
  Band_problem p(lv, pi, n, [&](std::size_t v) { return id[v]; });
  const auto t0 = std::chrono::steady_clock::now();
  ctx.stats.largest_band = (std::max)(ctx.stats.largest_band, n);
  std::string why;
  if(!p.solve(U, why)) return ctx.fail(why);
  if(std::ostream* log = ctx.log())
    *log << "[swn] multilevel: band of " << band << " nodes (" << n << " with the pieces, " << p.arcs.size()
         << " arcs) solved in " << seconds_since(t0) << " s\n";
  for(std::size_t v = 0; v < lv.n; ++v) pi[v] += p.delta[id[v]];
  p.write_flows(lv);
  normalize(lv, pi);
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
