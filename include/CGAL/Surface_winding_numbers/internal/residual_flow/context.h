// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The exact residual solver (paper Eq. 11 as a minimum-cost circulation): the types its steps share.
// The steps are free functions over one Context, one file each:
//   integer_network.h       contraction, gauge, integer scaling; sigma recovered from the potentials
//   network_simplex.h       LEMON's network simplex and its duality certificate
//   hierarchy.h             contracted levels, flows carried down
//   bands.h                 bands around the jumps re-solved exactly
//   max_flow_certificate.h  optimality of a level as a maximum flow; barriers of refused certificates
//   descent.h               steepest-descent steps along the barriers
//   multilevel.h            the levels from coarse to fine

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_CONTEXT_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_CONTEXT_H

#include <CGAL/Surface_winding_numbers/LEMON_residual_solver_options.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/boykov_kolmogorov_flow.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/warm_push_relabel.h>

#include <chrono>
#include <cstddef>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

typedef long long Int;
#ifdef __SIZEOF_INT128__
__extension__ typedef __int128 Wide;   // exact duality certificate and line searches
constexpr bool has_wide = true;
#else
typedef long double Wide;
constexpr bool has_wide = false;
#endif
constexpr std::size_t npos = std::size_t(-1);

typedef LEMON_residual_solver_options Options;
typedef LEMON_residual_solver_statistics Statistics;

// What every step reads (the options) and writes (the statistics, messages).
struct Context
{
  Options options;
  Statistics stats;
  std::string error;
  bool augmenting_paths = false;   // certificates by Warm_push_relabel::run_paths() (the warm start's)

  bool fail(const std::string& why)
  {
    error = why;
    if(options.verbose) std::cerr << "[swn] " << why << "\n";
    return false;
  }
  bool concurrent() const { return options.concurrent; }
  std::ostream* log() const { return options.verbose ? &std::cerr : nullptr; }
};

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A problem arc in scaled integers: its jump is J = sh + pi[L] - pi[R], its cost w |J| plus U times
// the distance of J to [lo, up] (the bounds that exist: has_lo, has_up).
struct Int_arc
{
  std::size_t L, R;
  Int sh, w, lo, up;
  bool has_lo, has_up;
};

inline Int tension(const Int_arc& e, const std::vector<Int>& pi) { return e.sh + pi[e.L] - pi[e.R]; }
// an arc without bounds and without jump: its two nodes may share one shift
inline bool contractible(const Int_arc& e) { return !e.has_lo && !e.has_up && e.sh == 0; }

// one-sided derivatives of the cost f(J) = w |J| + U dist(J, [lo, up]) of arc e
inline Int right_slope(const Int_arc& e, Int J, Int U)
{
  Int d = J >= 0 ? e.w : -e.w;
  if(e.has_up && J >= e.up) d += U;
  if(e.has_lo && J < e.lo) d -= U;
  return d;
}
inline Int left_slope(const Int_arc& e, Int J, Int U)
{
  Int d = J > 0 ? e.w : -e.w;
  if(e.has_up && J > e.up) d += U;
  if(e.has_lo && J <= e.lo) d -= U;
  return d;
}
// calls f(b) once for every tension b where the cost of arc e has a kink: 0 and its bounds
template <class F>
void for_each_kink(const Int_arc& e, F f)
{
  f(Int(0));
  if(e.has_lo && e.lo != 0) f(e.lo);
  if(e.has_up && e.up != 0 && !(e.has_lo && e.up == e.lo)) f(e.up);
}

// node -> incident arcs (those for which `keep` holds), in compressed rows
struct Adjacency
{
  std::vector<std::size_t> first, arc;
  Adjacency(std::size_t n, const std::vector<Int_arc>& arcs) : Adjacency(n, arcs, [](const Int_arc&) { return true; }) {}
  template <class Keep>
  Adjacency(std::size_t n, const std::vector<Int_arc>& arcs, Keep keep) : first(n + 1, 0)
  {
    for(const Int_arc& e : arcs)
      if(keep(e)) { ++first[e.L + 1]; ++first[e.R + 1]; }
    for(std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    arc.resize(first[n]);
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < arcs.size(); ++i)
      if(keep(arcs[i])) { arc[fill[arcs[i].L]++] = i; arc[fill[arcs[i].R]++] = i; }
  }
  // calls f(arc index, the other end) for every kept arc at v
  template <class F>
  void for_each_neighbour(const std::vector<Int_arc>& arcs, std::size_t v, F f) const
  {
    for(std::size_t k = first[v]; k < first[v + 1]; ++k)
    {
      const Int_arc& e = arcs[arc[k]];
      f(arc[k], e.L == v ? e.R : e.L);
    }
  }
};

// What the certificates of a level keep from one to the next: the maximum flows' graphs (built by
// the first certificate, reused by those that follow the descent steps, which only change
// capacities), the bounds and the adjacency. Allocating them anew for every certificate cost a
// quarter of the time on the finest level of a 1.15M-face problem (page faults).
struct Certificate_workspace
{
  std::vector<Int> lower, upper, x0, supply;
  std::unique_ptr<Warm_push_relabel<Int>> push_relabel;
  std::unique_ptr<Boykov_kolmogorov_flow<Int>> boykov_kolmogorov;
  std::shared_ptr<const Adjacency> adjacency;
};

// One level of the hierarchy of contracted problems (level 0: the problem itself).
struct Level
{
  std::size_t n = 0;
  std::vector<Int_arc> arcs;
  std::vector<std::size_t> parent;      // node -> node of the next coarser level
  std::vector<std::size_t> component;   // node -> its connected component's first node
  std::vector<std::size_t> arc_parent;  // arc -> arc of the next coarser level (npos inside a cluster)
  std::vector<signed char> arc_sign;    // -1 where the coarser arc runs the other way
  std::vector<Int> x;                   // a flow within the subdifferentials at the level's answer
  std::unique_ptr<Certificate_workspace> workspace;

  // the adjacency of the level, built once and kept with the certificates' workspace
  const Adjacency& adjacency()
  {
    if(!workspace) workspace.reset(new Certificate_workspace());
    if(!workspace->adjacency) workspace->adjacency = std::make_shared<const Adjacency>(n, arcs);
    return *workspace->adjacency;
  }
};

// Numbers the connected pieces of the nodes v with inside(v), joined by the arcs between two such
// nodes: every such v with id[v] == npos gets its piece's number, counted from `first` in the order
// of the pieces' first nodes. Returns the next number.
template <class Inside>
std::size_t number_pieces(std::size_t n, const std::vector<Int_arc>& arcs, const Adjacency& adj, Inside inside,
                          std::vector<std::size_t>& id, std::size_t first)
{
  std::vector<std::size_t> queue;
  std::size_t next = first;
  for(std::size_t r = 0; r < n; ++r)
  {
    if(id[r] != npos || !inside(r)) continue;
    id[r] = next;
    queue.assign(1, r);
    for(std::size_t q = 0; q < queue.size(); ++q)
      adj.for_each_neighbour(arcs, queue[q], [&](std::size_t, std::size_t y) {
        if(id[y] == npos && inside(y)) { id[y] = next; queue.push_back(y); }
      });
    ++next;
  }
  return next;
}

// pi[v] -= pi[first node of v's component]: keeps the potentials small across refinements
inline void normalize(const Level& lv, std::vector<Int>& pi)
{
  for(std::size_t v = 0; v < lv.n; ++v)
    if(lv.component[v] != v) pi[v] -= pi[lv.component[v]];
  for(std::size_t v = 0; v < lv.n; ++v)
    if(lv.component[v] == v) pi[v] = 0;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
