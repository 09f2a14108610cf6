// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// A re-solve that starts from the last answer (the paper's sketching use, Sec. 5.3: one stroke changed,
// the rest of the data alike). Between two problems on the same graph the jumps s change only a
// little away from the changed curve (the harmonic part is global, but the integer cycle sums of s
// change only where a curve moved), so the last optimum's jumps at the kinks of the cost (0 and the
// bounds) are carried over exactly, its flow is carried over as the certificate's start, and the
// finest level alone is certified and repaired (descent steps and bands around the barriers) as the
// multilevel solver does. The answer is an optimum of the new problem (certified by the maximum flow);
// if the certificate is not reached within the bands, the caller solves the problem afresh.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_WARM_START_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_WARM_START_H

#include <CGAL/Surface_winding_numbers/internal/residual_flow/context.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/hierarchy.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/integer_network.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/multilevel.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {
namespace residual_flow {

// The last certified answer, in units of the jumps (not of the integer scaling, which may change).
struct Warm_state
{
  bool valid = false;
  std::vector<std::size_t> face_node;   // the contraction of the last problem
  std::vector<std::size_t> ends;        // its arcs' nodes, L and R in turn
  std::vector<double> kink;             // arc -> its jump if at a kink of its cost (0 or a bound), else NaN
  std::vector<double> shift;            // node -> its shift sigma0 + pi / 2^k
  std::vector<Int> x;                   // the certificate's flow, in units of 2^-m
  int m = 0;
  // the finest level's certificate workspace of the last warm solve (its maximum flow's graph and
  // buffers), for the next warm solve on the same graph: building them anew on every re-solve costs
  // page faults
  std::unique_ptr<Certificate_workspace> workspace;

  void clear() { *this = Warm_state(); }
  // the same graph: same contraction, same arcs in the same order
  bool matches(const Integer_problem& ip) const
  {
    if(!valid || ip.face_node != face_node || ends.size() != 2 * ip.arcs.size()) return false;
    for(std::size_t i = 0; i < ip.arcs.size(); ++i)
      if(ends[2 * i] != ip.arcs[i].L || ends[2 * i + 1] != ip.arcs[i].R) return false;
    return true;
  }
};

inline bool at_kink(const Int_arc& e, Int J) { return J == 0 || (e.has_lo && J == e.lo) || (e.has_up && J == e.up); }

// keeps the answer pi (with the certificate's flow x, whose weights are scaled by 2^m) of ip
inline void keep_answer(Warm_state& w, const Integer_problem& ip, const std::vector<Int>& pi, std::vector<Int>&& x, int m)
{
  w.face_node = ip.face_node;
  w.ends.resize(2 * ip.arcs.size());
  w.kink.resize(ip.arcs.size());
  const double unit = std::ldexp(1., -ip.k);
  for(std::size_t i = 0; i < ip.arcs.size(); ++i)
  {
    const Int_arc& e = ip.arcs[i];
    w.ends[2 * i] = e.L;
    w.ends[2 * i + 1] = e.R;
    const Int J = tension(e, pi);
    w.kink[i] = at_kink(e, J) ? double(J) * unit : std::numeric_limits<double>::quiet_NaN();
  }
  w.shift.resize(ip.nodes);
  for(std::size_t v = 0; v < ip.nodes; ++v) w.shift[v] = ip.sigma0[v] + double(pi[v]) * unit;
  w.x = std::move(x);
  w.m = m;
  w.valid = true;
}

// Potentials of ip from the kept answer: along a spanning forest of the arcs whose last jump was at a
// kink that the arc still has, that jump exactly; each tree of the forest placed by the kept shift
// of its first node.
inline std::vector<Int> warm_potentials(const Warm_state& w, const Integer_problem& ip)
{
  const std::size_t n = ip.nodes;
  const double scale = std::ldexp(1., ip.k);
  std::vector<Int> target(ip.arcs.size(), 0);   // the jump carried over, on the arcs with use[i]
  std::vector<char> use(ip.arcs.size(), 0);
  for(std::size_t i = 0; i < ip.arcs.size(); ++i)
    if(!std::isnan(w.kink[i]))
    {
      target[i] = Int(std::llround(w.kink[i] * scale));
      use[i] = at_kink(ip.arcs[i], target[i]) ? 1 : 0;
    }
  const Adjacency& adj = *ip.adjacency;
  std::vector<Int> pi(n, 0);
  std::vector<char> seen(n, 0);
  std::vector<std::size_t> queue;
  for(std::size_t r = 0; r < n; ++r)
  {
    if(seen[r]) continue;
    seen[r] = 1;
    pi[r] = Int(std::llround((w.shift[r] - ip.sigma0[r]) * scale));
    queue.assign(1, r);
    for(std::size_t q = 0; q < queue.size(); ++q)
      adj.for_each_neighbour(ip.arcs, queue[q], [&](std::size_t i, std::size_t y) {
        if(seen[y] || !use[i]) return;
        seen[y] = 1;
        const Int_arc& e = ip.arcs[i];
        // target = sh + pi[L] - pi[R]
        pi[y] = e.L == y ? target[i] - e.sh + pi[e.R] : e.sh + pi[e.L] - target[i];
        queue.push_back(y);
      });
  }
  return pi;
}

// The finest level alone, from the kept answer: true with pi certified optimal and x its flow (and the
// level's workspace kept in w for the next warm solve); false
// (ctx.error set on errors only) if the certificate was not reached.
inline bool warm_solve(Context& ctx, Integer_problem& ip, Warm_state& w, std::vector<Int>& pi, std::vector<Int>& x)
{
  pi = warm_potentials(w, ip);
  std::vector<Level> levels(1);
  Level& lv = levels[0];
  lv.n = ip.nodes;
  lv.arcs.swap(ip.arcs);
  // the last warm solve's workspace (the same graph: w matches ip), else one with the integer
  // problem's adjacency; the components from the integer problem's (its gauge forest spans them)
  lv.workspace = std::move(w.workspace);
  if(!lv.workspace)
  {
    lv.workspace.reset(new Certificate_workspace());
    lv.workspace->adjacency = ip.adjacency;
  }
  name_components(lv, ip.component, ip.roots.size());
  normalize(lv, pi);
  const int dm = ctx.stats.capacity_exponent - w.m;
  lv.x.resize(w.x.size());
  for(std::size_t i = 0; i < w.x.size(); ++i) lv.x[i] = Int(std::llround(std::ldexp(double(w.x[i]), dm)));
  // the changed curve's imbalances travel around its barriers: augmenting paths move them whole
  struct Paths
  {
    Context& ctx;
    Paths(Context& c) : ctx(c) { ctx.augmenting_paths = true; }
    ~Paths() { ctx.augmenting_paths = false; }
  } paths(ctx);
  const bool certified = fits_certificate_range(ctx, lv.n, lv.arcs, ip.U) &&
                         certify_level(ctx, levels, 0, ip.U, pi, ctx.options.max_refinements);
  lv.arcs.swap(ip.arcs);
  if(!certified) return false;
  x.swap(lv.x);
  w.workspace = std::move(lv.workspace);
  return true;
}

} // namespace residual_flow
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
