// Benchmark generator: the planted nonbounding loops (a greedy homology basis of H1(M, border),
// straightened).

#ifndef SWN_BENCH_GEN_LOOPS_H
#define SWN_BENCH_GEN_LOOPS_H

#include "gen_common.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <queue>

namespace swn_bench {

// Straightens a loop (paper: FlipOut, then snapped back to edges): repeatedly replaces a stretch of
// the loop by the shortest edge path between its ends inside a thin corridor around the stretch
// (a few rings of faces, so the replacement is homotopic), until no stretch gets shorter. Border
// edges are never used, nor edges of infinite length in `len` (edges to avoid: a stretch using one is
// replaced by any path that avoids them). The caller checks that the result is homologous to the input.
inline std::vector<VI> straighten_loop(const Mesh& m, std::vector<VI> loop, const std::vector<double>& len, Rng& rng,
                                       int passes = 6)
{
  const std::size_t nv = m.number_of_vertices();
  std::vector<int> stamp(nv, -1), dist_stamp(nv, -1), ring(nv, 0);
  std::vector<double> dist(nv);
  std::vector<HI> par(nv);
  int stamp_id = 0;
  auto edge_len = [&](VI a, VI b) { return len[std::size_t(m.edge(m.halfedge(a, b)))]; };
  for(int pass = 0; pass < passes; ++pass)
  {
    bool improved = false;
    const std::size_t n0 = loop.size();
    if(n0 < 6) break;
    std::rotate(loop.begin(), loop.begin() + std::ptrdiff_t(rng.index(n0)), loop.end());
    const std::size_t k = std::max<std::size_t>(3, std::min<std::size_t>(n0 / 3, 40));
    for(std::size_t start = 0; start + k < loop.size(); start += k / 2)
    {
      // corridor: vertices within 3 rings of the stretch loop[start..start+k]
      ++stamp_id;
      std::vector<VI> frontier;
      double old_len = 0;
      for(std::size_t i = start; i <= start + k; ++i)
      {
        if(stamp[std::size_t(loop[i])] != stamp_id) { stamp[std::size_t(loop[i])] = stamp_id; ring[std::size_t(loop[i])] = 0; frontier.push_back(loop[i]); }
        if(i > start) old_len += edge_len(loop[i - 1], loop[i]);
      }
      for(int r = 1; r <= 3; ++r)
      {
        std::vector<VI> next;
        for(VI x : frontier)
          for(VI y : CGAL::vertices_around_target(m.halfedge(x), m))
            if(stamp[std::size_t(y)] != stamp_id) { stamp[std::size_t(y)] = stamp_id; ring[std::size_t(y)] = r; next.push_back(y); }
        frontier.swap(next);
      }
      // Dijkstra from a to b inside the corridor, over interior edges
      const VI a = loop[start], b = loop[start + k];
      typedef std::pair<double, std::size_t> QE;
      std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
      dist_stamp[std::size_t(a)] = stamp_id;
      dist[std::size_t(a)] = 0;
      q.push({0., std::size_t(a)});
      bool reached = false;
      while(!q.empty())
      {
        auto [d, xi] = q.top();
        q.pop();
        if(d > dist[xi]) continue;
        if(xi == std::size_t(b)) { reached = true; break; }
        const VI x(static_cast<Mesh::size_type>(xi));
        for(HI h : CGAL::halfedges_around_source(x, m))
        {
          if(m.is_border(m.edge(h))) continue;
          const std::size_t y = std::size_t(m.target(h));
          if(stamp[y] != stamp_id) continue;
          const double nd = d + len[std::size_t(m.edge(h))];
          if(!std::isfinite(nd)) continue;
          if(dist_stamp[y] != stamp_id || nd < dist[y]) { dist_stamp[y] = stamp_id; dist[y] = nd; par[y] = h; q.push({nd, y}); }
        }
      }
      if(!reached || dist[std::size_t(b)] >= old_len * (1 - 1e-9)) continue;
      std::vector<VI> path;
      for(VI x = b; x != a; x = m.source(par[std::size_t(x)])) path.push_back(x);
      path.push_back(a);
      std::reverse(path.begin(), path.end());   // a ... b
      std::vector<VI> nl(loop.begin(), loop.begin() + std::ptrdiff_t(start));
      nl.insert(nl.end(), path.begin(), path.end());
      nl.insert(nl.end(), loop.begin() + std::ptrdiff_t(start + k + 1), loop.end());
      loop.swap(nl);
      improved = true;
    }
    if(!improved) break;
  }
  return loop;
}

// Greedy homology basis (Erickson-Whittlesey 2005) of the surface with its border loops capped by
// virtual cones, plus shortest arcs between border loops: a basis of H1(M, border) made of chains on
// interior edges. Generators that would use a border edge are dropped.
struct Basis
{
  std::vector<Chain> loops;     // handle loops
  std::vector<std::vector<VI>> loop_vertices;   // the same, as cyclic vertex sequences
  std::vector<Chain> arcs;      // arcs from border loop j to border loop 0
  int dropped = 0;
};

// `avoid` (per edge, optional): edges the arcs between border loops may not use.
inline Basis homology_basis(const Mesh& m, Rng& rng, const std::vector<char>* avoid = nullptr)
{
  Basis B;
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  std::vector<double> len(ne);
  for(EI e : m.edges()) len[std::size_t(e)] = std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  const auto loops = border_loops(m);

  // shortest-path tree over interior edges from a random root
  auto dijkstra = [&](const std::vector<VI>& sources, std::vector<double>& dist, std::vector<HI>& parent,
                      const std::vector<char>* stop_at, VI* reached, const std::vector<char>* skip) {
    dist.assign(nv, std::numeric_limits<double>::infinity());
    parent.assign(nv, Mesh::null_halfedge());
    typedef std::pair<double, std::size_t> QE;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
    for(VI s : sources) { dist[std::size_t(s)] = 0; q.push({0., std::size_t(s)}); }
    while(!q.empty())
    {
      auto [d, vi] = q.top();
      q.pop();
      if(d > dist[vi]) continue;
      const VI v(static_cast<Mesh::size_type>(vi));
      if(stop_at && (*stop_at)[vi]) { *reached = v; return; }
      for(HI h : CGAL::halfedges_around_source(v, m))   // h: v -> target(h)
      {
        if(m.is_border(m.edge(h)) || (skip && (*skip)[std::size_t(m.edge(h))])) continue;
        const std::size_t w = std::size_t(m.target(h));
        const double nd = d + len[std::size_t(m.edge(h))];
        if(nd < dist[w]) { dist[w] = nd; parent[w] = h; q.push({nd, w}); }
      }
    }
  };

  std::vector<double> dist;
  std::vector<HI> parent;
  VI root;
  do root = VI(Mesh::size_type(rng.index(nv))); while(m.is_border(root));
  dijkstra({root}, dist, parent, nullptr, nullptr, nullptr);
  std::vector<char> in_tree(ne, 0);
  for(std::size_t v = 0; v < nv; ++v)
    if(parent[v] != Mesh::null_halfedge()) in_tree[std::size_t(m.edge(parent[v]))] = 1;

  // dual nodes: faces, then one cone face per border halfedge
  std::map<std::size_t, std::size_t> cone_face;   // border halfedge -> dual node
  std::size_t nnodes = nf;
  for(const auto& L : loops)
    for(HI h : L) cone_face[std::size_t(h)] = nnodes++;
  struct DualEdge { double w; std::size_t a, b; long edge; };   // edge < 0: cone edge
  std::vector<DualEdge> de;
  const double top = std::numeric_limits<double>::max();
  for(EI e : m.edges())
  {
    const HI h = m.halfedge(e), o = m.opposite(h);
    if(m.is_border(e))
    {
      const HI hb = m.is_border(h) ? h : o, hf = m.is_border(h) ? o : h;
      de.push_back({top, std::size_t(m.face(hf)), cone_face[std::size_t(hb)], long(std::size_t(e))});
      continue;
    }
    if(in_tree[std::size_t(e)]) continue;
    const double w = dist[std::size_t(m.source(h))] + len[std::size_t(e)] + dist[std::size_t(m.target(h))];
    de.push_back({std::isfinite(w) ? w : top, std::size_t(m.face(h)), std::size_t(m.face(o)), long(std::size_t(e))});
  }
  for(const auto& L : loops)   // cone edges between consecutive cone faces; the first one is the tree edge
    for(std::size_t i = 1; i < L.size(); ++i)
      de.push_back({top, cone_face[std::size_t(L[i - 1])], cone_face[std::size_t(L[i])], -1});
  std::stable_sort(de.begin(), de.end(), [](const DualEdge& x, const DualEdge& y) { return x.w > y.w; });
  std::vector<std::size_t> uf(nnodes);
  std::iota(uf.begin(), uf.end(), std::size_t(0));
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    while(uf[x] != x) { uf[x] = uf[uf[x]]; x = uf[x]; }
    return x;
  };
  std::vector<long> leftover;
  for(const DualEdge& d : de)
  {
    const std::size_t a = find(d.a), b = find(d.b);
    if(a != b) uf[std::max(a, b)] = std::min(a, b);
    else leftover.push_back(d.edge);
  }
  for(long le : leftover)
  {
    if(le < 0 || m.is_border(EI(Mesh::size_type(le)))) { ++B.dropped; continue; }
    const EI e(static_cast<Mesh::size_type>(le));
    const VI u = m.source(m.halfedge(e)), v = m.target(m.halfedge(e));
    if(!std::isfinite(dist[std::size_t(u)]) || !std::isfinite(dist[std::size_t(v)])) { ++B.dropped; continue; }
    // the loop LCA -> ... -> u -> v -> ... -> LCA as a cyclic vertex sequence
    std::vector<VI> up_u{u}, up_v{v};
    for(VI x = u; x != root; x = m.source(parent[std::size_t(x)])) up_u.push_back(m.source(parent[std::size_t(x)]));
    for(VI x = v; x != root; x = m.source(parent[std::size_t(x)])) up_v.push_back(m.source(parent[std::size_t(x)]));
    while(up_u.size() > 1 && up_v.size() > 1 && up_u[up_u.size() - 2] == up_v[up_v.size() - 2]) { up_u.pop_back(); up_v.pop_back(); }
    std::vector<VI> loop(up_u.rbegin(), up_u.rend());   // LCA ... u
    loop.insert(loop.end(), up_v.begin(), up_v.end() - 1);   // v ... (before LCA)
    Chain c = loop_chain(m, loop);
    if(!is_closed(m, c)) { std::cerr << "[gen] internal error: open basis loop\n"; ++B.dropped; continue; }
    B.loop_vertices.push_back(loop);
    B.loops.push_back(c);
  }

