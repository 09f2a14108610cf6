// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The residual solvers and sparse linear solvers compiled into the package, by the names the tool
// (--lp-solver, --linear-solver) and the Python module (lp_solver=, linear_solver=) give them, and the
// call of a solve with the ones chosen.

#ifndef CGAL_SWN_TOOL_IO_SOLVER_CHOICE_H
#define CGAL_SWN_TOOL_IO_SOLVER_CHOICE_H

#include <CGAL/Surface_winding_numbers/Surface_winding_numbers_solver.h>
#ifdef CGAL_USE_GLPK
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#endif

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/// the residual solvers compiled in, the default first: `lemon` (multilevel minimum-cost flow with an
/// optimality certificate), `lemon-simplex` (LEMON's network simplex on the whole problem), `glpk` (simplex)
inline std::vector<std::string> lp_solver_names()
{
  std::vector<std::string> names;
#ifdef CGAL_SWN_USE_LEMON
  names.insert(names.end(), {"lemon", "lemon-simplex"});
#endif
#ifdef CGAL_USE_GLPK
  names.push_back("glpk");
#endif
  return names;
}

/// the sparse Cholesky solvers compiled in, the default first: `cholmod` (the package's supernodal
/// factorization on CHOLMOD's analysis), `ldlt` (Eigen's SimplicialLDLT)
inline std::vector<std::string> linear_solver_names()
{
#ifdef CGAL_SWN_USE_CHOLMOD
  return {"cholmod", "ldlt"};
#else
  return {"ldlt"};
#endif
}

/// "a, b, c" (or "none")
inline std::string name_list(const std::vector<std::string>& names)
{
  std::string s;
  for(const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

/// `true` if `name` is among `names`
inline bool is_one_of(const std::string& name, const std::vector<std::string>& names)
{
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// Calls `run(lp)` with the residual solver `name` (one of `lp_solver_names()`) and returns what it returns.
/// \throws std::invalid_argument on another name
template <class Run>
bool with_lp_solver(const std::string& name, Run run)
{
#ifdef CGAL_SWN_USE_LEMON
  if(name == "lemon" || name == "lemon-simplex")
  {
    LEMON_residual_solver::Options options;
    if(name == "lemon-simplex") options.algorithm = LEMON_residual_solver::Options::NETWORK_SIMPLEX;
    LEMON_residual_solver lemon(options);
    return run(lemon);
  }
#endif
#ifdef CGAL_USE_GLPK
  if(name == "glpk")
  {
    GLPK_linear_program_traits glpk;
    return run(glpk);
  }
#endif
  throw std::invalid_argument("unknown residual solver '" + name + "' (available: " + name_list(lp_solver_names()) + ")");
}

/// Calls `run(sparse_solver)` with a default-constructed sparse solver `name` (one of
/// `linear_solver_names()`) and returns what it returns.
/// \throws std::invalid_argument on another name
template <class Run>
auto with_linear_solver(const std::string& name, Run run)
{
#ifdef CGAL_SWN_USE_CHOLMOD
  if(name == "cholmod") return run(Surface_winding_numbers::internal::CHOLMOD_sparse_solver());
#endif
  if(name != "ldlt")
    throw std::invalid_argument("unknown sparse linear solver '" + name + "' (available: " +
                                name_list(linear_solver_names()) + ")");
  return run(Surface_winding_numbers::internal::Eigen_LDLT_sparse_solver());
}

/// Calls `run(lp, sparse_solver)` with the residual solver `lp_solver` and the sparse solver `linear_solver`.
template <class Run>
bool with_solvers(const std::string& lp_solver, const std::string& linear_solver, Run run)
{
  return with_lp_solver(lp_solver, [&](auto& lp) {
    return with_linear_solver(linear_solver, [&](auto sparse_solver) { return run(lp, sparse_solver); });
  });
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_SOLVER_CHOICE_H
