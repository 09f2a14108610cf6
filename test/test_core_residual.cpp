// test_core: the residual problem and its linear program (Residual, LinearProgramTraits).
#include "test_core_support.h"

#include <set>

// =============================================================================================
// Residual (residual.h): local integration, the residual problem, its linear program, the residual function
// =============================================================================================

namespace {
// A residual problem small enough to solve by hand. Faces 0..3; the arcs 0 -> 1 -> 2 -> 0 form a
// cycle: a0 on the curve (Gamma = 1, cost 0.1), a1 and a2 free (costs 2 and 3), s = 0.5 on each; a3
// from face 2 to face 3 on the curve with Gamma = -2 (cost 0.2, s = -0.5). Around the cycle the jumps
// sum to 1.5 whatever sigma: the optimum puts 1 on a0 (its bound), 0.5 on a1 (the cheaper free arc),
// 0 on a2 and a3: objective 0.1 + 2 * 0.5 = 1.1, at sigma = (0, -0.5, -0.5, -1) with face 0 as gauge.
SWN::Residual_problem tiny_residual_problem()
{
  SWN::Residual_problem P;
  P.number_of_faces = 4;
  P.left = {0, 1, 2, 2};
  P.right = {1, 2, 0, 3};
  P.s = {0.5, 0.5, 0.5, -0.5};
  P.cost = {0.1, 2, 3, 0.2};
  P.lower = {0, -inf, -inf, -2};
  P.upper = {1, inf, inf, 0};
  P.gauge_faces = {0};
  return P;
}
const std::vector<double> tiny_optimum = {0, -0.5, -0.5, -1};

// A model of SurfaceWindingNumbersLPTraits that records the program it is given and answers with
// `answer` and `status`.
struct Recording_lp_traits
{
  static double infinity() { return inf; }
  void resize(std::size_t n, std::size_t m)
  {
    q.assign(n, 0.);
    lo.assign(n, -inf);
    hi.assign(n, inf);
    l.assign(m, -inf);
    u.assign(m, inf);
    A.clear();
  }
  void reserve_A(std::size_t) {}
  void set_q(std::size_t j, double c) { q.at(j) = c; }
  void set_variable_bounds(std::size_t j, double a, double b) { lo.at(j) = a; hi.at(j) = b; }
  void set_A(std::size_t i, std::size_t j, double a)
  {
    ASSERT_LT(i, l.size());
    ASSERT_LT(j, q.size());
    A[{i, j}] += a;
  }
  void set_l(std::size_t i, double x) { l.at(i) = x; }
  void set_u(std::size_t i, double x) { u.at(i) = x; }
  template <class OutputIterator>
  SWN::LP_status solve(OutputIterator x) const
  {
    if(status == SWN::LP_status::OPTIMAL) std::copy(answer.begin(), answer.end(), x);
    return status;
  }

  std::vector<double> q, lo, hi, l, u;
  std::map<std::pair<std::size_t, std::size_t>, double> A;
  SWN::LP_status status = SWN::LP_status::OPTIMAL;
  std::vector<double> answer;
};

// A model of SurfaceWindingNumbersResidualSolver that answers with `answer`, and its variant that
// explains its failures.
struct Scripted_residual_solver
{
  bool solve_residual(const SWN::Residual_problem&, std::vector<double>& sigma) const
  {
    sigma = answer;
    return succeed;
  }
  std::vector<double> answer;
  bool succeed = true;
};
struct Explaining_residual_solver : Scripted_residual_solver
{
  std::string error() const { return "no augmenting path"; }
};

// the residual function's answer and what it reports
struct Residual_answer
{
  std::vector<double> sigma;
  double objective = -1;
  std::size_t n_vars = 0, n_rows = 0;
};
template <class Solver_>
Residual_answer residual_answer(const SWN::Residual_problem& P, Solver_& solver)
{
  Residual_answer r;
  r.sigma = SI::residual_function(P, solver, r.objective, r.n_vars, r.n_rows);
  return r;
}
} // namespace