  // arcs from border loop j to border loop 0
  if(loops.size() >= 2)
  {
    std::vector<char> in_loop0(nv, 0);
    for(HI h : loops[0]) in_loop0[std::size_t(m.target(h))] = 1;
    for(std::size_t j = 1; j < loops.size(); ++j)
    {
      std::vector<VI> src;
      for(HI h : loops[j]) src.push_back(m.target(h));
      VI reached;
      std::vector<double> d2;
      std::vector<HI> p2;
      reached = Mesh::null_vertex();
      dijkstra(src, d2, p2, &in_loop0, &reached, avoid);
      if(reached == Mesh::null_vertex()) { ++B.dropped; continue; }
      Chain c(ne, 0);
      for(VI x = reached; p2[std::size_t(x)] != Mesh::null_halfedge(); x = m.source(p2[std::size_t(x)]))
        add_traversal(m, c, m.source(p2[std::size_t(x)]), x, 1);
      B.arcs.push_back(c);
    }
  }
  return B;
}


// The planted nonbounding chain of a case: a random nonempty subset of a homology basis of
// H1(M, border), with random signs, the loops straightened.
struct Planted
{
  Chain chain;
  int loops = 0, arcs = 0, basis_size = 0, dropped = 0, straightened = 0;
  int rerouting_failed = 0;   // basis loops left out: they could not be routed off the region curves
  bool nontrivial = true;
};

