// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The hierarchy of contracted problems of the multilevel residual solver: clusters of nodes joined
// by free arcs without jump share one shift on the next coarser level; flows are carried back down.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_HIERARCHY_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_HIERARCHY_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// lv.component from a numbering of the connected components (node -> 0, 1, ...): each named by its
// first node, as find_components() names them
inline void name_components(Level& lv, const std::vector<std::size_t>& component, std::size_t count)
{
  std::vector<std::size_t> first_node(count, npos);
  lv.component.resize(lv.n);
  for(std::size_t v = 0; v < lv.n; ++v)
  {
    if(first_node[component[v]] == npos) first_node[component[v]] = v;
    lv.component[v] = first_node[component[v]];
  }
}

// lv.component: every node's connected component, named by its first node
inline void find_components(Level& lv)
{
  const Adjacency adj(lv.n, lv.arcs);
  std::vector<std::size_t> piece(lv.n, npos);
  const std::size_t count = number_pieces(lv.n, lv.arcs, adj, [](std::size_t) { return true; }, piece, 0);
  name_components(lv, piece, count);
}

// Clusters of at most `cap` nodes grown breadth first over contractible arcs; a node joins a cluster
// only if all its arcs into the cluster are contractible (then every jump inside the cluster is 0
// when its nodes share one shift). Returns the number of clusters.
inline std::size_t cluster_nodes(const Level& lv, std::size_t cap, std::vector<std::size_t>& cluster)
{
  const Adjacency adj(lv.n, lv.arcs);
  cluster.assign(lv.n, npos);
  std::size_t nc = 0;
  std::vector<std::size_t> members;
  for(std::size_t seed = 0; seed < lv.n; ++seed)
  {
    if(cluster[seed] != npos) continue;
    const std::size_t c = nc++;
    cluster[seed] = c;
    members.assign(1, seed);
    for(std::size_t q = 0; q < members.size() && members.size() < cap; ++q)
      for(std::size_t k = adj.first[members[q]]; k < adj.first[members[q] + 1] && members.size() < cap; ++k)
      {
        const Int_arc& e = lv.arcs[adj.arc[k]];
        const std::size_t y = e.L == members[q] ? e.R : e.L;
        if(cluster[y] != npos || !contractible(e)) continue;
        bool ok = true;
        for(std::size_t j = adj.first[y]; j < adj.first[y + 1] && ok; ++j)
        {
          const Int_arc& f = lv.arcs[adj.arc[j]];
          ok = cluster[f.L == y ? f.R : f.L] != c || contractible(f);
        }
        if(!ok) continue;
        cluster[y] = c;
        members.push_back(y);
      }
  }
  return nc;
}

// The next coarser level of lv (whose `parent` holds the clusters): clusters become nodes; arcs
// inside a cluster vanish (their jump is 0), parallel contractible arcs merge (their weights add).
inline Level coarsen(Level& lv, std::size_t nc)
{
  Level next;
  next.n = nc;
  lv.arc_parent.assign(lv.arcs.size(), npos);
  lv.arc_sign.assign(lv.arcs.size(), 1);
  std::vector<std::size_t> free_arcs;   // fine arcs that become contractible coarse arcs
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)
  {
    const Int_arc& e = lv.arcs[i];
    const std::size_t L = lv.parent[e.L], R = lv.parent[e.R];
    if(L == R) continue;
    if(contractible(e))
    {
      if(L > R) lv.arc_sign[i] = -1;   // w |pi[L] - pi[R]| is symmetric
      free_arcs.push_back(i);
    }
    else
    {
      lv.arc_parent[i] = next.arcs.size();
      next.arcs.push_back(e);
      next.arcs.back().L = L;
      next.arcs.back().R = R;
    }
  }
  auto key = [&](std::size_t i) {
    const std::size_t L = lv.parent[lv.arcs[i].L], R = lv.parent[lv.arcs[i].R];
    return std::make_pair((std::min)(L, R), (std::max)(L, R));
  };
  std::sort(free_arcs.begin(), free_arcs.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  for(std::size_t i = 0; i < free_arcs.size();)
  {
    const auto k = key(free_arcs[i]);
    Int_arc x = lv.arcs[free_arcs[i]];
    x.L = k.first;
    x.R = k.second;
    x.w = 0;
    for(; i < free_arcs.size() && key(free_arcs[i]) == k; ++i)
    {
      x.w += lv.arcs[free_arcs[i]].w;
      lv.arc_parent[free_arcs[i]] = next.arcs.size();
    }
    next.arcs.push_back(x);
  }
  find_components(next);
  return next;
}

