// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_REDUCED_RESIDUAL_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_REDUCED_RESIDUAL_H

#include <CGAL/Surface_winding_numbers/Residual_problem.h>
#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/residual.h>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Shortest-path completion of the gaps (paper Sec. 6): every interior endpoint where curves arrive
// is joined to the nearest endpoint where curves depart (or, failing that, to the border) by a
// shortest path, by edge length, over the interior edges that are not on the curve. Returns the
// completion chain (to be added to Gamma). Unlike the authors' code, the Dijkstra weights are the
// edge lengths (their code gives infinite weight to the edges off the curve, a documented slip).
// `weight(p, v, x, e, x_departs)`: the length of edge e from v to x on a path from p (infinite: not taken),
// x_departs when x is an interior endpoint where curves depart. The arrival endpoints are taken in vertex
// order, or with `shortest_first` the one with the shortest join of all first (then the joins whose
// departure endpoint was taken are searched again): a completion that does not depend on the numbering.
template <class Weight>
std::vector<double> shortest_path_completion(const Mesh_tables& m, const std::vector<double>& chain, Weight weight,
                                             bool shortest_first = false)
{
  std::vector<double> d = chain_boundary(m, chain);
  std::vector<double> completion(m.ne, 0.);
  // vertex adjacency over interior edges off the curve
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> adjacent(m.nv);   // (neighbour, edge)
  for(const Arc& a : m.arcs)
  {
    if(std::abs(chain[a.edge]) > chain_tolerance) continue;
    const std::size_t i = m.ev[2 * a.edge], j = m.ev[2 * a.edge + 1];
    adjacent[i].emplace_back(j, a.edge);
    adjacent[j].emplace_back(i, a.edge);
  }
  auto is_target = [&](std::size_t v) { return !m.vertex_on_border[v] && d[v] < -chain_tolerance; };
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> dist(m.nv, infinity);
  std::vector<std::size_t> pred_edge(m.nv), pred_vertex(m.nv), touched;
  struct Join { double length; std::size_t target; std::vector<std::size_t> path; };   // path: (vertex, edge) pairs
  // Dijkstra from p to the nearest departure endpoint, else to the nearest border vertex (target npos: none)
  auto search = [&](std::size_t p) {
    for(std::size_t t : touched) dist[t] = infinity;
    touched.assign(1, p);
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    dist[p] = 0;
    queue.emplace(0., p);
    std::size_t target = npos, border = npos;
    while(!queue.empty())
    {
      const Item top = queue.top();
      queue.pop();
      const std::size_t v = top.second;
      if(top.first > dist[v]) continue;
      if(v != p && is_target(v)) { target = v; break; }
      if(v != p && m.vertex_on_border[v] && border == npos) border = v;
      for(const auto& ne : adjacent[v])
      {
        const double w = weight(p, v, ne.first, ne.second, is_target(ne.first));
        const double nd = dist[v] + w;
        if(!(w < infinity) || !(nd < dist[ne.first])) continue;
        if(dist[ne.first] == infinity) touched.push_back(ne.first);
        dist[ne.first] = nd; pred_edge[ne.first] = ne.second; pred_vertex[ne.first] = v; queue.emplace(nd, ne.first);
      }
    }
    if(target == npos) target = border;
    Join join{infinity, target, {}};
    if(target == npos) return join;
    join.length = dist[target];
    for(std::size_t v = target; v != p; v = pred_vertex[v]) { join.path.push_back(v); join.path.push_back(pred_edge[v]); }
    return join;
  };
  // add the path p -> target: +1 along it
  auto add = [&](std::size_t p, const Join& join) {
    for(std::size_t k = 0; k < join.path.size(); k += 2)
    {
      const std::size_t v = join.path[k], e = join.path[k + 1];
      completion[e] += (m.ev[2 * e + 1] == v) ? 1. : -1.;
    }
    d[p] -= 1.;
    d[join.target] += 1.;
  };
  if(!shortest_first)
  {
    for(std::size_t p = 0; p < m.nv; ++p)
      while(!m.vertex_on_border[p] && d[p] > chain_tolerance)
      {
        const Join join = search(p);
        if(join.target == npos) break;   // nothing reachable: the gap stays open
        add(p, join);
      }
    return completion;
  }
  std::vector<std::size_t> ends;
  std::vector<Join> joins;
  for(std::size_t p = 0; p < m.nv; ++p)
    if(!m.vertex_on_border[p] && d[p] > chain_tolerance) { ends.push_back(p); joins.push_back(search(p)); }
  for(;;)
  {
    std::size_t best = npos;
    for(std::size_t i = 0; i < ends.size(); ++i)
      if(d[ends[i]] > chain_tolerance && joins[i].target != npos && (best == npos || joins[i].length < joins[best].length)) best = i;
    if(best == npos) break;   // the ends left have nothing reachable
    const std::size_t target = joins[best].target;
    add(ends[best], joins[best]);
    for(std::size_t i = 0; i < ends.size(); ++i)
      if(d[ends[i]] > chain_tolerance && (i == best || (joins[i].target == target && !m.vertex_on_border[target] && !is_target(target))))
        joins[i] = search(ends[i]);
  }
  return completion;
}

inline std::vector<double> shortest_path_completion(const Mesh_tables& m, const std::vector<double>& chain)
{
  return shortest_path_completion(m, chain, [&m](std::size_t, std::size_t, std::size_t, std::size_t e, bool) { return m.edge_length(e); });
}

