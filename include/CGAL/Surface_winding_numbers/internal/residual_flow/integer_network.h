// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The residual problem (paper Eq. 11) in the integers of the flow algorithms, and back: fixed arcs
// contracted, the gauge fixed along a spanning forest, jumps, bounds and weights scaled and rounded;
// sigma recovered from the optimal potentials.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_INTEGER_NETWORK_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_INTEGER_NETWORK_H

#include <CGAL/Surface_winding_numbers/Residual_problem.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// Beyond 2^42 the scaled jumps start to carry the rounding noise of the doubles (the gauge-fixed
// jumps are sums of differences of values of order 1..100, whose ulp is 2^-52..2^-46): on the
// demo torus 155 arcs keep a nonzero cost at 2^42, 256 at 2^44, 463 at 2^46. That noise only
// makes network simplex slower.
constexpr int max_cost_exponent = 42;

// The problem over the contracted nodes in scaled integers, and what the recovery of sigma needs.
struct Integer_problem
{
  std::size_t nodes = 0;
  std::vector<Int_arc> arcs;
  Int U = 0;                               // capacity of the penalty arcs: exceeds every optimal flow
  int k = 0;                               // jumps and bounds are scaled by 2^k
  std::vector<std::size_t> face_node;      // face -> node
  std::vector<double> face_offset;         // sigma[face] - sigma[its node's first face]
  std::vector<double> sigma0;              // node -> its shift in the gauge (jump 0 on the forest)
  std::vector<std::size_t> component;      // node -> its connected component
  std::vector<std::size_t> roots;          // component -> its root node
  std::shared_ptr<const Adjacency> adjacency;   // node -> its arcs (the warm start's level shares it)
};

inline bool check_residual_problem(const Residual_problem& P, Context& ctx)
{
  const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
  if(P.right.size() != na || P.s.size() != na || P.cost.size() != na || P.lower.size() != na || P.upper.size() != na)
    return ctx.fail("the residual problem has arrays of different sizes");
  const double inf = std::numeric_limits<double>::infinity();
  for(std::size_t a = 0; a < na; ++a)
  {
    const auto at = [a] { return " at arc " + std::to_string(a); };   // built on failure only
    if(P.left[a] >= nf || P.right[a] >= nf) return ctx.fail("the residual problem has a face index out of range" + at());
    if(!std::isfinite(P.s[a])) return ctx.fail("the residual problem has a non-finite jump s" + at());
    if(!(P.cost[a] >= 0) || !std::isfinite(P.cost[a]))
      return ctx.fail("the residual problem has a negative or non-finite cost" + at());
    if(std::isnan(P.lower[a]) || std::isnan(P.upper[a]) || !(P.lower[a] <= P.upper[a]) || P.lower[a] == inf ||
       P.upper[a] == -inf)
      return ctx.fail("the residual problem has empty or invalid bounds" + at());
  }
  for(std::size_t f : P.gauge_faces)
    if(f >= nf) return ctx.fail("the residual problem has a gauge face out of range");
  return true;
}

// The arcs whose two bounds are equal fix the difference of their faces' shifts: the faces they join
// become one node, each face with its offset from the node's first face (breadth first along the
// fixed arcs). Fails if the fixed jumps do not add up around a cycle.
inline bool contract_fixed_arcs(const Residual_problem& P, Context& ctx, Integer_problem& ip)
{
  const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
  Union_find groups(nf);
  std::vector<std::size_t> first(nf + 1, 0), fixed;
  for(std::size_t a = 0; a < na; ++a)
    if(P.lower[a] == P.upper[a])
    {
      groups.unite(P.left[a], P.right[a]);
      fixed.push_back(a);
      ++first[P.left[a] + 1];
      ++first[P.right[a] + 1];
    }
  ctx.stats.fixed_arcs = fixed.size();
  for(std::size_t f = 0; f < nf; ++f) first[f + 1] += first[f];
  std::vector<std::size_t> at(first[nf]), fill(first.begin(), first.end() - 1);
  for(std::size_t a : fixed) { at[fill[P.left[a]]++] = a; at[fill[P.right[a]]++] = a; }
  ip.face_node.assign(nf, npos);
  ip.face_offset.assign(nf, 0.);
  std::vector<std::size_t> queue;
  std::size_t nn = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(groups.find(f) != f) continue;   // the smallest face of a group is its root
    ip.face_node[f] = nn;
    queue.assign(1, f);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(std::size_t k = first[queue[q]]; k < first[queue[q] + 1]; ++k)
      {
        const std::size_t a = at[k], x = queue[q];
        const std::size_t y = P.left[a] == x ? P.right[a] : P.left[a];
        if(ip.face_node[y] != npos) continue;
        // sigma[L] - sigma[R] = lower - s
        const double d = P.lower[a] - P.s[a];
        ip.face_offset[y] = P.left[a] == x ? ip.face_offset[x] - d : ip.face_offset[x] + d;
        ip.face_node[y] = nn;
        queue.push_back(y);
      }
    ++nn;
  }
  double worst_gap = 0;
  for(std::size_t a : fixed)
    worst_gap = (std::max)(worst_gap, std::abs(ip.face_offset[P.left[a]] - ip.face_offset[P.right[a]] -
                                               (P.lower[a] - P.s[a])));
  if(!(worst_gap <= ctx.options.feasibility_tolerance))
    return ctx.fail("the arcs with a fixed jump (lower == upper) contradict each other around a cycle by " +
                    std::to_string(worst_gap));
  ip.nodes = ctx.stats.nodes = nn;
  return true;
}

