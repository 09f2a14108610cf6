// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_H
#define CGAL_SURFACE_WINDING_NUMBERS_LEMON_RESIDUAL_SOLVER_H

#include <CGAL/Surface_winding_numbers/Residual_problem.h>

#include <lemon/cost_scaling.h>
#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersTraitsClasses

Exact solver of the residual problem (paper Eq. 11, `Residual_problem`) as a minimum-cost
circulation, with the network flow algorithms of LEMON (<https://lemon.cs.elte.hu>, Boost Software
License).

Eq. 11 minimizes a sum of convex piecewise-linear functions of the differences `sigma[left] -
sigma[right]` (a minimum-cost tension problem on the dual graph). Its linear programming dual is a
minimum-cost circulation in which every arc of the problem becomes two to four parallel network arcs:
two of capacity `cost[a]` (the slopes of `|J|`) and, for each finite bound, one penalty arc of a
capacity larger than any flow of an optimal basic circulation, so that the penalty is exact. The
optimal node potentials of the circulation are an optimal `sigma`. The solver

- contracts the arcs whose two bounds are equal (the jump is fixed) with a union-find that keeps
  the offsets between the shifts of the merged faces; a cycle of fixed arcs whose jumps do not add
  up fails;
- fixes the gauge of each connected component of the dual graph along a breadth-first spanning
  tree (the jump is 0 on the tree), so that only the arcs that close a nonzero cycle of `s` keep a
  nonzero cost;
- scales costs and jumps by \f$ 2^k \f$ and the weights `cost[a]` by \f$ 2^m \f$ and rounds them to
  64-bit integers (LEMON's algorithms need integer data): \f$ k \f$ is the largest exponent up to
  42 for which no node potential can exceed \f$ 2^{59} \f$, and, for cost scaling, the costs
  multiplied by 16 times the number of nodes (as `lemon::CostScaling` does internally) stay below
  \f$ 2^{60} \f$ (\f$ k = 42 \f$ with network simplex, 39 with cost scaling at 35k faces and
  jumps of order 1). \f$ m \f$ makes the sum of all capacities at most \f$ 2^{58} \f$. The jump
  of every arc is then exact up to \f$ 2^{-k-1} \f$ (\f$ 1.1 \cdot 10^{-13} \f$ at
  \f$ k = 42 \f$), and each weight up to \f$ 2^{-m-1} \f$ in absolute value;
- solves the circulation with LEMON's `NetworkSimplex` (or, on request, `CostScaling`: see
  `Algorithm`), checks that the flow is a circulation within the capacities and, where the
  compiler has 128-bit integers, the exact duality certificate (the penalized objective of the
  potentials equals minus the cost of the flow), and fails if a check fails;
- recovers `sigma` from the potentials (differences taken in integers before the conversion), and
  shifts each component so that its face listed in `gauge_faces` gets 0; faces without any
  constraining arc get 0 (up to the offsets of fixed arcs).

`solve_residual()` returns `false`, and `error()` says why, if the problem is malformed (sizes,
indices, a negative or non-finite cost, bounds with `lower > upper`), if fixed arcs contradict each
other, if the data are too large for the integer scaling, if no algorithm returned a certified
optimum, or if the problem is infeasible. In the last case `sigma` holds the solution of least
penalized violation, and `statistics().max_violation` tells by how much it violates the bounds.

On the demo double torus with loops (35k faces) the residual problem takes 0.5 s with the default
algorithm, against 117 to 250 s with GLPK's dual simplex on the same (shared) machine; the
objectives agree to \f$ 10^{-11} \f$ (see `benchmark/residual_solvers.md` in the source tree). The class is not copyable: pass it with
`std::ref()` to the named parameter `lp_solver`.