// The completion of the named parameter completed_homology_class (issue 46): as shortest_path_completion(),
// but following the curve's direction at both ends of a gap: a path leaves its arrival endpoint p forward
// (its first edge at an acute angle to the direction the curve arrives in) and reaches a departure endpoint
// from behind (its last edge at an acute angle to the direction the curve departs in). The direction at an
// endpoint is the sum of the unit directions of travel of the curve edges there. The shortest joins are
// made first.
inline std::vector<double> directed_completion(const Mesh_tables& m, const std::vector<double>& chain)
{
  const std::vector<double> d = chain_boundary(m, chain);
  std::vector<double> direction(3 * m.nv, 0.);
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    if(std::abs(chain[e]) <= chain_tolerance) continue;
    const std::size_t a = m.ev[2 * e], b = m.ev[2 * e + 1];
    const double unit = (chain[e] > 0 ? 1. : -1.) / (m.edge_length(e) > 0 ? m.edge_length(e) : 1.);
    for(std::size_t end : {a, b})
      if(std::abs(d[end]) > chain_tolerance)
        for(int k = 0; k < 3; ++k) direction[3 * end + k] += unit * (m.point(b)[k] - m.point(a)[k]);
  }
  // (to - from) . direction at `at` > 0
  auto ahead = [&](std::size_t from, std::size_t to, std::size_t at) {
    double s = 0;
    for(int k = 0; k < 3; ++k) s += (m.point(to)[k] - m.point(from)[k]) * direction[3 * at + k];
    return s > 0;
  };
  return shortest_path_completion(m, chain, [&](std::size_t p, std::size_t v, std::size_t x, std::size_t e, bool x_departs) {
    if((v == p && !ahead(p, x, p)) || (x_departs && !ahead(v, x, x))) return std::numeric_limits<double>::infinity();
    return m.edge_length(e);
  }, true);
}

// The reduced residual problem (paper Sec. 6): after completing the gaps, the faces are grouped
// into regions separated by the completed curve; gamma is integrated along a spanning tree of each
// region, and one shift per region is optimized with the objective of Eq. 11 (without its bounds)
// over the arcs of the completed curve. Jumps of the integrated function inside a region (periods around
// handles that no curve crosses) are not modelled: that is the approximation. Returns v per corner.
template <class Solver>
std::vector<double> reduced_residual_function(const Mesh_tables& m, const std::vector<double>& chain,
                                              const std::vector<double>& gamma, double epsilon, Solver& solver,
                                              bool concurrent, double& objective, std::size_t& n_vars, std::size_t& n_rows)
{
  std::vector<double> completed = shortest_path_completion(m, chain);
  for(std::size_t e = 0; e < m.ne; ++e) completed[e] += chain[e];

  // regions and the integration of gamma along a breadth-first tree of each region
  const std::size_t none = npos;
  std::vector<std::size_t> region(m.nf, none), region_component;
  std::vector<double> v(3 * m.nf, 0.);
  auto gamma_along = [&](std::size_t side) { return m.fs[side] * gamma[m.fe[side]]; };
  std::vector<std::size_t> queue;
  for(std::size_t seed = 0; seed < m.nf; ++seed)
  {
    if(region[seed] != none) continue;
    const std::size_t r = region_component.size();
    region_component.push_back(m.face_component[seed]);
    region[seed] = r;
    integrate_in_face(m, gamma, seed, v);
    queue.assign(1, seed);
    for(std::size_t q = 0; q < queue.size(); ++q)
    {
      const std::size_t f = queue[q];
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t s = 3 * f + k, a = m.edge_arc[m.fe[s]];
        if(a == npos || std::abs(completed[m.fe[s]]) > chain_tolerance) continue;
        const std::size_t other = (m.arcs[a].left_side == s) ? m.arcs[a].right_side : m.arcs[a].left_side;
        const std::size_t g = other / 3;
        if(region[g] != none) continue;
        region[g] = r;
        // continuity across the shared edge, then gamma along the neighbour's sides
        const std::size_t c0 = other, c1 = Mesh_tables::next_in_face(other), c2 = Mesh_tables::prev_in_face(other);
        v[c0] = v[m.corner_at(f, m.fv[c0])];
        v[c1] = v[m.corner_at(f, m.fv[c1])];
        v[c2] = v[c1] + gamma_along(c1);
        queue.push_back(g);
      }
    }
  }

  // the reduced problem: one shift per region, over the arcs of the completed curve between regions
  // costs as in Eq. 11: eps * length on curve arcs, length on completion arcs
  const Residual_problem full = residual_problem(m, v, chain, epsilon);
  Residual_problem P;
  P.number_of_faces = region_component.size();
  std::vector<char> gauge(m.n_components, 0);
  for(std::size_t r = 0; r < region_component.size(); ++r)
    if(!gauge[region_component[r]]) { gauge[region_component[r]] = 1; P.gauge_faces.push_back(r); }
  for(std::size_t a = 0; a < full.number_of_arcs(); ++a)
  {
    const std::size_t L = region[full.left[a]], R = region[full.right[a]];
    if(L == R) continue;   // inside a region the jump is fixed by the integration
    P.left.push_back(L);
    P.right.push_back(R);
    P.s.push_back(full.s[a]);
    P.cost.push_back(full.cost[a]);
    // no bounds: the integration paths inside a region ignore its periods, so the arcs between two
    // regions may carry different s and the bounds 0 <= J / Gamma <= 1 could be infeasible (the
    // authors' reduced LP has no bounds either)
    P.lower.push_back(-std::numeric_limits<double>::infinity());
    P.upper.push_back(std::numeric_limits<double>::infinity());
  }
  const std::vector<double> x = residual_function(P, solver, objective, n_vars, n_rows, concurrent);
  for(std::size_t c = 0; c < 3 * m.nf; ++c) v[c] += x[region[c / 3]];
  return v;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