// `region` (optional): the region curve; the loops and arcs are then routed so that they share no edge
// with it (they cross it at vertices only): straightening treats its edges as infinitely long, and a
// loop still on one is left out of the basis.
inline Planted plant_loops(const Mesh& m, const Topology& topo, const std::vector<double>& edge_len, bool straighten,
                           const Chain* region, Rng& rng)
{
  Planted P;
  P.chain.assign(m.number_of_edges(), 0);
  if(topo.simply_connected()) return P;
  std::vector<char> avoid;
  std::vector<double> len = edge_len;
  if(region)
  {
    avoid.assign(m.number_of_edges(), 0);
    for(std::size_t e = 0; e < avoid.size(); ++e)
      if((*region)[e] != 0) { avoid[e] = 1; len[e] = std::numeric_limits<double>::infinity(); }
  }
  Basis B = homology_basis(m, rng, region ? &avoid : nullptr);
  P.basis_size = int(B.loops.size() + B.arcs.size());
  if(straighten)
    for(std::size_t i = 0; i < B.loops.size(); ++i)
    {
      const std::vector<VI> sl = straighten_loop(m, B.loop_vertices[i], len, rng, region ? 12 : 6);
      const Chain c2 = loop_chain(m, sl);
      Chain d(c2.size());
      for(std::size_t e = 0; e < d.size(); ++e) d[e] = c2[e] - B.loops[i][e];
      if(is_closed(m, c2) && is_relative_boundary(m, d)) { B.loops[i] = c2; ++P.straightened; }
    }
  P.dropped = B.dropped;
  std::vector<std::pair<int, const Chain*>> all;
  auto off_region = [&](const Chain& c) {
    for(std::size_t e = 0; e < c.size(); ++e)
      if(c[e] != 0 && !avoid.empty() && avoid[e]) return false;
    return true;
  };
  for(const Chain& c : B.loops)
  {
    if(off_region(c)) all.push_back({0, &c});
    else ++P.rerouting_failed;
  }
  for(const Chain& c : B.arcs) all.push_back({1, &c});
  if(all.empty()) return P;
  const std::size_t k = 1 + rng.index(all.size());
  for(std::size_t i = all.size(); i > 1; --i) std::swap(all[i - 1], all[rng.index(i)]);
  for(std::size_t i = 0; i < k; ++i)
  {
    const int sgn = rng.coin() ? 1 : -1;
    for(std::size_t e = 0; e < P.chain.size(); ++e) P.chain[e] += sgn * (*all[i].second)[e];
    (all[i].first == 0 ? P.loops : P.arcs)++;
  }
  P.nontrivial = !is_relative_boundary(m, P.chain);
  return P;
}

} // namespace swn_bench

#endif // SWN_BENCH_GEN_LOOPS_H