\cgalModels `SurfaceWindingNumbersResidualSolver`
*/
class LEMON_residual_solver
{
public:
  /*!
  The minimum-cost flow algorithm of LEMON run on the circulation.

  \warning The cost scaling variants are for experiments only. In LEMON 1.3.1 (Debian's
  `liblemon-dev`) the price refinement heuristic of `lemon::CostScaling`, used by all three
  methods, can index its rank buckets out of bounds (a heap buffer overflow, found with
  AddressSanitizer on random networks of 3 to 8 nodes) and can loop forever (`PUSH` on such random
  networks; `AUGMENT` and `PARTIAL_AUGMENT` on a residual problem of 4 faces, a cycle with one
  curve arc).
  `NETWORK_SIMPLEX` passed the same random tests (40,000 networks, checked against
  `lemon::CycleCanceling` and the duality certificate, clean under AddressSanitizer).
  */
  enum Algorithm
  {
    NETWORK_SIMPLEX,               ///< `lemon::NetworkSimplex`, pivot rule `BLOCK_SEARCH` (the default)
    COST_SCALING_PUSH,             ///< `lemon::CostScaling`, method `PUSH` (see the warning)
    COST_SCALING_AUGMENT,          ///< `lemon::CostScaling`, method `AUGMENT` (see the warning)
    COST_SCALING_PARTIAL_AUGMENT   ///< `lemon::CostScaling`, method `PARTIAL_AUGMENT` (see the warning)
  };

  /// What the last call to `solve_residual()` did.
  struct Statistics
  {
    std::size_t faces = 0;               ///< faces of the problem
    std::size_t arcs = 0;                ///< arcs of the problem
    std::size_t fixed_arcs = 0;          ///< arcs with `lower == upper`, contracted
    std::size_t constant_arcs = 0;       ///< arcs whose two faces were merged by the contraction (constant jump)
    std::size_t nodes = 0;               ///< nodes of the network (faces after contraction)
    std::size_t network_arcs = 0;        ///< arcs of the network
    std::size_t nonzero_cost_arcs = 0;   ///< problem arcs whose scaled jump `s` is nonzero after gauge fixing
    int cost_exponent = 0;               ///< jumps and costs are scaled by 2^cost_exponent
    int capacity_exponent = 0;           ///< weights are scaled by 2^capacity_exponent
    Algorithm algorithm = NETWORK_SIMPLEX;   ///< the algorithm whose result was used
    bool fallback = false;               ///< the first algorithm failed and the other one was used
    bool certified = false;              ///< the exact duality certificate of the scaled problem held
    double objective = 0;                ///< Eq. 11 objective of `sigma`, recomputed with the original data
    double max_violation = 0;            ///< largest violation of the bounds by `sigma`
    double time_build = 0;               ///< seconds: checks, contraction, gauge, scaling, network
    double time_solve = 0;               ///< seconds: LEMON (graph, algorithm) and the certificate
    double time_recover = 0;             ///< seconds: sigma from the potentials, objective and violation
  };

  /// the algorithm used by default: `NETWORK_SIMPLEX`. On the demo double torus with loops and its
  /// subdivisions (35k, 140k, 560k faces) it took 0.5, 15 and 204 s, cost scaling (push) 2.1, 27
  /// and 108 s (see `benchmark/residual_solvers.md`); it is the faster one up to about 200k faces,
  /// and the one without known defects in LEMON 1.3.1 (see `Algorithm`).
  static Algorithm default_algorithm() { return NETWORK_SIMPLEX; }

  /// creates a solver that uses `default_algorithm()`
  LEMON_residual_solver() : algorithm_(default_algorithm()) {}
  /// creates a solver that uses `algorithm`
  explicit LEMON_residual_solver(Algorithm algorithm) : algorithm_(algorithm) {}
  LEMON_residual_solver(const LEMON_residual_solver&) = delete;
  LEMON_residual_solver& operator=(const LEMON_residual_solver&) = delete;

  /// a name for logs and summaries
  static const char* name() { return "lemon"; }

  /// sets the algorithm of the next solves
  void set_algorithm(Algorithm a) { algorithm_ = a; }
  /// the algorithm of the next solves
  Algorithm algorithm() const { return algorithm_; }
  /// if `true`, a failed or uncertified solve is repeated with the other kind of algorithm
  /// (`NETWORK_SIMPLEX` after cost scaling, `COST_SCALING_PUSH` after network simplex). Default:
  /// `false` (a failure of network simplex has not been seen; cost scaling has the defects listed
  /// at `Algorithm`).
  void set_fallback(bool b) { fallback_ = b; }
  /// largest violation of the bounds accepted (default `1e-9`; raised to \f$ 2^{1-k} \f$ when the
  /// scaling exponent `k` is small)
  void set_feasibility_tolerance(double t) { tolerance_ = t; }
  /// messages on standard error
  void set_verbose(bool b) { verbose_ = b; }

  /// why the last solve failed (empty after a success)
  const std::string& error() const { return error_; }
  /// what the last solve did
  const Statistics& statistics() const { return stats_; }

