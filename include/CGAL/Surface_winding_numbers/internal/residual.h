// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_H

#include <CGAL/Surface_winding_numbers/internal/derivatives.h>
#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/Residual_problem.h>
#include <CGAL/Surface_winding_numbers/Solve_report.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Local integration of gamma in every face (paper Sec. 3.4): v0 = 0 at the face's first corner,
// then gamma summed along the face's sides.
inline void integrate_in_face(const Mesh_tables& m, const std::vector<double>& gamma, std::size_t f, std::vector<double>& v)
{
  v[3 * f] = 0.;
  v[3 * f + 1] = m.fs[3 * f] * gamma[m.fe[3 * f]];
  v[3 * f + 2] = v[3 * f + 1] + m.fs[3 * f + 1] * gamma[m.fe[3 * f + 1]];
}

inline std::vector<double> local_integration(const Mesh_tables& m, const std::vector<double>& gamma)
{
  std::vector<double> v(3 * m.nf);
  for(std::size_t f = 0; f < m.nf; ++f) integrate_in_face(m, gamma, f, v);
  return v;
}

// The constraints "no jump across an edge at a nonmanifold vertex or inside a polygon" (Sec. 3.4,
// sigma_L - sigma_R = s_e) fix each such arc's shift difference. Where these arcs close a cycle (the
// fan around a nonmanifold vertex, two flaps meeting at a spine) the sampled jumps s_e add up to zero
// only up to the discretization (no curve crosses them, so there is no integer part): the constraint
// is kept exactly on a spanning forest of these arcs, and on the arcs that close a cycle the jump is
// fixed to the forest's small mismatch instead of 0, which keeps the problem feasible.
inline void make_forbidden_jumps_consistent(const Mesh_tables& m, Residual_problem& p)
{
  const std::size_t na = m.arcs.size(), nf = p.number_of_faces;
  std::vector<std::vector<std::size_t> > at(nf);
  bool any = false;
  for(std::size_t a = 0; a < na; ++a)
    if(m.jump_forbidden(m.arcs[a].edge))
    {
      at[p.left[a]].push_back(a);
      at[p.right[a]].push_back(a);
      any = true;
    }
  if(!any) return;
  // offset[f]: sigma_f relative to its tree's root, from sigma_L - sigma_R = -s along tree arcs
  const double unset = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> offset(nf, unset);
  std::vector<char> in_tree(na, 0);
  std::vector<std::size_t> queue;
  for(std::size_t root = 0; root < nf; ++root)
  {
    if(at[root].empty() || !std::isnan(offset[root])) continue;
    offset[root] = 0.;
    queue.assign(1, root);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(std::size_t a : at[queue[q]])
      {
        const std::size_t x = queue[q], y = p.left[a] == x ? p.right[a] : p.left[a];
        if(!std::isnan(offset[y])) continue;
        offset[y] = p.left[a] == x ? offset[x] + p.s[a] : offset[x] - p.s[a];
        in_tree[a] = 1;
        queue.push_back(y);
      }
  }
  for(std::size_t a = 0; a < na; ++a)
    if(m.jump_forbidden(m.arcs[a].edge) && !in_tree[a])
      p.lower[a] = p.upper[a] = p.s[a] + offset[p.left[a]] - offset[p.right[a]];   // J on this arc
}

// Data of the residual problem (paper Eq. 11) over the interior edges (arcs): s_e is the jump of the
// locally integrated v0 across the arc, averaged over the arc's two endpoints. The paper's objective
// is multiplied by eps (same argmin): cost eps * l on curve edges, l elsewhere, with lengths in units
// of the mean arc length (scale invariance of the solvers' tolerances). Bounds 0 <= J / Gamma <= 1 on
// curve edges.
inline Residual_problem residual_problem(const Mesh_tables& m, const std::vector<double>& v0,
                                         const std::vector<double>& chain, double epsilon)
{
  const std::size_t na = m.arcs.size();
  const double inf = std::numeric_limits<double>::infinity();
  const double mean_length = mean_interior_edge_length(m);
  Residual_problem p;
  p.number_of_faces = m.nf;
  p.left.resize(na); p.right.resize(na); p.s.resize(na); p.cost.resize(na); p.lower.resize(na); p.upper.resize(na);
  for(std::size_t a = 0; a < na; ++a)
  {
    const Arc& arc = m.arcs[a];
    p.left[a] = arc.left_side / 3;
    p.right[a] = arc.right_side / 3;
    p.s[a] = 0.5 * (corner_jump_at(m, v0, a, 0) + corner_jump_at(m, v0, a, 1));
    const double len = m.edge_length(arc.edge) / mean_length;
    const double G = chain[arc.edge];
    if(m.jump_forbidden(arc.edge))   // a diagonal inside a polygon, an edge at a nonmanifold vertex: no jump
    {
      p.cost[a] = len;
      p.lower[a] = p.upper[a] = 0.;
    }
    else if(std::abs(G) > chain_tolerance)
    {
      p.cost[a] = epsilon * len;
      p.lower[a] = (std::min)(0., G);
      p.upper[a] = (std::max)(0., G);
    }
    else
    {
      p.cost[a] = len;
      p.lower[a] = -inf;
      p.upper[a] = inf;
    }
  }
  p.gauge_faces = m.component_first_face;
  make_forbidden_jumps_consistent(m, p);
  return p;
}

