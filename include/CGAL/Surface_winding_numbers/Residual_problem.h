// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_RESIDUAL_PROBLEM_H
#define CGAL_SURFACE_WINDING_NUMBERS_RESIDUAL_PROBLEM_H

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersRef

The residual problem of the paper (Eq. 11) in index form: find one shift `sigma[f]` per face that
minimizes
\f[ \sum_a \mathrm{cost}_a \, | s_a + \sigma_{L_a} - \sigma_{R_a} | \f]
subject to `lower[a] <= s[a] + sigma[left[a]] - sigma[right[a]] <= upper[a]` for every arc `a` (an
interior edge, seen as a pair of faces: `left[a]` lies to its left). On curve edges the bounds are
`[0, Gamma]` (or `[Gamma, 0]`) and the cost is `epsilon` times the length; elsewhere the bounds are
infinite and the cost is the length (lengths in units of the mean length of the interior edges).
`gauge_faces` lists one face per connected component whose shift may be fixed to 0 (the objective
and the constraints only see differences of shifts).

A model of the concept `SurfaceWindingNumbersResidualSolver` solves it directly; a model of
`SurfaceWindingNumbersLPTraits` is given the linear program built from it.
*/
struct Residual_problem
{
  /// number of faces, i.e. of shifts `sigma` to compute
  std::size_t number_of_faces = 0;
  /// face to the left of each arc
  std::vector<std::size_t> left, right;   ///< faces of each arc
  std::vector<double> s;                   ///< jump of the locally integrated residual across each arc
  std::vector<double> cost;                ///< positive weight of each arc
  /// lower bound on the jump across each arc (-infinity when free)
  std::vector<double> lower, upper;        ///< bounds on the jump (+-infinity when free)
  std::vector<std::size_t> gauge_faces;    ///< one face per connected component

  /// number of arcs (interior edges)
  std::size_t number_of_arcs() const { return left.size(); }
  /// `true` if the jump across arc `a` has a finite bound (the arc is on the curve)
  bool is_bounded(std::size_t a) const { return std::isfinite(lower[a]) || std::isfinite(upper[a]); }

  /// jump of `s + sigma` across arc `a`
  double jump(const std::vector<double>& sigma, std::size_t a) const { return s[a] + sigma[left[a]] - sigma[right[a]]; }

  /// objective value of `sigma`
  double objective(const std::vector<double>& sigma) const
  {
    double o = 0;
    for(std::size_t a = 0; a < number_of_arcs(); ++a) o += cost[a] * std::abs(jump(sigma, a));
    return o;
  }

  /// largest violation of the bounds by `sigma` (0 if feasible)
  double max_violation(const std::vector<double>& sigma) const
  {
    double v = 0;
    for(std::size_t a = 0; a < number_of_arcs(); ++a)
    {
      const double J = jump(sigma, a);
      if(!std::isfinite(J)) return std::numeric_limits<double>::infinity();
      if(J < lower[a]) v = (std::max)(v, lower[a] - J);
      if(J > upper[a]) v = (std::max)(v, J - upper[a]);
    }
    return v;
  }
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