  /*!
  solves `P`: writes one shift per face to `sigma` (resized to `P.number_of_faces`).
  \returns `true` on success; `false` with a reason in `error()` otherwise.
  */
  bool solve_residual(const Residual_problem& P, std::vector<double>& sigma)
  {
    error_.clear();
    stats_ = Statistics();
    try
    {
      return solve_impl(P, sigma);
    }
    catch(const std::exception& e)
    {
      return fail(std::string("LEMON residual solver: ") + e.what());
    }
  }

private:
  typedef long long Int;
  typedef lemon::SmartDigraph Graph;
#ifdef __SIZEOF_INT128__
  __extension__ typedef __int128 Wide;   // exact certificate, large costs inside cost scaling
  static constexpr bool has_wide = true;
#else
  typedef long double Wide;
  static constexpr bool has_wide = false;
#endif

  // a problem arc after contraction: jump J = s + sigma[L] - sigma[R] over the contracted nodes
  struct Work_arc
  {
    std::size_t L, R;
    double s, w, lo, up;
    bool tree;
  };

  // the network handed to LEMON (and kept for the certificate)
  struct Network
  {
    std::vector<std::size_t> tail, head;
    std::vector<Int> cap, cost;
    void add(std::size_t t, std::size_t h, Int c, Int k)
    {
      if(c <= 0) return;
      tail.push_back(t); head.push_back(h); cap.push_back(c); cost.push_back(k);
    }
  };

  bool fail(const std::string& why)
  {
    error_ = why;
    if(verbose_) std::cerr << "[swn] " << why << "\n";
    return false;
  }