static_assert(SI::is_residual_solver<Scripted_residual_solver>::value, "a residual solver");
static_assert(!SI::is_residual_solver<Recording_lp_traits>::value, "LP traits, not a residual solver");
static_assert(SI::has_error_message<Explaining_residual_solver>::value, "explains its failures");
static_assert(!SI::has_error_message<Scripted_residual_solver>::value, "does not explain its failures");

TEST(Residual, LocalIntegrationStartsAtZeroAndFollowsGammaAlongTheSides)
{
  // v = 0 at every face's first corner, then gamma along the face's sides (signs found from the
  // edges' reference directions); gamma = d phi integrates to phi - phi(first corner)
  const Torus_tables torus(10, 6);
  const SI::Mesh_tables& t = torus.tables();
  const std::vector<double> gamma = random_values(t.ne, 8), phi = random_values(t.nv, 9);
  const std::vector<double> v = SI::local_integration(t, gamma);
  ASSERT_EQ(v.size(), 3 * t.nf);
  for(std::size_t f = 0; f < t.nf; ++f)
  {
    EXPECT_EQ(v[3 * f], 0.);
    for(std::size_t k = 0; k < 2; ++k)
    {
      const std::size_t c = 3 * f + k, e = t.fe[c];
      const double along = t.ev[2 * e] == t.fv[c] && t.ev[2 * e + 1] == t.fv[c + 1] ? 1. : -1.;
      EXPECT_NEAR(v[c + 1] - v[c], along * gamma[e], 1e-15) << "face " << f << ", side " << k;
    }
  }
  const std::vector<double> v_exact = SI::local_integration(t, differential(t, phi));
  for(std::size_t c = 0; c < 3 * t.nf; ++c) EXPECT_NEAR(v_exact[c], phi[t.fv[c]] - phi[t.fv[c / 3 * 3]], 1e-14);
  // integrate_in_face writes its own face only
  std::vector<double> one(3 * t.nf, 7.);
  SI::integrate_in_face(t, gamma, 5, one);
  for(std::size_t c = 0; c < 3 * t.nf; ++c) EXPECT_EQ(one[c], c / 3 == 5 ? v[c] : 7.);
}

