// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The integer nonbounding chain G from the real one g = J v (paper Sec. 3.6).
//
// The paper takes G = round(g). Where the curve has gaps, g is fractional along the completions and
// the residual may split a completion over several routes; rounding edge by edge then leaves G with
// endpoints inside the surface (about a quarter of the benchmark's cases with handles and gaps).
// The nonbounding loops must be closed (in the relative sense: they may end on the border), so G is
// defined here as the closed integer chain nearest to g,
//
//     G = argmin sum_e c_e |G_e - g_e|   over integer 1-chains on the interior edges with dG = 0 at
//                                        every interior vertex,
//
// with c_e the edge length, doubled on the edges of the input curve (curve_deviation_factor). When
// round(g) is closed it is that minimizer (every edge sits at its own minimum), so the paper's
// definition is kept wherever it already gives loops. Otherwise G is
// round(g) plus an integer flow that carries the excess endpoints of round(g) to the missing ones
// (or to the border) at least cost: a minimum-cost flow with convex, piecewise-linear arc costs,
// solved by successive shortest paths. The open endpoints of round(g) are few and close to one
// another (both ends of a split completion), so each Dijkstra search stops after a small ball.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_NONBOUNDING_CHAIN_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_NONBOUNDING_CHAIN_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/winding_number.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// G = round(g) edge by edge, half away from zero (paper Sec. 3.6).
inline std::vector<int> rounded_chain(const std::vector<double>& g)
{
  std::vector<int> G(g.size());
  for(std::size_t e = 0; e < g.size(); ++e) G[e] = int(round_half_away(g[e]));
  return G;
}

// Whether C is closed relative to the border: dC = 0 at every vertex off the border.
template <class Integer>
bool is_relatively_closed(const Mesh_tables& m, const std::vector<Integer>& C)
{
  const std::vector<long> d = chain_boundary<long>(m, C);
  for(std::size_t v = 0; v < m.nv; ++v)
    if(d[v] != 0 && !m.vertex_on_border[v]) return false;
  return true;
}

// Deviations from g on the edges of the input curve count this many times their length: between
// closings at nearly the same distance from g (g close to 1/2 along a whole broken loop), the one
// that keeps the curve the user drew wins over the one that drops it.
constexpr double curve_deviation_factor = 2.;