  static double seconds(std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  static const char* algorithm_name(Algorithm a)
  {
    switch(a)
    {
      case COST_SCALING_PUSH: return "CostScaling/PUSH";
      case COST_SCALING_AUGMENT: return "CostScaling/AUGMENT";
      case COST_SCALING_PARTIAL_AUGMENT: return "CostScaling/PARTIAL_AUGMENT";
      case NETWORK_SIMPLEX: return "NetworkSimplex/BLOCK_SEARCH";
    }
    return "?";
  }

  // weighted union-find: sigma[f] = sigma[parent[f]] + offset[f]
  struct Union_find
  {
    std::vector<std::size_t> parent, size;
    std::vector<double> offset;
    std::vector<std::size_t> path;
    explicit Union_find(std::size_t n) : parent(n), size(n, 1), offset(n, 0.)
    {
      for(std::size_t i = 0; i < n; ++i) parent[i] = i;
    }
    // root of f; o = sigma[f] - sigma[root]
    std::size_t find(std::size_t f, double& o)
    {
      path.clear();
      while(parent[f] != f) { path.push_back(f); f = parent[f]; }
      // compress from the top: offsets become relative to the root
      for(std::size_t i = path.size(); i-- > 0;)
      {
        const std::size_t x = path[i];
        if(parent[x] != f) offset[x] += offset[parent[x]];
        parent[x] = f;
      }
      o = path.empty() ? 0. : offset[path.front()];
      return f;
    }
    // imposes sigma[a] - sigma[b] = d; returns false and the gap if a and b are already joined
    bool join(std::size_t a, std::size_t b, double d, double& gap)
    {
      double oa, ob;
      const std::size_t ra = find(a, oa), rb = find(b, ob);
      if(ra == rb) { gap = (oa - ob) - d; return false; }
      // sigma[ra] - sigma[rb] = d - oa + ob
      const double x = d - oa + ob;
      if(size[ra] <= size[rb]) { parent[ra] = rb; offset[ra] = x; size[rb] += size[ra]; }
      else { parent[rb] = ra; offset[rb] = -x; size[ra] += size[rb]; }
      return true;
    }
  };

  bool check_input(const Residual_problem& P)
  {
    const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
    if(P.right.size() != na || P.s.size() != na || P.cost.size() != na || P.lower.size() != na || P.upper.size() != na)
      return fail("the residual problem has arrays of different sizes");
    for(std::size_t a = 0; a < na; ++a)
    {
      const std::string at = " at arc " + std::to_string(a);
      if(P.left[a] >= nf || P.right[a] >= nf) return fail("the residual problem has a face index out of range" + at);
      if(!std::isfinite(P.s[a])) return fail("the residual problem has a non-finite jump s" + at);
      if(!(P.cost[a] >= 0) || !std::isfinite(P.cost[a])) return fail("the residual problem has a negative or non-finite cost" + at);
      if(std::isnan(P.lower[a]) || std::isnan(P.upper[a]) || !(P.lower[a] <= P.upper[a]) ||
         P.lower[a] == std::numeric_limits<double>::infinity() || P.upper[a] == -std::numeric_limits<double>::infinity())
        return fail("the residual problem has empty or invalid bounds" + at);
    }
    for(std::size_t f : P.gauge_faces)
      if(f >= nf) return fail("the residual problem has a gauge face out of range");
    return true;
  }

  bool solve_impl(const Residual_problem& P, std::vector<double>& sigma)
  {
    const auto t_build = std::chrono::steady_clock::now();
    const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
    stats_.faces = nf;
    stats_.arcs = na;
    sigma.assign(nf, 0.);
    if(!check_input(P)) return false;
    if(nf == 0) { stats_.certified = true; return true; }

    // 1. contract the fixed arcs: sigma[L] - sigma[R] = lower - s
    Union_find uf(nf);
    double worst_gap = 0;
    for(std::size_t a = 0; a < na; ++a)
    {
      if(!(P.lower[a] == P.upper[a])) continue;
      ++stats_.fixed_arcs;
      double gap = 0;
      if(!uf.join(P.left[a], P.right[a], P.lower[a] - P.s[a], gap)) worst_gap = (std::max)(worst_gap, std::abs(gap));
    }
    if(!(worst_gap <= tolerance_))
      return fail("the arcs with a fixed jump (lower == upper) contradict each other around a cycle by " +
                  std::to_string(worst_gap));
    std::vector<std::size_t> node_of_root(nf, npos), face_node(nf);
    std::vector<double> face_offset(nf);
    std::size_t nn = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = uf.find(f, face_offset[f]);
      if(node_of_root[r] == npos) node_of_root[r] = nn++;
      face_node[f] = node_of_root[r];
    }
    stats_.nodes = nn;
    if(nn > std::size_t((std::numeric_limits<int>::max)() / 2) || na > std::size_t((std::numeric_limits<int>::max)() / 4))
      return fail("the residual problem is too large for LEMON's graphs (int indices)");

    // 2. the remaining arcs over the contracted nodes
    std::vector<Work_arc> arcs;
    arcs.reserve(na);
    double constant_violation = 0;
    for(std::size_t a = 0; a < na; ++a)
    {
      if(P.lower[a] == P.upper[a]) continue;
      const std::size_t L = face_node[P.left[a]], R = face_node[P.right[a]];
      const double s = P.s[a] + face_offset[P.left[a]] - face_offset[P.right[a]];
      if(L == R)
      {
        ++stats_.constant_arcs;   // constant jump s: only its bounds matter
        constant_violation = (std::max)(constant_violation, (std::max)(P.lower[a] - s, s - P.upper[a]));
        continue;
      }
      if(P.cost[a] == 0 && !P.is_bounded(a)) continue;   // no effect on anything
      arcs.push_back(Work_arc{L, R, s, P.cost[a], P.lower[a], P.upper[a], false});
    }
    if(!(constant_violation <= tolerance_))
      return fail("the residual problem is infeasible: an arc whose faces are joined by fixed arcs violates its bounds by " +
                  std::to_string(constant_violation));

    // 3. gauge: breadth-first forest, jump 0 on the tree arcs; components rooted at gauge faces first
    std::vector<std::size_t> first(nn + 1, 0), adj(2 * arcs.size());
    for(const Work_arc& e : arcs) { ++first[e.L + 1]; ++first[e.R + 1]; }
    for(std::size_t v = 0; v < nn; ++v) first[v + 1] += first[v];
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(std::size_t i = 0; i < arcs.size(); ++i) { adj[fill[arcs[i].L]++] = i; adj[fill[arcs[i].R]++] = i; }
    }
    std::vector<double> sigma0(nn, 0.);
    std::vector<std::size_t> component(nn, npos), roots, queue;
    queue.reserve(nn);
    auto grow = [&](std::size_t root) {
      if(component[root] != npos) return;
      const std::size_t c = roots.size();
      roots.push_back(root);
      component[root] = c;
      queue.clear();
      queue.push_back(root);
      for(std::size_t q = 0; q < queue.size(); ++q)
      {
        const std::size_t x = queue[q];
        for(std::size_t k = first[x]; k < first[x + 1]; ++k)
        {
          Work_arc& e = arcs[adj[k]];
          const std::size_t y = e.L == x ? e.R : e.L;
          if(component[y] != npos) continue;
          component[y] = c;
          // J = s + sigma0[L] - sigma0[R] = 0
          sigma0[y] = e.L == x ? sigma0[x] + e.s : sigma0[x] - e.s;
          e.tree = true;
          queue.push_back(y);
        }
      }
    };
    for(std::size_t f : P.gauge_faces) grow(face_node[f]);
    for(std::size_t v = 0; v < nn; ++v) grow(v);

