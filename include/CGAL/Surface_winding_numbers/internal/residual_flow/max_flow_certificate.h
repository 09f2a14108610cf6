// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The optimality certificate of a level: pi is optimal if and only if a circulation x exists with
// left_slope(J) <= x <= right_slope(J) on every arc. It is found as a maximum flow from the level's
// current flow; when it does not exist, the minimum cut is a barrier: a set of nodes whose shifts
// can all rise with a negative slope of the objective.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_MAX_FLOW_CERTIFICATE_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_MAX_FLOW_CERTIFICATE_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// the imbalance of the flow x at every node (x leaves L and enters R); it fits in Int (every node's
// arcs' capacities add up to less than the largest Int, checked by multilevel())
inline void node_supply(const Level& lv, const std::vector<Int>& x, std::vector<Int>& supply)
{
  supply.assign(lv.n, Int(0));
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)
  {
    supply[lv.arcs[i].L] -= x[i];
    supply[lv.arcs[i].R] += x[i];
  }
}

// A maximum-flow problem from the flow x0 within [lower, upper]: residual capacities both ways, and
// the imbalance of x0 at every node as its terminal capacity. The arcs are added the first time and
// only given new capacities afterwards (the graph of the level is kept).
template <class Max_flow>
void load_max_flow(Max_flow& mf, const Level& lv, const Certificate_workspace& ws)
{
  const bool reload = mf.number_of_arcs() == lv.arcs.size() && !lv.arcs.empty();
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)   // x = x0 + flow L->R
  {
    if(reload) mf.reset_arc(i, ws.upper[i] - ws.x0[i], ws.x0[i] - ws.lower[i]);
    else mf.add_arc(lv.arcs[i].L, lv.arcs[i].R, ws.upper[i] - ws.x0[i], ws.x0[i] - ws.lower[i]);
  }
  for(std::size_t v = 0; v < lv.n; ++v) mf.set_terminal(v, ws.supply[v]);
}

// The barrier of a refused certificate, from the flow x it ended with (a maximum flow): the nodes
// that cannot reach, along residual arcs, a node that still lacks inflow. It is the same set for
// every maximum flow (the source side of the minimum cut nearest to the sink).
inline void mark_barrier(Level& lv, const std::vector<Int>& x, std::vector<char>& barrier)
{
  const Certificate_workspace& ws = *lv.workspace;
  std::vector<Int> inflow;
  node_supply(lv, x, inflow);
  const Adjacency& adj = lv.adjacency();
  std::vector<char> reaches(lv.n, 0);
  std::vector<std::size_t> queue;
  for(std::size_t v = 0; v < lv.n; ++v)
    if(inflow[v] < 0) { reaches[v] = 1; queue.push_back(v); }
  for(std::size_t q = 0; q < queue.size(); ++q)
  {
    const std::size_t v = queue[q];
    adj.for_each_neighbour(lv.arcs, v, [&](std::size_t i, std::size_t u) {
      // u reaches v if the residual arc u -> v has capacity: L -> R while x < upper, R -> L while x > lower
      const bool open = lv.arcs[i].R == v ? x[i] < ws.upper[i] : x[i] > ws.lower[i];
      if(open && !reaches[u]) { reaches[u] = 1; queue.push_back(u); }
    });
  }
  barrier.assign(lv.n, 0);
  for(std::size_t v = 0; v < lv.n; ++v) barrier[v] = reaches[v] ? 0 : 1;
}