TEST(Residual, ProblemHasCurveBoundsUnitCostsAndOneGaugePerComponent)
{
  // a torus carrying a contractible loop (Gamma = +-1), a meridian traversed twice upwards and one
  // twice downwards (+-2), and a disk
  Mesh m;
  const int nu = 12, nv = 6;
  const auto vs = torus_mesh(m, nu, nv);
  grid_disk(m, 4, 3);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 2u);
  const std::vector<Vertex> up = meridian_piece(vs, nv, 8, 0, nv);
  std::vector<Vertex> down = meridian_piece(vs, nv, 10, 0, nv);
  std::reverse(down.begin(), down.end());
  const std::vector<double> chain = table_chain(m, s, {rect_loop(torus_vertex(vs, nv), 2, 1, 5, 3), up, up, down, down});
  const std::vector<double> phi = random_values(t.nv, 10), gamma = random_values(t.ne, 11);
  const double eps = 0.01;
  const SWN::Residual_problem P = SI::residual_problem(t, SI::local_integration(t, gamma), chain, eps);
  ASSERT_EQ(P.number_of_arcs(), t.arcs.size());
  EXPECT_EQ(P.number_of_faces, t.nf);
  double mean_length = 0;
  for(const SI::Arc& arc : t.arcs) mean_length += t.edge_length(arc.edge) / double(t.arcs.size());
  const std::vector<double> v0 = SI::local_integration(t, gamma);
  std::map<double, int> bounded_by;   // Gamma -> arcs
  for(std::size_t a = 0; a < P.number_of_arcs(); ++a)
  {
    const SI::Arc& arc = t.arcs[a];
    const double G = chain[arc.edge];
    EXPECT_EQ(P.left[a], arc.left_side / 3);
    EXPECT_EQ(P.right[a], arc.right_side / 3);
    EXPECT_EQ(P.is_bounded(a), G != 0);
    if(G != 0)
    {
      ++bounded_by[G];
      EXPECT_EQ(P.lower[a], std::min(0., G));   // 0 <= J / Gamma <= 1
      EXPECT_EQ(P.upper[a], std::max(0., G));
    }
    else
    {
      EXPECT_EQ(P.lower[a], -inf);
      EXPECT_EQ(P.upper[a], inf);
    }
    EXPECT_NEAR(P.cost[a], (G != 0 ? eps : 1.) * t.edge_length(arc.edge) / mean_length, 1e-12);
    double J[2];
    for(int k = 0; k < 2; ++k)
    {
      const std::size_t v = t.ev[2 * arc.edge + k];
      J[k] = v0[corner_of(t, P.left[a], v)] - v0[corner_of(t, P.right[a], v)];
    }
    EXPECT_NEAR(P.s[a], 0.5 * (J[0] + J[1]), 1e-15);
  }
  EXPECT_EQ(bounded_by.size(), 4u) << "Gamma = -2, -1, 1 and 2 all occur";
  EXPECT_EQ(bounded_by[-2] + bounded_by[2], 2 * nv);
  EXPECT_EQ(bounded_by[-1] + bounded_by[1], 10);
  ASSERT_EQ(P.gauge_faces.size(), 2u);
  for(std::size_t c = 0; c < 2; ++c) EXPECT_EQ(t.face_component[P.gauge_faces[c]], c);

  // the costs do not change with the scale of the mesh
  SI::Mesh_tables scaled = t;
  for(double& x : scaled.points) x *= 1000;
  const SWN::Residual_problem Q = SI::residual_problem(scaled, SI::local_integration(scaled, gamma), chain, eps);
  for(std::size_t a = 0; a < P.number_of_arcs(); ++a) EXPECT_NEAR(Q.cost[a], P.cost[a], 1e-12);

  // an exact gamma = d phi integrates without jumps: s = phi(R's first corner) - phi(L's first corner),
  // the same at both ends of every arc, and sigma_f = phi(f's first corner) cancels every jump
  const SWN::Residual_problem E = SI::residual_problem(t, SI::local_integration(t, differential(t, phi)), chain, eps);
  std::vector<double> sigma(t.nf);
  for(std::size_t f = 0; f < t.nf; ++f) sigma[f] = phi[t.fv[3 * f]];
  for(std::size_t a = 0; a < E.number_of_arcs(); ++a) EXPECT_NEAR(E.s[a], phi[t.fv[3 * E.right[a]]] - phi[t.fv[3 * E.left[a]]], 1e-14);
  EXPECT_LT(E.objective(sigma), 1e-12);
  EXPECT_LT(E.max_violation(sigma), 1e-14);
}