    // 4. integer scaling
    std::vector<double> st(arcs.size());
    double B = 1, wsum = 0;
    for(std::size_t i = 0; i < arcs.size(); ++i)
    {
      const Work_arc& e = arcs[i];
      st[i] = e.tree ? 0. : e.s + sigma0[e.L] - sigma0[e.R];
      double bound = 0;
      if(std::isfinite(e.lo)) bound = (std::max)(bound, std::abs(e.lo));
      if(std::isfinite(e.up)) bound = (std::max)(bound, std::abs(e.up));
      B = (std::max)(B, std::abs(st[i]) + bound);
      wsum += e.w;
    }
    // largest cost exponents: node potentials stay below 2^60 (network simplex); cost scaling also
    // multiplies the costs by (nodes + 1) * 16 internally, kept below 2^60 (beyond 2^62 its AUGMENT
    // method was seen to loop)
    const double lognB = std::log2(double(nn + 1) * B);
    const int k_simplex = (std::min)(max_cost_exponent, int(std::floor(59. - lognB)));
    const int k_scaling = (std::min)(k_simplex, int(std::floor(56. - lognB)));
    if(k_scaling < 12)
      return fail("the residual problem's jumps are too large for the 64-bit integer scaling (largest |s| + |bound| " +
                  std::to_string(B) + " on " + std::to_string(nn) + " nodes)");
    const int m = wsum > 0 ? (std::max)(-1000, (std::min)(1000, int(std::floor(57. - std::log2(wsum))))) : 0;
    stats_.capacity_exponent = m;

    auto to_int = [](double x, int e) { return Int(std::llround(std::ldexp(x, e))); };
    std::vector<Int> w_hat(arcs.size());
    Int finite_caps = 0;
    for(std::size_t i = 0; i < arcs.size(); ++i)
    {
      w_hat[i] = to_int(arcs[i].w, m);
      finite_caps += 2 * w_hat[i];
    }
    const Int U = finite_caps + 1;   // exceeds every flow of an optimal basic circulation: exact penalty

    // 5. the network for the cost exponent k: J^ = s^ + pi[L] - pi[R]; reduced cost c + pi[tail] - pi[head]
    //    R->L cost x - s^ has reduced cost x - J^ (active when J^ > x), L->R cost s^ - x has J^ - x.
    auto build = [&](int k, Network& net) {
      net = Network();
      net.tail.reserve(3 * arcs.size()); net.head.reserve(3 * arcs.size());
      net.cap.reserve(3 * arcs.size()); net.cost.reserve(3 * arcs.size());
      stats_.nonzero_cost_arcs = 0;
      for(std::size_t i = 0; i < arcs.size(); ++i)
      {
        const Work_arc& e = arcs[i];
        const Int sh = to_int(st[i], k);
        if(sh != 0) ++stats_.nonzero_cost_arcs;
        const bool has_up = std::isfinite(e.up), has_lo = std::isfinite(e.lo);
        const Int up = has_up ? to_int(e.up, k) : 0, lo = has_lo ? to_int(e.lo, k) : 0;
        const bool merge_up = has_up && up == 0, merge_lo = has_lo && lo == 0;
        net.add(e.R, e.L, w_hat[i] + (merge_up ? U : 0), -sh);   // w (J)_+
        net.add(e.L, e.R, w_hat[i] + (merge_lo ? U : 0), sh);    // w (-J)_+
        if(has_up && !merge_up) net.add(e.R, e.L, U, up - sh);   // U (J - up)_+
        if(has_lo && !merge_lo) net.add(e.L, e.R, U, sh - lo);   // U (lo - J)_+
      }
      stats_.network_arcs = net.cap.size();
      stats_.cost_exponent = k;
    };
    Algorithm a = algorithm_;
    if(!has_wide_large_cost() && a != NETWORK_SIMPLEX) a = NETWORK_SIMPLEX;
    int k = a == NETWORK_SIMPLEX ? k_simplex : k_scaling;
    Network net;
    build(k, net);
    stats_.time_build = seconds(t_build);

