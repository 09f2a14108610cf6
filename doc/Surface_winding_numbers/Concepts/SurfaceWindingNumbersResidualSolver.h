/*!
\ingroup PkgSurfaceWindingNumbersConcepts
\cgalConcept

A solver of the residual problem of the paper (Eq. 11), given in index form as a
`CGAL::Surface_winding_numbers::Residual_problem`: one shift per face minimizing the weighted sum of
the absolute jumps across arcs, under bounds on the jumps. Models solve the problem directly (for
instance as a minimum-cost flow), without going through a general linear program.

A type is recognised as a model of this concept by the presence of the member function
`solve_residual()`; a type that also models `SurfaceWindingNumbersLPTraits` is used as a residual
solver.

The package checks every returned solution against the bounds of the problem (violations above
1e-6 make the solve fail) and evaluates the objective itself.

\cgalHasModel `CGAL::Surface_winding_numbers::LEMON_residual_solver` (when built with LEMON)
*/
class SurfaceWindingNumbersResidualSolver
{
public:
  /// solves `problem`; on success resizes `sigma` to `problem.number_of_faces` and writes an
  /// optimal shift per face (the shifts of the gauge faces may be anything: only differences
  /// matter). Returns `false` on failure.
  bool solve_residual(const CGAL::Surface_winding_numbers::Residual_problem& problem, std::vector<double>& sigma);
};