TEST(Residual, LinearProgramHasOneRowPerArcAndSlacksOnTheFreeArcs)
{
  const SWN::Residual_problem P = tiny_residual_problem();
  Recording_lp_traits lp;
  lp.answer = {0, -0.5, -0.5, -1, 0.5, 0, 0, 0};
  std::size_t n_vars = 0, n_rows = 0;
  EXPECT_EQ(SI::solve_residual_with_lp(P, lp, n_vars, n_rows), tiny_optimum);   // the shifts, first
  EXPECT_EQ(n_vars, 8u);   // a shift per face, two slacks per free arc
  EXPECT_EQ(n_rows, 4u);
  ASSERT_EQ(lp.q.size(), 8u);
  ASSERT_EQ(lp.l.size(), 4u);
  // the gauge face is fixed, the other shifts are free, the slacks p and n nonnegative
  EXPECT_EQ(lp.lo, (std::vector<double>{0, -inf, -inf, -inf, 0, 0, 0, 0}));
  EXPECT_EQ(lp.hi, (std::vector<double>{0, inf, inf, inf, inf, inf, inf, inf}));
  // row a: sigma_L - sigma_R (- p + n on a free arc) = J - s, between the bounds of J minus s
  const std::map<std::pair<std::size_t, std::size_t>, double> A = {
    {{0, 0}, 1}, {{0, 1}, -1},                              // a0: 0 -> 1
    {{1, 1}, 1}, {{1, 2}, -1}, {{1, 4}, -1}, {{1, 5}, 1},   // a1: 1 -> 2, slacks 4 and 5
    {{2, 2}, 1}, {{2, 0}, -1}, {{2, 6}, -1}, {{2, 7}, 1},   // a2: 2 -> 0, slacks 6 and 7
    {{3, 2}, 1}, {{3, 3}, -1}};                             // a3: 2 -> 3
  EXPECT_EQ(lp.A, A);
  EXPECT_EQ(lp.l, (std::vector<double>{-0.5, -0.5, -0.5, -1.5}));
  EXPECT_EQ(lp.u, (std::vector<double>{0.5, -0.5, -0.5, 0.5}));
  // costs: on both slacks of a free arc; on a bounded arc |J| = J (Gamma > 0) or -J (Gamma < 0),
  // whose shifts part goes to the faces
  EXPECT_EQ(lp.q, (std::vector<double>{0.1, -0.1, -0.2, 0.2, 2, 2, 3, 3}));
  // so at every feasible sigma (p - n = J on the free arcs), the program's objective is P's, less the
  // constant part cost * |s| of the bounded arcs
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> U(-1, 1);
  int feasible = 0;
  for(int trial = 0; trial < 200; ++trial)
  {
    std::vector<double> sigma = tiny_optimum;
    for(std::size_t f = 1; f < 4; ++f) sigma[f] += U(rng);
    if(P.max_violation(sigma) > 0) continue;
    ++feasible;
    std::vector<double> x = sigma;
    for(std::size_t a : {1, 2}) { x.push_back(std::max(P.jump(sigma, a), 0.)); x.push_back(std::max(-P.jump(sigma, a), 0.)); }
    double objective = 0.1 * 0.5 - 0.2 * -0.5;   // cost * s on a0, -cost * s on a3
    for(std::size_t j = 0; j < 8; ++j) objective += lp.q[j] * x[j];
    EXPECT_NEAR(objective, P.objective(sigma), 1e-12);
    for(std::size_t a = 0; a < 4; ++a)
    {
      double row = 0;
      for(const auto& entry : lp.A)
        if(entry.first.first == a) row += entry.second * x[entry.first.second];
      EXPECT_GE(row, lp.l[a] - 1e-12);
      EXPECT_LE(row, lp.u[a] + 1e-12);
    }
  }
  EXPECT_GT(feasible, 10);
}

TEST(Residual, LinearProgramFailuresAreReportedAsSolverFailures)
{
  const SWN::Residual_problem P = tiny_residual_problem();
  Recording_lp_traits lp;
  std::size_t n_vars, n_rows;
  const std::pair<SWN::LP_status, const char*> statuses[] = {{SWN::LP_status::INFEASIBLE, "is infeasible"},
                                                             {SWN::LP_status::UNBOUNDED, "is unbounded"},
                                                             {SWN::LP_status::FAILED, "could not be solved"}};
  for(const auto& status : statuses)
  {
    lp.status = status.first;
    const std::string what = failure_message([&] { SI::solve_residual_with_lp(P, lp, n_vars, n_rows); });
    EXPECT_NE(what.find(status.second), std::string::npos) << what;
  }
  lp.status = SWN::LP_status::OPTIMAL;
  lp.answer = {0, -0.5, -0.5, -1, 0.5, 0, 0};   // one slack short
  const std::string what = failure_message([&] { SI::solve_residual_with_lp(P, lp, n_vars, n_rows); });
  EXPECT_NE(what.find("wrong size"), std::string::npos) << what;
}