    // 6. solve, certify, fall back
    const auto t_solve = std::chrono::steady_clock::now();
    std::vector<Int> pi(nn, 0), flow;
    if(!net.cap.empty())
    {
      std::string why;
      bool ok = run(a, nn, net, pi, flow, why) && certify(net, pi, flow, why);
      if(!ok && fallback_)
      {
        const Algorithm b = a == NETWORK_SIMPLEX && has_wide_large_cost() ? COST_SCALING_PUSH : NETWORK_SIMPLEX;
        if(b != a)
        {
          if(verbose_) std::cerr << "[swn] LEMON " << algorithm_name(a) << ": " << why << "; trying " << algorithm_name(b) << "\n";
          const int kb = b == NETWORK_SIMPLEX ? k_simplex : k_scaling;
          if(kb != k) { k = kb; build(k, net); }
          std::string why2;
          ok = run(b, nn, net, pi, flow, why2) && certify(net, pi, flow, why2);
          stats_.fallback = true;
          a = b;
          if(!ok) why += "; " + std::string(algorithm_name(b)) + ": " + why2;
        }
      }
      stats_.algorithm = a;
      if(!ok) return fail("LEMON residual solver: " + why);
    }
    else
      stats_.certified = true;
    stats_.time_solve = seconds(t_solve);
    const double tolerance = (std::max)(tolerance_, std::ldexp(1., 1 - k));