// Eq. 11 as a linear program for a model of SurfaceWindingNumbersLPTraits: one shift per face; on a
// bounded arc the sign of J is known, so |J| is linear there; elsewhere |J| = p + n with p, n >= 0.
// Gauge faces are fixed to 0.
template <class LP>
std::vector<double> solve_residual_with_lp(const Residual_problem& P, LP& lp, std::size_t& n_vars, std::size_t& n_rows)
{
  const std::size_t na = P.number_of_arcs(), nf = P.number_of_faces;
  std::vector<std::size_t> slack(na, npos);
  std::size_t n = nf;
  for(std::size_t a = 0; a < na; ++a)
    if(!P.is_bounded(a)) { slack[a] = n; n += 2; }
  n_vars = n;
  n_rows = na;
  lp.resize(n, na);
  lp.reserve_A(4 * na);
  for(std::size_t f : P.gauge_faces) lp.set_variable_bounds(f, 0., 0.);
  std::vector<double> q(nf, 0.);
  for(std::size_t a = 0; a < na; ++a)
  {
    const std::size_t L = P.left[a], R = P.right[a];
    lp.set_A(a, L, 1.);
    lp.set_A(a, R, -1.);
    if(slack[a] != npos)
    {
      const std::size_t p = slack[a], nn = slack[a] + 1;
      lp.set_A(a, p, -1.);
      lp.set_A(a, nn, 1.);
      lp.set_variable_bounds(p, 0., LP::infinity());
      lp.set_variable_bounds(nn, 0., LP::infinity());
      lp.set_q(p, P.cost[a]);
      lp.set_q(nn, P.cost[a]);
      lp.set_l(a, -P.s[a]);
      lp.set_u(a, -P.s[a]);
    }
    else
    {
      lp.set_l(a, P.lower[a] - P.s[a]);
      lp.set_u(a, P.upper[a] - P.s[a]);
      // the jump has the sign of the nonzero bound: |J| = sign * J
      const double c = P.upper[a] > 0 ? P.cost[a] : -P.cost[a];
      q[L] += c;
      q[R] -= c;
    }
  }
  for(std::size_t f = 0; f < nf; ++f)
    if(q[f] != 0) lp.set_q(f, q[f]);

  std::vector<double> x;
  x.reserve(n);
  const LP_status status = lp.solve(std::back_inserter(x));
  switch(status)
  {
    case LP_status::OPTIMAL: break;
    case LP_status::INFEASIBLE: throw Solver_failure("the residual linear program (Eq. 11) is infeasible");
    case LP_status::UNBOUNDED: throw Solver_failure("the residual linear program (Eq. 11) is unbounded");
    default: throw Solver_failure("the residual linear program (Eq. 11) could not be solved");
  }
  if(x.size() != n) throw Solver_failure("the LP solver returned a solution of the wrong size");
  return std::vector<double>(x.begin(), x.begin() + std::ptrdiff_t(nf));
}

// Detects models of SurfaceWindingNumbersResidualSolver (a member solve_residual(problem, sigma)).
template <class T, class = void>
struct is_residual_solver : std::false_type {};
template <class T>
struct is_residual_solver<T, std::void_t<decltype(std::declval<T&>().solve_residual(
                                std::declval<const Residual_problem&>(), std::declval<std::vector<double>&>()))>>
  : std::true_type {};

// Detects residual solvers that take the package's concurrency setting (a member
// solve_residual(problem, sigma, bool concurrent)).
template <class T, class = void>
struct takes_concurrency : std::false_type {};
template <class T>
struct takes_concurrency<T, std::void_t<decltype(std::declval<T&>().solve_residual(
                              std::declval<const Residual_problem&>(), std::declval<std::vector<double>&>(), true))>>
  : std::true_type {};

// Detects solvers that explain their failures (a member error() convertible to std::string).
template <class T, class = void>
struct has_error_message : std::false_type {};
template <class T>
struct has_error_message<T, std::void_t<decltype(std::string(std::declval<const T&>().error()))>> : std::true_type {};

// The residual function (paper Sec. 3.4, Eq. 11): solves the residual problem with the given solver
// (a residual solver, or LP traits), checks the optimum against the constraints, and returns sigma.
// `concurrent`: whether the solver may start threads (if it can be told).
template <class Solver>
std::vector<double> residual_function(const Residual_problem& P, Solver& solver, double& objective,
                                      std::size_t& n_vars, std::size_t& n_rows, bool concurrent = true)
{
  std::vector<double> sigma;
  if constexpr(is_residual_solver<Solver>::value)
  {
    n_vars = P.number_of_faces;
    n_rows = P.number_of_arcs();
    bool solved = false;
    if constexpr(takes_concurrency<Solver>::value) solved = solver.solve_residual(P, sigma, concurrent);
    else
    {
      (void)concurrent;
      solved = solver.solve_residual(P, sigma);
    }
    if(!solved)
    {
      std::string why;
      if constexpr(has_error_message<Solver>::value) why = std::string(": ") + solver.error();
      throw Solver_failure("the residual solver failed" + why);
    }
  }
  else
    sigma = solve_residual_with_lp(P, solver, n_vars, n_rows);
  if(sigma.size() != P.number_of_faces) throw Solver_failure("the residual solver returned a solution of the wrong size");
  const double violation = P.max_violation(sigma);
  if(!(violation <= 1e-6))
    throw Solver_failure("the residual solution violates 0 <= J/Gamma <= 1 by " + std::to_string(violation));
  objective = P.objective(sigma);
  return sigma;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