TEST(Residual, ResidualFunctionChecksAndReportsTheSolversAnswer)
{
  const SWN::Residual_problem P = tiny_residual_problem();
  Scripted_residual_solver solver;
  solver.answer = tiny_optimum;
  Residual_answer r = residual_answer(P, solver);
  EXPECT_EQ(r.sigma, tiny_optimum);
  EXPECT_NEAR(r.objective, 1.1, 1e-12);
  EXPECT_EQ(r.n_vars, 4u);   // a residual solver sees the faces' shifts only
  EXPECT_EQ(r.n_rows, 4u);
  solver.answer = {0, -0.4, -0.5, -1};   // feasible, not optimal: reported as it is
  EXPECT_NEAR(residual_answer(P, solver).objective, 0.1 * 0.9 + 2 * 0.6, 1e-12);
  // through LP traits: the size of the program, and the same objective
  Recording_lp_traits lp;
  lp.answer = {0, -0.5, -0.5, -1, 0.5, 0, 0, 0};
  r = residual_answer(P, lp);
  EXPECT_EQ(r.sigma, tiny_optimum);
  EXPECT_NEAR(r.objective, 1.1, 1e-12);
  EXPECT_EQ(r.n_vars, 8u);
  EXPECT_EQ(r.n_rows, 4u);

  // rejected: the wrong size, a violated bound (J = 1.2 > Gamma = 1 on a0; from the solver or from
  // the LP), a NaN, a failure (with the solver's reason when it gives one)
  const std::pair<std::vector<double>, const char*> wrong[] = {{{0, -0.5, -0.5}, "wrong size"},
                                                              {{0, -0.7, -0.5, -1}, "violates 0 <= J/Gamma <= 1 by 0.2"},
                                                              {{0, NaN, -0.5, -1}, "violates"}};
  for(const auto& answer : wrong)
  {
    solver.answer = answer.first;
    const std::string what = failure_message([&] { residual_answer(P, solver); });
    EXPECT_NE(what.find(answer.second), std::string::npos) << what;
  }
  lp.answer = {0, -0.7, -0.5, -1, 0.3, 0, 0, 0};
  EXPECT_NE(failure_message([&] { residual_answer(P, lp); }).find("violates"), std::string::npos);
  solver.answer = tiny_optimum;
  solver.succeed = false;
  EXPECT_EQ(failure_message([&] { residual_answer(P, solver); }), "the residual solver failed");
  Explaining_residual_solver explaining;
  explaining.succeed = false;
  EXPECT_EQ(failure_message([&] { residual_answer(P, explaining); }), "the residual solver failed: no augmenting path");
}

#ifdef CGAL_USE_GLPK
TEST(Residual, GLPKFindsTheOptimumOfATinyProblemByHand)
{
  SWN::Residual_problem P = tiny_residual_problem();
  SWN::GLPK_linear_program_traits lp;
  const Residual_answer r = residual_answer(P, lp);
  ASSERT_EQ(r.sigma.size(), 4u);
  for(std::size_t f = 0; f < 4; ++f) EXPECT_NEAR(r.sigma[f], tiny_optimum[f], 1e-9) << "face " << f;
  EXPECT_NEAR(r.objective, 1.1, 1e-9);
  EXPECT_EQ(r.n_vars, 8u);
  EXPECT_EQ(r.n_rows, 4u);
  // a1 and a2 on the curve too, with Gamma = 0.1: the jumps around the cycle cannot reach 1.5
  P.lower[1] = P.lower[2] = 0;
  P.upper[1] = P.upper[2] = 0.1;
  const std::string what = failure_message([&] { residual_answer(P, lp); });
  EXPECT_NE(what.find("infeasible"), std::string::npos) << what;
}

