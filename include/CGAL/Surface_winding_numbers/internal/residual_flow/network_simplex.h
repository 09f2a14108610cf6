// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// A list of integer arcs as a minimum-cost circulation, solved by LEMON's network simplex and checked
// by the exact duality certificate.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_NETWORK_SIMPLEX_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_NETWORK_SIMPLEX_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>

#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// The circulation network of a list of arcs: the linear programming dual of minimizing the sum of
// the arcs' convex piecewise-linear costs. Every arc becomes two to four parallel network arcs:
// two of capacity w (the slopes of w |J|) and, for each finite bound, one penalty arc of capacity U,
// larger than any flow of an optimal basic circulation, so that the penalty is exact (a bound at 0
// merges with the slope arc on the same side). With J = sh + pi[L] - pi[R] and reduced costs
// c + pi[tail] - pi[head], the arc R->L of cost x - sh is active when J > x, L->R of cost sh - x
// when J < x. The optimal potentials are the optimal shifts.
struct Network
{
  std::vector<std::size_t> tail, head, owner;   // owner: the arc the network arc comes from
  std::vector<Int> cap, cost;

  Network(const std::vector<Int_arc>& arcs, Int U)
  {
    tail.reserve(3 * arcs.size()); head.reserve(3 * arcs.size()); owner.reserve(3 * arcs.size());
    cap.reserve(3 * arcs.size()); cost.reserve(3 * arcs.size());
    for(std::size_t i = 0; i < arcs.size(); ++i)
    {
      const Int_arc& e = arcs[i];
      const bool merge_up = e.has_up && e.up == 0, merge_lo = e.has_lo && e.lo == 0;
      add(i, e.R, e.L, e.w + (merge_up ? U : 0), -e.sh);                    // w (J)_+
      add(i, e.L, e.R, e.w + (merge_lo ? U : 0), e.sh);                     // w (-J)_+
      if(e.has_up && !merge_up) add(i, e.R, e.L, U, e.up - e.sh);           // U (J - up)_+
      if(e.has_lo && !merge_lo) add(i, e.L, e.R, U, e.sh - e.lo);           // U (lo - J)_+
    }
  }

private:
  void add(std::size_t i, std::size_t t, std::size_t h, Int c, Int k)
  {
    if(c <= 0) return;
    tail.push_back(t); head.push_back(h); cap.push_back(c); cost.push_back(k); owner.push_back(i);
  }
};

// The flow is a circulation within the capacities and (where the compiler has 128-bit integers)
// its cost equals the dual objective of pi, sum cap * max(0, -reduced cost): both are optimal.
inline bool duality_holds(const Network& net, const std::vector<Int>& pi, const std::vector<Int>& flow, std::string& why)
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

// Network simplex on `arcs` over n nodes, its optimum checked by duality: the potentials pi and, per
// arc, its flow x from L to R in the sense of the subdifferential (left_slope(J) <= x <=
// right_slope(J): a circulation).
inline bool network_simplex_with_flows(std::size_t n, const std::vector<Int_arc>& arcs, Int U, std::vector<Int>& pi,
                                       std::vector<Int>& x, std::string& why, std::size_t* network_arcs = nullptr)
{
  typedef lemon::SmartDigraph Graph;
  typedef lemon::NetworkSimplex<Graph, Int, Int> Simplex;
  x.assign(arcs.size(), 0);
  pi.assign(n, 0);
  const Network net(arcs, U);
  if(network_arcs != nullptr) *network_arcs = net.cap.size();
  if(net.cap.empty()) return true;
  Graph g;
  g.reserveNode(int(n));
  g.reserveArc(int(net.cap.size()));
  for(std::size_t v = 0; v < n; ++v) g.addNode();
  for(std::size_t i = 0; i < net.cap.size(); ++i) g.addArc(g.nodeFromId(int(net.tail[i])), g.nodeFromId(int(net.head[i])));
  Graph::ArcMap<Int> cap(g), cost(g);
  for(Graph::ArcIt a(g); a != lemon::INVALID; ++a)
  {
    cap[a] = net.cap[std::size_t(g.id(a))];
    cost[a] = net.cost[std::size_t(g.id(a))];
  }
  Simplex ns(g);
  ns.upperMap(cap).costMap(cost);
  const auto status = ns.run(Simplex::BLOCK_SEARCH);
  if(status != Simplex::OPTIMAL)
  {
    why = "network simplex did not find an optimum (status " + std::to_string(int(status)) + ")";
    return false;
  }
  std::vector<Int> flow(net.cap.size());
  for(Graph::NodeIt v(g); v != lemon::INVALID; ++v) pi[std::size_t(g.id(v))] = ns.potential(v);
  for(Graph::ArcIt a(g); a != lemon::INVALID; ++a) flow[std::size_t(g.id(a))] = ns.flow(a);
  if(!duality_holds(net, pi, flow, why)) return false;
  for(std::size_t k = 0; k < flow.size(); ++k)
  {
    const Int_arc& e = arcs[net.owner[k]];
    x[net.owner[k]] += net.tail[k] == e.R ? flow[k] : -flow[k];
  }
  return true;
}

// network simplex on a whole problem (the coarsest level, or the problem itself), with the solver's
// bookkeeping: the largest problem and network, and the certificate (duality, exact where the
// compiler has 128-bit integers)
inline bool solve_whole(Context& ctx, std::size_t n, const std::vector<Int_arc>& arcs, Int U, std::vector<Int>& pi,
                        std::vector<Int>& x)
{
  ctx.stats.largest_band = (std::max)(ctx.stats.largest_band, n);
  std::string why;
  if(!network_simplex_with_flows(n, arcs, U, pi, x, why, &ctx.stats.network_arcs)) return ctx.fail(why);
  ctx.stats.certified = has_wide || arcs.empty();
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