// Optimality of pi on a level: true if a circulation x with left_slope(J) <= x <= right_slope(J)
// exists on every arc; otherwise false, with the barrier (the source side of a minimum cut) marked.
// As a maximum flow from the level's flow lv.x clamped to the bounds (the flows carried down the
// hierarchy and written by the bands are nearly balanced): push-relabel (Warm_push_relabel; by
// augmenting paths with ctx.augmenting_paths), fast while the imbalances are local, within a work
// budget (Options::max_flow_budget), then
// Boykov-Kolmogorov from where it stopped (faster on some large certificates). lv.x gets the flow
// found, and the certificate is checked independently (bounds and conservation, in integers).
inline bool certify_optimality(Context& ctx, Level& lv, Int U, const std::vector<Int>& pi, std::vector<char>& barrier)
{
  const std::size_t na = lv.arcs.size();
  lv.adjacency();   // creates the workspace
  Certificate_workspace& ws = *lv.workspace;
  ws.lower.resize(na); ws.upper.resize(na); ws.x0.resize(na);
  for(std::size_t i = 0; i < na; ++i)
  {
    const Int_arc& e = lv.arcs[i];
    const Int J = tension(e, pi);
    ws.lower[i] = left_slope(e, J, U);
    ws.upper[i] = right_slope(e, J, U);
    const Int start = i < lv.x.size() ? lv.x[i] : 0;
    ws.x0[i] = (std::min)(ws.upper[i], (std::max)(ws.lower[i], start));
  }
  node_supply(lv, ws.x0, ws.supply);
  barrier.assign(lv.n, 0);
  ++ctx.stats.certificates;
  typedef Warm_push_relabel<Int> Push_relabel;
  std::vector<Int>& x = lv.x;
  x = ws.x0;
  bool balanced = false, barrier_marked = false;
  typename Push_relabel::Outcome outcome = Push_relabel::OVER_BUDGET;
  const double budget = ctx.options.max_flow_budget;
  const auto t0 = std::chrono::steady_clock::now();
  if(budget != 0)
  {
    if(!ws.push_relabel) ws.push_relabel.reset(new Push_relabel(lv.n));
    load_max_flow(*ws.push_relabel, lv, ws);
    const double work = budget * double(lv.n + 2 * na);
    const std::size_t limit = budget < 0 || work >= 1e18 ? (std::numeric_limits<std::size_t>::max)() : std::size_t(work);
    try { outcome = ctx.augmenting_paths ? ws.push_relabel->run_paths(limit) : ws.push_relabel->run(limit); }
    catch(...) { ws.push_relabel.reset(); throw; }
    for(std::size_t i = 0; i < na; ++i) x[i] += ws.push_relabel->flow(i);
    balanced = outcome == Push_relabel::BALANCED;
    barrier_marked = outcome == Push_relabel::CUT;
    if(barrier_marked)
      for(std::size_t v = 0; v < lv.n; ++v) barrier[v] = ws.push_relabel->source_side(v) ? 1 : 0;
  }
  if(outcome == Push_relabel::OVER_BUDGET)
  {
    if(budget != 0) ++ctx.stats.max_flow_fallbacks;
    const auto t1 = std::chrono::steady_clock::now();
    ws.x0 = x;   // push-relabel's preflow
    node_supply(lv, ws.x0, ws.supply);
    if(!ws.boykov_kolmogorov) ws.boykov_kolmogorov.reset(new Boykov_kolmogorov_flow<Int>(lv.n));
    load_max_flow(*ws.boykov_kolmogorov, lv, ws);
    try { balanced = ws.boykov_kolmogorov->run(); }
    catch(...) { ws.boykov_kolmogorov.reset(); throw; }   // out of memory, say: built anew next time
    for(std::size_t i = 0; i < na; ++i) x[i] += ws.boykov_kolmogorov->flow(i);
    if(std::ostream* log = ctx.log())
      *log << "[swn] multilevel: push-relabel over budget after " << std::chrono::duration<double>(t1 - t0).count()
           << " s, Boykov-Kolmogorov " << seconds_since(t1) << " s\n";
  }
  if(!balanced && !barrier_marked) mark_barrier(lv, x, barrier);
  if(!balanced) return false;
  for(std::size_t i = 0; i < na; ++i)
    if(x[i] < ws.lower[i] || x[i] > ws.upper[i]) return false;
  node_supply(lv, x, ws.supply);
  return std::all_of(ws.supply.begin(), ws.supply.end(), [](Int b) { return b == 0; });
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