/*
  Closes the rounded chain G in place: adds the integer flow X on the interior edges that makes
  G + X relatively closed and minimizes sum_e c_e |G_e + X_e - g_e|, c_e the length of e, times
  curve_deviation_factor where `chain` (the input curve) is nonzero (see the top of this file).
  Returns the number of units of flow sent (0 when G was already closed).

  Nodes are the vertices plus one node standing for the whole border (relative closedness: flow
  may enter or leave the surface there at no cost). The cost of moving X_e by one step is the
  change of c_e |G_e + X_e - g_e|, convex in X_e; successive shortest paths with node potentials
  keep every reduced cost nonnegative, one unit per Dijkstra search, which stops at the first node
  still missing flow.
*/
inline std::size_t close_rounded_chain(const Mesh_tables& m, const std::vector<double>& g,
                                       const std::vector<double>& chain, std::vector<int>& G)
{
  // A vertex with supply +k has k more arrivals than departures in G: k units must leave it. The
  // border node absorbs (or emits) what the interior vertices leave over.
  const std::size_t border = m.nv;
  std::vector<long> supply(m.nv + 1, 0);
  {
    const std::vector<long> d = chain_boundary<long>(m, G);
    bool open = false;
    for(std::size_t v = 0; v < m.nv; ++v)
      if(!m.vertex_on_border[v] && d[v] != 0)
      {
        supply[v] = d[v];
        supply[border] -= d[v];
        open = true;
      }
    if(!open) return 0;
  }

  // vertex -> incident arcs (CSR), the border vertices grouped under the border node
  auto node_of = [&](std::size_t v) { return m.vertex_on_border[v] ? border : v; };
  std::vector<std::size_t> begin(m.nv + 2, 0), incident;
  // (diagonals inside input polygons are left out: G lives on the input's edges; nothing may jump at
  // nonmanifold vertices)
  for(const Arc& a : m.arcs)
  {
    if(m.jump_forbidden(a.edge)) continue;
    ++begin[node_of(m.ev[2 * a.edge]) + 1];
    ++begin[node_of(m.ev[2 * a.edge + 1]) + 1];
  }
  for(std::size_t n = 0; n <= m.nv; ++n) begin[n + 1] += begin[n];
  incident.resize(begin[m.nv + 1]);
  {
    std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
    for(std::size_t a = 0; a < m.arcs.size(); ++a)
    {
      if(m.jump_forbidden(m.arcs[a].edge)) continue;
      incident[fill[node_of(m.ev[2 * m.arcs[a].edge])]++] = a;
      incident[fill[node_of(m.ev[2 * m.arcs[a].edge + 1])]++] = a;
    }
  }

  std::vector<double> weight(m.arcs.size());
  for(std::size_t a = 0; a < m.arcs.size(); ++a)
    weight[a] = m.edge_length(m.arcs[a].edge) *
                (std::abs(chain[m.arcs[a].edge]) > chain_tolerance ? curve_deviation_factor : 1.);
  std::vector<int> X(m.arcs.size(), 0);
  // cost of moving X_a by step = +-1
  auto step_cost = [&](std::size_t a, int step) {
    const std::size_t e = m.arcs[a].edge;
    const double r = G[e] + X[a] - g[e];
    return weight[a] * (std::abs(r + step) - std::abs(r));
  };

  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> potential(m.nv + 1, 0.), dist(m.nv + 1, inf);
  std::vector<std::size_t> pred_arc(m.nv + 1, npos), settled;
  std::vector<char> done(m.nv + 1, 0);
  using Entry = std::pair<double, std::size_t>;

  // the nodes with flow to send (no node becomes one: a path's source only loses supply)
  std::vector<std::size_t> sources;
  for(std::size_t n = 0; n <= m.nv; ++n)
    if(supply[n] > 0) sources.push_back(n);

  std::size_t sent = 0;
  for(;;)
  {
    // multi-source Dijkstra from every node that still has flow to send
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    std::vector<std::size_t> touched;
    sources.erase(std::remove_if(sources.begin(), sources.end(), [&](std::size_t n) { return supply[n] <= 0; }),
                  sources.end());
    for(std::size_t n : sources) { dist[n] = 0.; heap.push({0., n}); touched.push_back(n); }
    if(heap.empty()) break;
    std::size_t target = npos;
    settled.clear();
    while(!heap.empty())
    {
      const Entry top = heap.top();
      heap.pop();
      const std::size_t u = top.second;
      if(done[u] || top.first > dist[u]) continue;
      done[u] = 1;
      settled.push_back(u);
      if(supply[u] < 0) { target = u; break; }
      for(std::size_t i = begin[u]; i < begin[u + 1]; ++i)
      {
        const std::size_t a = incident[i];
        const std::size_t e = m.arcs[a].edge;
        const std::size_t t = node_of(m.ev[2 * e]), h = node_of(m.ev[2 * e + 1]);
        if(t == h) continue;  // both ends on the border
        // leaving u along the reference direction raises X, against it lowers X
        const int step = (u == t) ? +1 : -1;
        const std::size_t w = (u == t) ? h : t;
        if(done[w]) continue;
        const double reduced = std::max(0., step_cost(a, step) + potential[u] - potential[w]);
        if(dist[u] + reduced < dist[w])
        {
          if(dist[w] == inf) touched.push_back(w);
          dist[w] = dist[u] + reduced;
          pred_arc[w] = a;
          heap.push({dist[w], w});
        }
      }
    }
    if(target == npos)
      throw std::logic_error("SWN internal error: the rounded nonbounding chain cannot be closed");

    // potentials: pi += min(dist, D) - D keeps reduced costs nonnegative (and changes only the
    // settled nodes)
    const double D = dist[target];
    for(std::size_t u : settled) potential[u] += dist[u] - D;

    // one unit along the path, back from the target to its source (the sources are the nodes
    // without a predecessor: they start at distance 0 and reduced costs are nonnegative)
    std::size_t w = target;
    while(pred_arc[w] != npos)
    {
      const std::size_t a = pred_arc[w];
      const std::size_t e = m.arcs[a].edge;
      const std::size_t t = node_of(m.ev[2 * e]), h = node_of(m.ev[2 * e + 1]);
      // the path entered w along arc a: from t to h raises X
      X[a] += (w == h) ? +1 : -1;
      w = (w == h) ? t : h;
    }
    --supply[w];
    ++supply[target];
    ++sent;

    for(std::size_t n : touched) { dist[n] = inf; pred_arc[n] = npos; done[n] = 0; }
  }

  for(std::size_t a = 0; a < m.arcs.size(); ++a) G[m.arcs[a].edge] += X[a];
  return sent;
}

// Nonbounding chain G (paper Sec. 3.6): round(g), closed where rounding left it open.
inline std::vector<int> nonbounding_chain(const Mesh_tables& m, const std::vector<double>& g,
                                          const std::vector<double>& chain, std::size_t* closing_units = nullptr)
{
  std::vector<int> G = rounded_chain(g);
  // On a nonorientable surface G is a dual chain, without a global boundary to close: left as rounded.
  const std::size_t units = m.nonorientable_arcs > 0 ? 0 : close_rounded_chain(m, g, chain, G);
  if(closing_units) *closing_units = units;
  return G;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