// Level 0 holds the problem; coarser levels are added until one has at most `coarsest_nodes` nodes
// or clustering stalls (fewer than 20 % of the nodes merged).
inline std::vector<Level> build_hierarchy(std::size_t n, std::vector<Int_arc> arcs, const Options& options)
{
  std::vector<Level> levels(1);
  levels[0].n = n;
  levels[0].arcs = std::move(arcs);
  find_components(levels[0]);
  while(levels.back().n > (std::max)(std::size_t(1), options.coarsest_nodes))
  {
    std::vector<std::size_t> cluster;
    const std::size_t nc = cluster_nodes(levels.back(), (std::max)(std::size_t(2), options.cluster_size), cluster);
    if(10 * nc > 8 * levels.back().n) break;   // coarsening stalls
    levels.back().parent = std::move(cluster);
    Level next = coarsen(levels.back(), nc);
    levels.push_back(std::move(next));
  }
  return levels;
}

// The flow of the coarser level carried to the arcs of lv: a bundle's flow is shared in proportion
// to the weights (so |x| <= w when the bundle's |X| <= its weight; the units lost to rounding go to
// arcs with room left, so that the shares add up to X exactly). The imbalances this leaves inside
// the clusters are settled by balance_inside_regions() on large levels, by the certificate's maximum
// flow otherwise.
inline void prolong_flow(Level& lv, const Level& coarse)
{
  lv.x.assign(lv.arcs.size(), 0);
  std::vector<Int> given(coarse.arcs.size(), 0);   // the part of each coarse flow shared so far
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)
  {
    const std::size_t a = lv.arc_parent[i];
    if(a == npos) continue;
    const Int X = lv.arc_sign[i] * coarse.x[a];
    if(contractible(lv.arcs[i]) && coarse.arcs[a].w > 0)
      lv.x[i] = Int(Wide(X) * Wide(lv.arcs[i].w) / Wide(coarse.arcs[a].w));
    else
      lv.x[i] = X;
    given[a] += lv.arc_sign[i] * lv.x[i];
  }
  // the rounding remainders (fewer units than the bundle has arcs), one unit per arc with room
  for(std::size_t i = 0; i < lv.arcs.size(); ++i)
  {
    const std::size_t a = lv.arc_parent[i];
    if(a == npos || given[a] == coarse.x[a]) continue;
    const Int unit = lv.arc_sign[i] * (coarse.x[a] > given[a] ? 1 : -1);   // in the fine arc's sense
    const Int to = lv.x[i] + unit;
    if(contractible(lv.arcs[i]) && (to > lv.arcs[i].w || to < -lv.arcs[i].w)) continue;
    lv.x[i] = to;
    given[a] += lv.arc_sign[i] * unit;
  }
}

