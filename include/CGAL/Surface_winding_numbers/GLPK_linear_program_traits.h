// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_GLPK_LINEAR_PROGRAM_TRAITS_H
#define CGAL_SURFACE_WINDING_NUMBERS_GLPK_LINEAR_PROGRAM_TRAITS_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>

#include <glpk.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersTraitsClasses

Index-based linear program `min q^T x  s.t.  l <= A x <= u,  lo <= x <= hi` solved with the simplex
method of GLPK (GNU Linear Programming Kit).

Unlike CGAL's `GLPK_mixed_integer_program_traits`, the status of the solve is read from
`glp_get_status()`, so infeasible and unbounded programs are reported as such, and the matrix is
passed to GLPK in one call as merged triplets. Entries given twice for the same `(i, j)` are summed.
The class is not copyable: pass it with `std::ref()` to the named parameter `lp_solver`.

\cgalModels `SurfaceWindingNumbersLPTraits`
*/
class GLPK_linear_program_traits
{
public:
  GLPK_linear_program_traits() = default;
  GLPK_linear_program_traits(const GLPK_linear_program_traits&) = delete;
  GLPK_linear_program_traits& operator=(const GLPK_linear_program_traits&) = delete;

  /// a name for logs and summaries
  static const char* name() { return "glpk"; }

  /// clears the program and sets its size: `n` variables (free, zero cost) and `m` rows (unbounded)
  void resize(std::size_t n, std::size_t m)
  {
    if(n > std::size_t(INT_MAX - 1) || m > std::size_t(INT_MAX - 1))
      throw std::length_error("GLPK_linear_program_traits: program too large for GLPK");
    q_.assign(n, 0.);
    lo_.assign(n, -infinity());
    hi_.assign(n, infinity());
    l_.assign(m, -infinity());
    u_.assign(m, infinity());
    ti_.clear(); tj_.clear(); ta_.clear();
  }
  /// reserves room for `k` matrix entries
  void reserve_A(std::size_t k) { ti_.reserve(k); tj_.reserve(k); ta_.reserve(k); }
  /// sets the cost of variable `j`
  void set_q(std::size_t j, double c) { q_.at(j) = c; }
  /// sets the bounds of variable `j` (`+-infinity()` for none)
  void set_variable_bounds(std::size_t j, double lo, double hi) { lo_.at(j) = lo; hi_.at(j) = hi; }
  /// adds `a` to the entry `(i, j)` of the constraint matrix
  void set_A(std::size_t i, std::size_t j, double a)
  {
    if(i >= l_.size() || j >= q_.size()) throw std::out_of_range("GLPK_linear_program_traits::set_A: index out of range");
    ti_.push_back(int(i) + 1); tj_.push_back(int(j) + 1); ta_.push_back(a);
  }
  /// sets the lower bound of row `i`
  void set_l(std::size_t i, double lo) { l_.at(i) = lo; }
  /// sets the upper bound of row `i`
  void set_u(std::size_t i, double hi) { u_.at(i) = hi; }
  /// GLPK messages on standard output
  void set_verbose(bool b) { verbose_ = b; }
  /// simplex time limit in seconds (0: none)
  void set_time_limit(double seconds) { time_limit_ = seconds; }
  /// the value that stands for "no bound" (`std::numeric_limits<double>::%infinity()`)
  static double infinity() { return std::numeric_limits<double>::infinity(); }

  /// solves the program; on `LP_status::OPTIMAL` writes the `n` variable values to `x`
  template <class OutputIterator>
  LP_status solve(OutputIterator x)
  {
    const int n = int(q_.size()), m = int(l_.size());
    glp_prob* lp = glp_create_prob();
    glp_set_obj_dir(lp, GLP_MIN);
    if(n > 0) glp_add_cols(lp, n);
    if(m > 0) glp_add_rows(lp, m);
    for(int j = 0; j < n; ++j)
    {
      glp_set_col_bnds(lp, j + 1, bound_type(lo_[j], hi_[j]), finite_or_zero(lo_[j]), finite_or_zero(hi_[j]));
      glp_set_obj_coef(lp, j + 1, q_[j]);
    }
    for(int i = 0; i < m; ++i)
      glp_set_row_bnds(lp, i + 1, bound_type(l_[i], u_[i]), finite_or_zero(l_[i]), finite_or_zero(u_[i]));
    std::vector<int> I, J;
    std::vector<double> A;
    merged_triplets(I, J, A);   // GLPK aborts the process on repeated (i, j)
    glp_load_matrix(lp, int(I.size()) - 1, I.data(), J.data(), A.data());

    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = verbose_ ? GLP_MSG_ON : GLP_MSG_OFF;
    parm.presolve = GLP_ON;
    parm.meth = GLP_DUALP;
    parm.tol_bnd = 1e-9;
    parm.tol_dj = 1e-9;
    if(time_limit_ > 0) parm.tm_lim = int(std::min(1e9, time_limit_ * 1000.));
    const int ret = glp_simplex(lp, &parm);
    LP_status status = LP_status::FAILED;
    if(ret == 0)
    {
      switch(glp_get_status(lp))
      {
        case GLP_OPT: status = LP_status::OPTIMAL; break;
        case GLP_NOFEAS: status = LP_status::INFEASIBLE; break;
        case GLP_UNBND: status = LP_status::UNBOUNDED; break;
        default: break;
      }
    }
    else if(ret == GLP_ENOPFS) status = LP_status::INFEASIBLE;
    else if(ret == GLP_ENODFS) status = LP_status::UNBOUNDED;
    if(status == LP_status::OPTIMAL)
      for(int j = 0; j < n; ++j) *x++ = glp_get_col_prim(lp, j + 1);
    glp_delete_prob(lp);
    return status;
  }

private:
  void merged_triplets(std::vector<int>& I, std::vector<int>& J, std::vector<double>& A) const
  {
    std::vector<std::size_t> order(ti_.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return ti_[a] != ti_[b] ? ti_[a] < ti_[b] : tj_[a] < tj_[b];
    });
    I.assign(1, 0); J.assign(1, 0); A.assign(1, 0.);   // GLPK arrays are 1-based
    for(std::size_t k : order)
    {
      if(I.size() > 1 && I.back() == ti_[k] && J.back() == tj_[k]) A.back() += ta_[k];
      else { I.push_back(ti_[k]); J.push_back(tj_[k]); A.push_back(ta_[k]); }
    }
  }
  static int bound_type(double lo, double hi)
  {
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if(has_lo && has_hi) return lo == hi ? GLP_FX : GLP_DB;
    return has_lo ? GLP_LO : has_hi ? GLP_UP : GLP_FR;
  }
  static double finite_or_zero(double v) { return std::isfinite(v) ? v : 0.; }

  std::vector<double> q_, lo_, hi_, l_, u_;
  std::vector<int> ti_, tj_;
  std::vector<double> ta_;
  bool verbose_ = false;
  double time_limit_ = 0;
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