    // 7. sigma = sigma0 + (pi - pi[root]) / 2^k on the nodes, plus the offsets of the contraction
    const auto t_recover = std::chrono::steady_clock::now();
    std::vector<double> node_sigma(nn);
    for(std::size_t v = 0; v < nn; ++v)
      node_sigma[v] = sigma0[v] + std::ldexp(double(pi[v] - pi[roots[component[v]]]), -k);
    for(std::size_t f = 0; f < nf; ++f) sigma[f] = node_sigma[face_node[f]] + face_offset[f];
    // gauge faces get 0 (the first gauge face of each component)
    std::vector<double> shift(roots.size(), 0.);
    std::vector<char> shifted(roots.size(), 0);
    for(std::size_t f : P.gauge_faces)
    {
      const std::size_t c = component[face_node[f]];
      if(shifted[c]) continue;
      shifted[c] = 1;
      shift[c] = sigma[f];
    }
    for(std::size_t f = 0; f < nf; ++f) sigma[f] -= shift[component[face_node[f]]];
    stats_.objective = P.objective(sigma);
    stats_.max_violation = P.max_violation(sigma);
    stats_.time_recover = seconds(t_recover);
    if(verbose_)
      std::cerr << "[swn] LEMON " << algorithm_name(stats_.algorithm) << (stats_.fallback ? " (fallback)" : "") << ": "
                << stats_.nodes << " nodes, " << stats_.network_arcs << " arcs (" << stats_.fixed_arcs
                << " fixed arcs contracted, " << stats_.nonzero_cost_arcs << " nonzero costs after gauge), scale 2^"
                << k << " / 2^" << m << ", objective " << stats_.objective << ", violation " << stats_.max_violation
                << (stats_.certified ? ", certified" : "") << "; build " << stats_.time_build << " s, solve "
                << stats_.time_solve << " s\n";
    if(!(stats_.max_violation <= tolerance))
      return fail("the residual problem is infeasible: the least-violation solution violates the bounds by " +
                  std::to_string(stats_.max_violation));
    return true;
  }

  static bool has_wide_large_cost()
  {
    return has_wide && std::numeric_limits<Wide>::is_specialized && std::numeric_limits<Wide>::is_integer &&
           std::numeric_limits<Wide>::max() > Wide(std::numeric_limits<Int>::max());
  }

  template <class Solver>
  static void read_solution(const Graph& g, const Solver& solver, std::size_t nn, std::size_t narcs,
                            std::vector<Int>& pi, std::vector<Int>& flow)
  {
    pi.assign(nn, 0);
    flow.assign(narcs, 0);
    for(Graph::NodeIt v(g); v != lemon::INVALID; ++v) pi[std::size_t(g.id(v))] = solver.potential(v);
    for(Graph::ArcIt a(g); a != lemon::INVALID; ++a) flow[std::size_t(g.id(a))] = solver.flow(a);
  }

  bool run(Algorithm algorithm, std::size_t nn, const Network& net, std::vector<Int>& pi, std::vector<Int>& flow,
           std::string& why) const
  {
    Graph g;
    g.reserveNode(int(nn));
    g.reserveArc(int(net.cap.size()));
    for(std::size_t v = 0; v < nn; ++v) g.addNode();
    for(std::size_t i = 0; i < net.cap.size(); ++i) g.addArc(g.nodeFromId(int(net.tail[i])), g.nodeFromId(int(net.head[i])));
    Graph::ArcMap<Int> cap(g), cost(g);
    for(Graph::ArcIt a(g); a != lemon::INVALID; ++a)
    {
      cap[a] = net.cap[std::size_t(g.id(a))];
      cost[a] = net.cost[std::size_t(g.id(a))];
    }
    if(algorithm == NETWORK_SIMPLEX)
    {
      lemon::NetworkSimplex<Graph, Int, Int> ns(g);
      ns.upperMap(cap).costMap(cost);
      const auto status = ns.run(lemon::NetworkSimplex<Graph, Int, Int>::BLOCK_SEARCH);
      if(status != lemon::NetworkSimplex<Graph, Int, Int>::OPTIMAL)
      {
        why = std::string(algorithm_name(algorithm)) + " did not find an optimum (status " + std::to_string(int(status)) + ")";
        return false;
      }
      read_solution(g, ns, nn, net.cap.size(), pi, flow);
      return true;
    }
    return run_cost_scaling<Wide>(g, cap, cost, algorithm, nn, net.cap.size(), pi, flow, why);
  }

  template <class Large>
  static bool run_cost_scaling(const Graph& g, const Graph::ArcMap<Int>& cap, const Graph::ArcMap<Int>& cost,
                               Algorithm algorithm, std::size_t nn, std::size_t narcs, std::vector<Int>& pi,
                               std::vector<Int>& flow, std::string& why)
  {
    if constexpr(std::numeric_limits<Large>::is_integer)
    {
      typedef typename lemon::CostScaling<Graph, Int, Int>::template SetLargeCost<Large>::Create CS;
      CS cs(g);
      cs.upperMap(cap).costMap(cost);
      const typename CS::Method method = algorithm == COST_SCALING_PUSH      ? CS::PUSH
                                         : algorithm == COST_SCALING_AUGMENT ? CS::AUGMENT
                                                                             : CS::PARTIAL_AUGMENT;
      const typename CS::ProblemType status = cs.run(method, 16);
      if(status != CS::OPTIMAL)
      {
        why = std::string(algorithm_name(algorithm)) + " did not find an optimum (status " + std::to_string(int(status)) + ")";
        return false;
      }
      read_solution(g, cs, nn, narcs, pi, flow);
      return true;
    }
    else
    {
      (void)g; (void)cap; (void)cost; (void)algorithm; (void)nn; (void)narcs; (void)pi; (void)flow;
      why = "cost scaling needs a 128-bit integer type";
      return false;
    }
  }

  // exact duality certificate of the scaled circulation: the flow is a feasible circulation and
  // sum cap * max(0, -reduced cost) (the penalized tension objective of pi) == -sum cost * flow
  bool certify(const Network& net, const std::vector<Int>& pi, const std::vector<Int>& flow, std::string& why)
  {
    stats_.certified = false;
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
    stats_.certified = has_wide;
    return true;
  }

  static constexpr std::size_t npos = std::size_t(-1);
  // Beyond 2^42 the scaled jumps start to carry the rounding noise of the doubles (the gauge-fixed
  // jumps are sums of differences of values of order 1..100, whose ulp is 2^-52..2^-46): on the
  // demo torus 155 arcs keep a nonzero cost at 2^42, 256 at 2^44, 463 at 2^46. That noise only
  // makes network simplex slower.
  static constexpr int max_cost_exponent = 42;

  Algorithm algorithm_;
  bool fallback_ = false;
  bool verbose_ = false;
  double tolerance_ = 1e-9;
  std::string error_;
  Statistics stats_;
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