// Augmenting paths inside each region (region[v] < nr), from every excess to the deficits (breadth
// first, along the arcs inside the region with room left: their jump is 0, so their flow may lie
// anywhere in [-w, w]); stops once more than `work_limit` arcs were scanned. Returns the arcs scanned.
inline std::size_t route_inside_regions(const Level& lv, const std::vector<std::size_t>& region, std::size_t nr,
                                        std::vector<Int>& excess, std::vector<Int>& x, std::size_t work_limit)
{
  std::vector<std::size_t> member;   // the nodes with an excess, region by region
  {
    std::vector<std::size_t> first(nr + 1, 0);
    for(std::size_t v = 0; v < lv.n; ++v)
      if(excess[v] > 0) ++first[region[v] + 1];
    for(std::size_t c = 0; c < nr; ++c) first[c + 1] += first[c];
    member.resize(first[nr]);
    for(std::size_t v = 0; v < lv.n; ++v)
      if(excess[v] > 0) member[first[region[v]]++] = v;
  }
  if(member.empty()) return 0;
  const Adjacency inside(lv.n, lv.arcs, [&](const Int_arc& e) { return region[e.L] == region[e.R] && contractible(e); });
  auto room = [&](std::size_t i, std::size_t from) { return from == lv.arcs[i].L ? lv.arcs[i].w - x[i] : x[i] + lv.arcs[i].w; };
  // a search that finds no deficit marks what it reached as dead: a set that cannot reach a deficit
  // never will (an augmenting path never enters it, so no arc out of it gains room)
  std::vector<std::size_t> pred_arc(lv.n, npos), queue;
  std::vector<char> seen(lv.n, 0), dead(lv.n, 0);
  std::size_t work = 0;
  for(std::size_t s : member)
    while(excess[s] > 0 && !dead[s])
    {
      if(work > work_limit) return work;
      queue.assign(1, s);
      seen[s] = 1;
      std::size_t t = npos;
      for(std::size_t q = 0; q < queue.size() && t == npos; ++q)
      {
        const std::size_t u = queue[q];
        work += inside.first[u + 1] - inside.first[u];
        for(std::size_t j = inside.first[u]; j < inside.first[u + 1] && t == npos; ++j)
        {
          const std::size_t i = inside.arc[j];
          const std::size_t y = lv.arcs[i].L == u ? lv.arcs[i].R : lv.arcs[i].L;
          if(seen[y] || dead[y] || room(i, u) <= 0) continue;
          seen[y] = 1;
          pred_arc[y] = i;
          queue.push_back(y);
          if(excess[y] < 0) t = y;
        }
      }
      for(std::size_t u : queue) { seen[u] = 0; if(t == npos) dead[u] = 1; }
      if(t == npos) break;
      Int d = (std::min)(excess[s], -excess[t]);
      for(int pass = 0; pass < 2; ++pass)   // the bottleneck, then the augmentation
        for(std::size_t y = t; y != s;)
        {
          const std::size_t i = pred_arc[y];
          const std::size_t u = lv.arcs[i].L == y ? lv.arcs[i].R : lv.arcs[i].L;
          if(pass == 0) d = (std::min)(d, room(i, u));
          else x[i] += u == lv.arcs[i].L ? d : -d;
          y = u;
        }
      excess[s] -= d;
      excess[t] += d;
    }
  return work;
}

// The shares of the bundles leave imbalances at the nodes of each cluster that add up to the coarse
// node's (0: the coarse flow is a circulation); on levels of at least
// Options::carried_flow_routing_nodes nodes they are routed along the arcs inside the cluster,
// then inside the clusters of clusters, and so on up the hierarchy, while the regions have at most
// 512 nodes of the level on average and the searches of a region level stay within 16 arc scans per
// arc of the level. What remains goes to the certificate's maximum flow. (chain10, 1.15M faces:
// residual about 20 % longer without it; on levels below 100k nodes push-relabel alone is faster.)
inline void balance_inside_regions(Context& ctx, const std::vector<Level>& levels, std::size_t l, std::vector<Int>& x)
{
  const Level& lv = levels[l];
  if(lv.n < ctx.options.carried_flow_routing_nodes) return;
  ++ctx.stats.routed_levels;
  std::vector<Int> excess(lv.n, Int(0));
  for(std::size_t i = 0; i < lv.arcs.size(); ++i) { excess[lv.arcs[i].L] -= x[i]; excess[lv.arcs[i].R] += x[i]; }
  std::vector<std::size_t> region = lv.parent;
  const std::size_t work_limit = 16 * lv.arcs.size();
  for(std::size_t c = l + 1;; ++c)   // region[v]: v's node on level c
  {
    const std::size_t work = route_inside_regions(lv, region, levels[c].n, excess, x, work_limit);
    if(work > work_limit || c + 1 >= levels.size() || lv.n > 512 * levels[c + 1].n) break;
    for(std::size_t v = 0; v < lv.n; ++v) region[v] = levels[c].parent[region[v]];
  }
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