// Builds the integer problem (ip: empty, or the last one, whose storage is reused): contraction, then
// the remaining arcs over the nodes, a breadth-first spanning forest along which the jump is made 0
// (components rooted at gauge faces first, so that only the arcs that close a nonzero cycle of s keep
// a nonzero cost), and the scaling: jumps and
// bounds by 2^k with k the largest exponent up to 42 for which no node potential can exceed 2^59,
// weights by 2^m so that all capacities add up to at most 2^58.
inline bool build_integer_problem(const Residual_problem& P, Context& ctx, Integer_problem& ip)
{
  if(!contract_fixed_arcs(P, ctx, ip)) return false;
  const std::size_t na = P.number_of_arcs(), nn = ip.nodes;
  if(nn > std::size_t((std::numeric_limits<int>::max)() / 2) || na > std::size_t((std::numeric_limits<int>::max)() / 4))
    return ctx.fail("the residual problem is too large for LEMON's graphs (int indices)");

  // the remaining arcs, in doubles for now (sh: the jump s over the nodes)
  std::vector<std::size_t> kept;
  std::vector<double> s(na);
  double constant_violation = 0;
  for(std::size_t a = 0; a < na; ++a)
  {
    if(P.lower[a] == P.upper[a]) continue;
    const std::size_t L = ip.face_node[P.left[a]], R = ip.face_node[P.right[a]];
    s[a] = P.s[a] + ip.face_offset[P.left[a]] - ip.face_offset[P.right[a]];
    if(L == R)
    {
      ++ctx.stats.constant_arcs;   // constant jump s: only its bounds matter
      constant_violation = (std::max)(constant_violation, (std::max)(P.lower[a] - s[a], s[a] - P.upper[a]));
      continue;
    }
    if(P.cost[a] == 0 && !P.is_bounded(a)) continue;   // no effect on anything
    kept.push_back(a);
  }
  if(!(constant_violation <= ctx.options.feasibility_tolerance))
    return ctx.fail("the residual problem is infeasible: an arc whose faces are joined by fixed arcs violates its bounds by " +
                    std::to_string(constant_violation));
  // ip may hold the last problem (a solver's re-solve): its adjacency serves again if the arcs join
  // the same nodes
  bool same_arcs = ip.adjacency && ip.adjacency->first.size() == nn + 1 && ip.arcs.size() == kept.size();
  ip.arcs.resize(kept.size());
  for(std::size_t i = 0; i < kept.size(); ++i)
  {
    Int_arc& e = ip.arcs[i];
    const std::size_t L = ip.face_node[P.left[kept[i]]], R = ip.face_node[P.right[kept[i]]];
    same_arcs = same_arcs && e.L == L && e.R == R;
    e.L = L;
    e.R = R;
    e.has_lo = std::isfinite(P.lower[kept[i]]);
    e.has_up = std::isfinite(P.upper[kept[i]]);
  }

  // gauge: jump 0 on a breadth-first spanning forest
  if(!same_arcs)
  {
    ip.adjacency.reset();   // not stale if the next line throws
    ip.adjacency = std::make_shared<const Adjacency>(nn, ip.arcs);
  }
  const Adjacency& adj = *ip.adjacency;
  ip.sigma0.assign(nn, 0.);
  ip.component.assign(nn, npos);
  ip.roots.clear();
  std::vector<char> tree(kept.size(), 0);
  std::vector<std::size_t> queue;
  auto grow = [&](std::size_t root) {
    if(ip.component[root] != npos) return;
    const std::size_t c = ip.roots.size();
    ip.roots.push_back(root);
    ip.component[root] = c;
    queue.assign(1, root);
    for(std::size_t q = 0; q < queue.size(); ++q)
      adj.for_each_neighbour(ip.arcs, queue[q], [&](std::size_t i, std::size_t y) {
        if(ip.component[y] != npos) return;
        const std::size_t x = queue[q];
        ip.component[y] = c;
        // J = s + sigma0[L] - sigma0[R] = 0
        ip.sigma0[y] = ip.arcs[i].L == x ? ip.sigma0[x] + s[kept[i]] : ip.sigma0[x] - s[kept[i]];
        tree[i] = 1;
        queue.push_back(y);
      });
  };
  for(std::size_t f : P.gauge_faces) grow(ip.face_node[f]);
  for(std::size_t v = 0; v < nn; ++v) grow(v);

  // scaling
  std::vector<double> st(kept.size());
  double B = 1, wsum = 0;
  for(std::size_t i = 0; i < kept.size(); ++i)
  {
    const std::size_t a = kept[i];
    const Int_arc& e = ip.arcs[i];
    st[i] = tree[i] ? 0. : s[a] + ip.sigma0[e.L] - ip.sigma0[e.R];
    double bound = 0;
    if(e.has_lo) bound = (std::max)(bound, std::abs(P.lower[a]));
    if(e.has_up) bound = (std::max)(bound, std::abs(P.upper[a]));
    B = (std::max)(B, std::abs(st[i]) + bound);
    wsum += P.cost[a];
  }
  const int k = (std::min)(max_cost_exponent, int(std::floor(59. - std::log2(double(nn + 1) * B))));
  if(k < 12)
    return ctx.fail("the residual problem's jumps are too large for the 64-bit integer scaling (largest |s| + |bound| " +
                    std::to_string(B) + " on " + std::to_string(nn) + " nodes)");
  const int m = wsum > 0 ? (std::max)(-1000, (std::min)(1000, int(std::floor(57. - std::log2(wsum))))) : 0;
  // x 2^e rounded (a product by a power of two: exact, as ldexp, and cheaper)
  const double two_k = std::ldexp(1., k), two_m = std::ldexp(1., m);
  auto to_int = [](double x, double two_e) { return Int(std::llround(x * two_e)); };
  Int finite_caps = 0;
  ctx.stats.nonzero_cost_arcs = 0;
  for(std::size_t i = 0; i < kept.size(); ++i)
  {
    const std::size_t a = kept[i];
    Int_arc& e = ip.arcs[i];
    e.sh = to_int(st[i], two_k);
    e.w = to_int(P.cost[a], two_m);
    e.lo = e.has_lo ? to_int(P.lower[a], two_k) : 0;
    e.up = e.has_up ? to_int(P.upper[a], two_k) : 0;
    finite_caps += 2 * e.w;
    if(e.sh != 0) ++ctx.stats.nonzero_cost_arcs;
  }
  ip.U = finite_caps + 1;
  ip.k = ctx.stats.cost_exponent = k;
  ctx.stats.capacity_exponent = m;
  return true;
}