namespace {
// The authors' formulation of Eq. 11 (slack z >= |J| on every arc, 0 <= Gamma J <= Gamma^2), solved
// with GLPK: an independent formulation whose optimum must equal ours.
double reference_residual_objective(const SI::Mesh_tables& t, const SWN::Residual_problem& P, const std::vector<double>& chain)
{
  SWN::GLPK_linear_program_traits lp;
  const std::size_t na = P.number_of_arcs();
  lp.resize(t.nf + na, 4 * na);
  std::size_t row = 0;
  for(std::size_t a = 0; a < na; ++a)
  {
    const std::size_t L = P.left[a], R = P.right[a], z = t.nf + a;
    const double G = chain[t.arcs[a].edge], s = P.s[a];
    lp.set_variable_bounds(z, 0, lp.infinity());
    lp.set_q(z, P.cost[a]);
    lp.set_A(row, L, 1); lp.set_A(row, R, -1); lp.set_A(row, z, -1); lp.set_u(row++, -s);   // J <= z
    lp.set_A(row, L, 1); lp.set_A(row, R, -1); lp.set_A(row, z, 1); lp.set_l(row++, -s);    // -z <= J
    lp.set_A(row, L, G); lp.set_A(row, R, -G); lp.set_l(row, -G * s); lp.set_u(row++, G * G - G * s);
    ++row;   // the reference's trivial row
  }
  std::vector<double> x;
  EXPECT_EQ(lp.solve(std::back_inserter(x)), SWN::LP_status::OPTIMAL);
  x.resize(t.nf);
  EXPECT_LT(P.max_violation(x), 1e-7);
  return P.objective(x);
}
} // namespace

TEST(Residual, OptimumOnATorusSatisfiesTheBoundsAndMatchesTheAuthorsFormulation)
{
  const int nu = 20, nv = 10;
  const Torus_tables torus(nu, nv);
  const SI::Mesh_tables& t = torus.tables();
  // broken meridian + broken contractible loop
  const std::vector<double> chain = torus.chain({meridian_piece(torus.vs, nv, 2, 0, 3),
    meridian_piece(torus.vs, nv, 2, 5, nv), without_last(rect_loop(torus_vertex(torus.vs, nv), 8, 2, 12, 5), 4)});
  const SWN::Residual_problem P = torus.solver->core().residual_problem_of(chain, 0.01);
  SWN::GLPK_linear_program_traits lp;
  const Residual_answer r = residual_answer(P, lp);
  for(std::size_t k = 0; k < P.number_of_arcs(); ++k)
  {
    const double G = chain[t.arcs[k].edge];
    if(G == 0) { EXPECT_FALSE(P.is_bounded(k)); continue; }
    const double J = P.jump(r.sigma, k);
    EXPECT_GE(J / G, -1e-7);
    EXPECT_LE(J / G, 1 + 1e-7);
  }
  EXPECT_GT(r.objective, 0.);
  EXPECT_NEAR(r.objective, reference_residual_objective(t, P, chain), 1e-7 * (1 + r.objective));
}

// =============================================================================================
// LinearProgramTraits (GLPK_linear_program_traits.h)
// =============================================================================================

TEST(LinearProgramTraits, StatusAndDuplicates)
{
  SWN::GLPK_linear_program_traits lp;
  lp.resize(2, 2);   // max x + y s.t. x + 2y <= 4, 3x + y <= 6, x, y >= 0 -> (1.6, 1.2)
  lp.set_q(0, -1); lp.set_q(1, -1);
  lp.set_variable_bounds(0, 0, lp.infinity()); lp.set_variable_bounds(1, 0, lp.infinity());
  lp.set_A(0, 0, 1); lp.set_A(0, 1, 2); lp.set_u(0, 4);
  lp.set_A(1, 0, 3); lp.set_A(1, 1, 0.5); lp.set_A(1, 1, 0.5); lp.set_u(1, 6);   // repeated entry summed
  std::vector<double> x;
  ASSERT_EQ(lp.solve(std::back_inserter(x)), SWN::LP_status::OPTIMAL);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], 1.6, 1e-9);
  EXPECT_NEAR(x[1], 1.2, 1e-9);

  lp.resize(1, 2);   // x >= 2 and x <= 1
  lp.set_A(0, 0, 1); lp.set_l(0, 2); lp.set_A(1, 0, 1); lp.set_u(1, 1);
  x.clear();
  EXPECT_EQ(lp.solve(std::back_inserter(x)), SWN::LP_status::INFEASIBLE);
  EXPECT_TRUE(x.empty());

  lp.resize(1, 0);   // min -x, x >= 0
  lp.set_q(0, -1); lp.set_variable_bounds(0, 0, lp.infinity());
  EXPECT_EQ(lp.solve(std::back_inserter(x)), SWN::LP_status::UNBOUNDED);
}
#endif // CGAL_USE_GLPK


