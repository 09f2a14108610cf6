/*!
\ingroup PkgSurfaceWindingNumbersConcepts
\cgalConcept

The concept `SurfaceWindingNumbersLPTraits` describes the linear program solver used to compute
the residual function of the surface winding numbers (Eq. 11 of the paper, see
\ref SWNResidualLP "the layout of the linear program" in the user manual).

A model holds one linear program with `n` real variables \f$ x \f$ and `m` rows,
\f[
  \min_{x} \; q^T x \quad \text{subject to} \quad l \le A x \le u, \qquad lo \le x \le hi,
\f]
where \f$ A \f$ is a sparse `m` \f$ \times \f$ `n` matrix. Everything is addressed by 0-based
indices: variables by `j` in `[0, n)`, rows by `i` in `[0, m)`. A bound equal to `infinity()`
(resp. `-infinity()`) means "no upper (resp. lower) bound"; equal lower and upper bounds fix a row
or a variable.

The package writes the residual problem (`CGAL::Surface_winding_numbers::Residual_problem`) as a linear
program for such a model; a solver that prefers the problem itself can be written as a residual solver
instead (see the user manual). How the package uses a model, once per call to `solve()` of the winding
number solver that needs the residual (that is, when a connected component of the mesh is neither a
disk nor a sphere):
<ol>
<li>`resize(n, m)`, then `reserve_A(k)` with an upper bound on the number of matrix entries;</li>
<li>`set_variable_bounds()` for some variables, `set_q()` for the variables with a nonzero cost,
    `set_A()` for every matrix entry, `set_l()` and `set_u()` for every row;</li>
<li>`solve()`; the solution is used only if the status is `CGAL::Surface_winding_numbers::LP_status::OPTIMAL`,
    and it is checked against the constraints before use.</li>
</ol>
The package never relies on calls being made in a particular order between `resize()` and
`solve()`, but it does rely on the state set by `resize()`: the variables it does not bound are free
and the variables it does not give a cost have cost zero.

The object is passed by reference (`CGAL::Surface_winding_numbers::parameters::lp_solver(std::ref(lp))`)
and may be reused for several solves: `resize()` must discard the previous program.

\cgalHasModel `CGAL::Surface_winding_numbers::GLPK_linear_program_traits`

\sa `CGAL::surface_winding_numbers()`
\sa `CGAL::Surface_winding_numbers::Surface_winding_numbers_solver`
*/
class SurfaceWindingNumbersLPTraits
{
public:
  /*!
  discards the current program, if any, and starts a new one with `n` variables and `m` rows.
  After the call every variable is free (bounds `-infinity()` and `infinity()`) with cost 0,
  every row is unbounded, and the matrix has no entry.
  */
  void resize(std::size_t n, std::size_t m);

  /*!
  announces that about `k` matrix entries will be given with `set_A()`. It is a hint only: more
  entries must still be accepted.
  */
  void reserve_A(std::size_t k);

  /*!
  sets the cost of variable `j` to `c` (the coefficient of \f$ x_j \f$ in the minimized objective).
  \pre `j < n`
  */
  void set_q(std::size_t j, double c);

  /*!
  sets the bounds of variable `j`: `lo <= x[j] <= hi`. Either bound may be infinite
  (`-infinity()` for `lo`, `infinity()` for `hi`); `lo == hi` fixes the variable.
  \pre `j < n` and `lo <= hi`
  */
  void set_variable_bounds(std::size_t j, double lo, double hi);

  /*!
  adds `a` to the entry `(i, j)` of the constraint matrix \f$ A \f$. Entries given several times for
  the same `(i, j)` are summed; a model must accept them (GLPK, for instance, aborts the process on
  repeated entries, so its model merges them first). Entries never given are zero.
  \pre `i < m` and `j < n`
  */
  void set_A(std::size_t i, std::size_t j, double a);

  /*!
  sets the lower bound of row `i`: \f$ (A x)_i \ge lo \f$; `-infinity()` for none.
  \pre `i < m`
  */
  void set_l(std::size_t i, double lo);

  /*!
  sets the upper bound of row `i`: \f$ (A x)_i \le hi \f$; `infinity()` for none.
  A row with equal lower and upper bounds is an equality.
  \pre `i < m`
  */
  void set_u(std::size_t i, double hi);

  /*!
  returns the value that stands for "no bound", typically `std::numeric_limits<double>::%infinity()`.
  The package only passes it as a bound (today: as the upper bound of its slack variables) and never
  compares anything with it.
  */
  static double infinity();

  /*!
  solves the program.

  On `LP_status::OPTIMAL`, writes the `n` values of an optimal \f$ x \f$ to `x`, in the order of
  the variables (`x[0]` first). On any other status, `x` may receive nothing; what it receives is
  ignored. `LP_status::INFEASIBLE` and `LP_status::UNBOUNDED` are for programs proved infeasible or
  unbounded; `LP_status::FAILED` is for anything else (time limit, numerical trouble, no solver
  available). The package turns every status but `OPTIMAL` into a failed solve with a message in
  `CGAL::Surface_winding_numbers::Solve_report::error`.

  The function may throw an exception derived from `std::exception`; it is caught by the package and
  reported the same way. It must never end the process.

  \tparam OutputIterator an output iterator accepting `double`
  \returns the status of the solve, a value of `CGAL::Surface_winding_numbers::LP_status`
  */
  template <class OutputIterator>
  CGAL::Surface_winding_numbers::LP_status solve(OutputIterator x);
};