// sigma = sigma0 + (pi - pi[root]) / 2^k on the nodes, plus the offsets of the contraction; the
// first gauge face of each component gets 0. Fails if sigma violates the bounds (the problem is
// infeasible: sigma is then the solution of least penalized violation).
inline bool recover_sigma(const Residual_problem& P, const Integer_problem& ip, const std::vector<Int>& pi, Context& ctx,
                          std::vector<double>& sigma)
{
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t nf = P.number_of_faces;
  std::vector<double> node_sigma(ip.nodes);
  const double unit = std::ldexp(1., -ip.k);
  for(std::size_t v = 0; v < ip.nodes; ++v)
    node_sigma[v] = ip.sigma0[v] + double(pi[v] - pi[ip.roots[ip.component[v]]]) * unit;
  sigma.resize(nf);
  for(std::size_t f = 0; f < nf; ++f) sigma[f] = node_sigma[ip.face_node[f]] + ip.face_offset[f];
  std::vector<double> shift(ip.roots.size(), 0.);
  std::vector<char> shifted(ip.roots.size(), 0);
  for(std::size_t f : P.gauge_faces)
  {
    const std::size_t c = ip.component[ip.face_node[f]];
    if(shifted[c]) continue;
    shifted[c] = 1;
    shift[c] = sigma[f];
  }
  for(std::size_t f = 0; f < nf; ++f) sigma[f] -= shift[ip.component[ip.face_node[f]]];
  Statistics& st = ctx.stats;
  st.objective = P.objective(sigma);
  st.max_violation = P.max_violation(sigma);
  st.time_recover = seconds_since(t0);
  if(std::ostream* log = ctx.log())
    *log << "[swn] LEMON " << (st.algorithm == Options::MULTILEVEL ? "multilevel" : "network simplex")
         << (st.fallback ? " (fallback)" : "") << ": " << st.nodes << " nodes, " << ip.arcs.size() << " arcs ("
         << st.fixed_arcs << " fixed arcs contracted, " << st.nonzero_cost_arcs << " nonzero costs after gauge), scale 2^"
         << ip.k << " / 2^" << st.capacity_exponent << ", objective " << st.objective << ", violation "
         << st.max_violation << (st.certified ? ", certified" : "") << "; build " << st.time_build << " s, solve "
         << st.time_solve << " s\n";
  const double tolerance = (std::max)(ctx.options.feasibility_tolerance, std::ldexp(1., 1 - ip.k));
  if(!(st.max_violation <= tolerance))
    return ctx.fail("the residual problem is infeasible: the least-violation solution violates the bounds by " +
                    std::to_string(st.max_violation));
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