// =============================================================================================
// BeyondEq11 (named parameter completed_homology_class; issue 46)
// =============================================================================================

namespace {
// torus_mesh(24, 12) with a meridian at i = 12 drawn from j = 0 to j = `drawn` only, and the outputs
struct Half_meridian
{
  static constexpr int nu = 24, nv = 12, i0 = 12;
  Mesh m;
  Mesh::Property_map<Mesh::Edge_index, int> chain, G;
  Mesh::Property_map<Mesh::Face_index, int> W;
  explicit Half_meridian(int drawn)
  {
    const auto vs = torus_mesh(m, nu, nv);
    chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    G = m.add_property_map<Mesh::Edge_index, int>("e:G", 0).first;
    W = m.add_property_map<Mesh::Face_index, int>("f:W", 0).first;
    EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, meridian_piece(vs, nv, i0, 0, drawn), chain));
  }
  template <class NP>
  bool solve(const NP& np)
  {
    return CGAL::surface_winding_numbers(m, chain, W, SWN::parameters::nonbounding_chain_map(G, np));
  }
  // edges of G that run up the meridian i0 (+1 from j to j + 1), and the others
  std::pair<int, int> G_up_the_meridian() const
  {
    int up = 0, other = 0;
    for(auto e : edges(m))
    {
      if(G[e] == 0) continue;
      const auto h = halfedge(e, m);
      const std::size_t a = std::size_t(source(h, m)), b = std::size_t(target(h, m));
      const bool on = a / nv == std::size_t(i0) && b / nv == std::size_t(i0);
      const int dir = int((b % nv + nv - a % nv) % nv == 1) - int((a % nv + nv - b % nv) % nv == 1);   // +1: h goes up
      (on && G[e] * dir == 1 ? up : other) += 1;
    }
    return {up, other};
  }
  std::size_t distinct_labels() const
  {
    std::set<int> l;
    for(auto f : faces(m)) l.insert(W[f]);
    return l.size();
  }
};
} // namespace

TEST(BeyondEq11, CompletedHomologyClassKeepsAMeridianWithAHalfGap)
{
  // Half of a meridian drawn (6 of its 12 edges). Analytic answer: G = the meridian closed along its
  // gap (12 edges, upwards), one label everywhere. The harmonic part of the broken curve has a period
  // below 1/2 around the tube, so Eq. 11 (the default) puts jumps below 1/2 on it: G rounds to nothing
  // (the labels stay constant here, the residual jump of w across the half meridian rounding away).
  Half_meridian c(6);
  SWN::Solve_report rep;
  ASSERT_TRUE(c.solve(SWN::parameters::report(std::ref(rep))));
  EXPECT_EQ(rep.interior_endpoints, 2u);
  EXPECT_EQ(c.G_up_the_meridian(), std::make_pair(0, 0));
  EXPECT_EQ(c.distinct_labels(), 1u);
  ASSERT_TRUE(c.solve(SWN::parameters::completed_homology_class(true)));
  EXPECT_EQ(c.G_up_the_meridian(), std::make_pair(int(c.nv), 0));
  EXPECT_EQ(c.distinct_labels(), 1u);
}

