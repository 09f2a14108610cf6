// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_H

#include <CGAL/Surface_winding_numbers/internal/derivatives.h>
#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Local integration of gamma in every face (paper Sec. 3.4): v0 = 0 at the face's first corner,
// then gamma summed along the face's sides.
inline std::vector<double> local_integration(const Mesh_tables& m, const std::vector<double>& gamma)
{
  std::vector<double> v(3 * m.nf);
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    v[3 * f] = 0.;
    v[3 * f + 1] = m.fs[3 * f] * gamma[m.fe[3 * f]];
    v[3 * f + 2] = v[3 * f + 1] + m.fs[3 * f + 1] * gamma[m.fe[3 * f + 1]];
  }
  return v;
}

// The residual linear program (paper Eq. 11), solved for one shift sigma per face:
//   min  sum_{e in Gamma} eps l_e |J_e| + sum_{e not in Gamma} l_e |J_e|,   J_e = s_e + sigma_L - sigma_R
//   s.t. 0 <= J_e / Gamma_e <= 1 on curve edges,
// over interior edges (arcs); s_e is the jump of the locally integrated v0. The objective is the
// paper's multiplied by eps (same argmin). On a curve edge the sign of J_e is known, so |J_e| is
// linear there; elsewhere |J_e| = p_e + n_e with p_e, n_e >= 0. Lengths are in units of the mean
// arc length (scale invariance of the LP's tolerances). The first face of each component has
// sigma = 0 (the LP's constant null space). Returns sigma; writes the objective and LP size.
template <class LP>
std::vector<double> residual_function(const Mesh_tables& m, const std::vector<double>& s,
                                      const std::vector<double>& chain, double epsilon, LP& lp,
                                      double& objective, std::size_t& n_vars, std::size_t& n_rows)
{
  const std::size_t na = m.arcs.size();
  double mean_length = 0;
  for(const Arc& a : m.arcs) mean_length += m.edge_length(a.edge);
  mean_length = na > 0 ? mean_length / double(na) : 1.;
  if(!(mean_length > 0)) mean_length = 1.;

  std::vector<std::size_t> slack(na, npos);
  std::size_t n = m.nf;
  for(std::size_t a = 0; a < na; ++a)
    if(std::abs(chain[m.arcs[a].edge]) <= chain_tolerance) { slack[a] = n; n += 2; }
  n_vars = n;
  n_rows = na;

  lp.resize(n, na);
  lp.reserve_A(4 * na);
  for(std::size_t c = 0; c < m.n_components; ++c)
    lp.set_variable_bounds(m.component_first_face[c], 0., 0.);
  std::vector<double> q(m.nf, 0.);
  for(std::size_t a = 0; a < na; ++a)
  {
    const Arc& arc = m.arcs[a];
    const std::size_t L = arc.left_side / 3, R = arc.right_side / 3;
    const double len = m.edge_length(arc.edge) / mean_length;
    const double G = chain[arc.edge];
    // row a: sigma_L - sigma_R (+ n - p)
    lp.set_A(a, L, 1.);
    lp.set_A(a, R, -1.);
    if(slack[a] != npos)
    {
      const std::size_t p = slack[a], nn = slack[a] + 1;
      lp.set_A(a, p, -1.);
      lp.set_A(a, nn, 1.);
      lp.set_variable_bounds(p, 0., LP::infinity());
      lp.set_variable_bounds(nn, 0., LP::infinity());
      lp.set_q(p, len);
      lp.set_q(nn, len);
      lp.set_l(a, -s[a]);
      lp.set_u(a, -s[a]);
    }
    else
    {
      // 0 <= J / G <= 1 and cost eps * len * |J| = eps * len * sign(G) * J
      const double lo = G > 0 ? -s[a] : G - s[a];
      const double hi = G > 0 ? G - s[a] : -s[a];
      lp.set_l(a, lo);
      lp.set_u(a, hi);
      const double c = epsilon * len * (G > 0 ? 1. : -1.);
      q[L] += c;
      q[R] -= c;
    }
  }
  for(std::size_t f = 0; f < m.nf; ++f)
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
  std::vector<double> sigma(x.begin(), x.begin() + std::ptrdiff_t(m.nf));

  // Check the optimum against the constraints before using it, and evaluate the objective.
  objective = 0;
  for(std::size_t a = 0; a < na; ++a)
  {
    const Arc& arc = m.arcs[a];
    const double J = s[a] + sigma[arc.left_side / 3] - sigma[arc.right_side / 3];
    const double G = chain[arc.edge];
    const double len = m.edge_length(arc.edge) / mean_length;
    if(!std::isfinite(J)) throw Solver_failure("the LP solver returned non-finite values");
    if(slack[a] == npos)
    {
      const double r = J / G;
      if(r < -1e-6 || r > 1 + 1e-6)
        throw Solver_failure("the LP solution violates 0 <= J/Gamma <= 1 on edge " + std::to_string(arc.edge) +
                             " (J/Gamma = " + std::to_string(r) + ")");
      objective += epsilon * len * std::abs(J);
    }
    else
      objective += len * std::abs(J);
  }
  return sigma;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