TEST(BeyondEq11, CompletedHomologyClassChangesNothingWithoutGaps)
{
  // a closed meridian and a closed contractible loop: no interior endpoint, so the same labels and G
  Mesh m;
  const auto vs = torus_mesh(m, 24, 12);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  for(const auto& p : {meridian_piece(vs, 12, 3, 0, 12), rect_loop(torus_vertex(vs, 12), 10, 2, 15, 6)})
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
  Solver solver(m);
  Labels_and_G paper, completed;
  ASSERT_TRUE(paper.solve(solver, chain));
  ASSERT_TRUE(completed.solve(solver, chain, SWN::parameters::completed_homology_class(true)));
  paper.expect_equal(completed);
  int inside = 0;
  for(const auto& fl : paper.labels) inside += fl.second != paper.labels.begin()->second;
  EXPECT_EQ(inside, 2 * 5 * 4);
}

TEST(BeyondEq11, DirectedCompletionContinuesTheCurveRoundTheHandle)
{
  // 4 (then 5) of the 12 edges of a meridian drawn upwards from j = 0. The shortest closure of the gap
  // backs out of the upper end and runs down beside the drawn piece (5, then 6 edges: the completed
  // curve bounds a sliver, the class of nothing); the directed completion leaves the upper end upwards
  // and reaches the lower end from below: the rest of the meridian (8, then 7 edges), the meridian's
  // class. With the option, G is the whole meridian (12 edges, upwards).
  const int nu = 24, nv = 12, i0 = 12;
  const Torus_tables torus(nu, nv);
  const SI::Mesh_tables& t = torus.tables();
  for(int drawn : {4, 5})
  {
    const std::vector<double> chain = torus.chain({meridian_piece(torus.vs, nv, i0, 0, drawn)});
    const std::vector<double> rest = torus.chain({meridian_piece(torus.vs, nv, i0, drawn, nv)});
    const std::vector<double> shortest = SI::shortest_path_completion(t, chain), directed = SI::directed_completion(t, chain);
    EXPECT_EQ(directed, rest);
    // the shortest closure: drawn + 1 edges, none of the gap's (a closure round the tube needs at least
    // nv - drawn > drawn + 1 edges)
    EXPECT_EQ(std::count_if(shortest.begin(), shortest.end(), [](double x) { return x != 0; }), drawn + 1);
    for(std::size_t e = 0; e < t.ne; ++e) EXPECT_FALSE(rest[e] != 0 && shortest[e] != 0);
    std::vector<int> completed(t.ne);
    for(std::size_t e = 0; e < t.ne; ++e) completed[e] = int(chain[e] + shortest[e]);
    EXPECT_TRUE(SI::is_relatively_closed(t, completed));
    Half_meridian c(drawn);
    ASSERT_TRUE(c.solve(SWN::parameters::completed_homology_class(true)));
    EXPECT_EQ(c.G_up_the_meridian(), std::make_pair(int(c.nv), 0));
    EXPECT_EQ(c.distinct_labels(), 1u);
  }
}

TEST(BeyondEq11, DirectedCompletionMakesTheShortestJoinsFirst)
{
  // Two rows of a grid, each a curve going right with a gap: row 5 from the border to (2, 5), again from
  // (3, 5) to the border; row 4 from the border to (2, 4), again from (6, 4). The end (2, 4) comes first in
  // vertex order, and the directed search taken in vertex order closes the gaps otherwise (checked once,
  // 2026-12-07); the shortest join of all, (2, 5) -> (3, 5), is made first, so each gap is closed along
  // its row.
  const Grid_tables g(8, 9, 0.);
  std::vector<Vertex> a, b, c, e;
  for(int i = 0; i <= 2; ++i) { a.push_back(g.V(i, 5)); c.push_back(g.V(i, 4)); }
  for(int i = 3; i <= 8; ++i) b.push_back(g.V(i, 5));
  for(int i = 6; i <= 8; ++i) e.push_back(g.V(i, 4));
  const std::vector<double> chain = g.chain({a, b, c, e});
  std::vector<Vertex> row4;
  for(int i = 2; i <= 6; ++i) row4.push_back(g.V(i, 4));
  EXPECT_EQ(SI::directed_completion(g.tables(), chain), g.chain({{g.V(2, 5), g.V(3, 5)}, row4}));
}
