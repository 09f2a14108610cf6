// The exact residual solver (LEMON network flows) against GLPK's simplex: random residual problems
// on dual graphs of grids (torus, disk, several components), real instances from the pipeline, and
// whole solves.
#include "test_residual_support.h"

// ---------------------------------------------------------------------------------------------

TEST(LemonResidual, NameAndDefaults)
{
  EXPECT_STREQ(Lemon::name(), "lemon");
  Lemon l;
  EXPECT_EQ(l.options().algorithm, Options::MULTILEVEL);
  EXPECT_TRUE(l.options().concurrent);
  EXPECT_TRUE(l.error().empty());
  static_assert(SI::is_residual_solver<Lemon>::value, "LEMON_residual_solver models SurfaceWindingNumbersResidualSolver");
  static_assert(SI::takes_concurrency<Lemon>::value, "LEMON_residual_solver takes the concurrency setting");
  static_assert(!std::is_copy_constructible<Lemon>::value, "not copyable");
#ifdef CGAL_SWN_USE_LEMON
  static_assert(std::is_same<SI::Default_linear_program_traits, Lemon>::value, "LEMON is the default residual solver");
#endif
  // the default is the multilevel solver; a problem this small is its coarsest level (one network
  // simplex, no hierarchy)
  const Random_problem rp = random_problem(11, true, 10., false);
  std::vector<double> sigma;
  ASSERT_TRUE(l.solve_residual(rp.P, sigma)) << l.error();
  EXPECT_EQ(l.statistics().algorithm, Options::MULTILEVEL);
  EXPECT_EQ(l.statistics().levels, 1u);
  EXPECT_FALSE(l.statistics().fallback);
  EXPECT_TRUE(l.statistics().certified);
  EXPECT_GE(l.statistics().cost_exponent, 30);
  // the documented defaults; sizes below their minimum are raised to it
  EXPECT_EQ(l.options().descent_steps, 1000u);
  EXPECT_EQ(l.options().finest_band_radius, 8);
  EXPECT_EQ(l.options().band_radius, 3);
  EXPECT_EQ(l.options().coarsest_nodes, 2000u);
  EXPECT_EQ(l.options().cluster_size, 16u);
  EXPECT_EQ(l.options().max_refinements, 16u);
  EXPECT_EQ(l.options().max_flow_budget, 200.);
  EXPECT_EQ(l.options().narrow_curve_band_nodes, (std::numeric_limits<std::size_t>::max)());
  EXPECT_EQ(l.options().split_band_nodes, 5000u);
  EXPECT_EQ(l.options().carried_flow_routing_nodes, 100000u);
  Options o;
  o.coarsest_nodes = 0;
  o.cluster_size = 1;
  o.band_radius = -3;
  o.finest_band_radius = -2;
  o.max_flow_budget = -1.;
  Lemon p(o);
  EXPECT_EQ(p.options().coarsest_nodes, 1u);
  EXPECT_EQ(p.options().cluster_size, 2u);
  EXPECT_EQ(p.options().band_radius, 0);
  EXPECT_EQ(p.options().finest_band_radius, 0);
  EXPECT_EQ(p.options().max_flow_budget, -1.);
  // a sequential solve leaves the options as they were
  ASSERT_TRUE(l.solve_residual(rp.P, sigma, false)) << l.error();
  EXPECT_TRUE(l.options().concurrent);
}

TEST(LemonResidual, RandomClosedProblemsMatchGLPK)
{
  for(unsigned seed = 1; seed <= 12; ++seed)
  {
    const Random_problem rp = random_problem(seed, true, 10., seed % 3 == 0);
    ASSERT_FALSE(rp.bounded.empty());
    expect_matches_glpk(rp.P, all_algorithms[seed % n_algorithms], "closed s, seed " + std::to_string(seed));
  }
}

TEST(LemonResidual, RandomNonClosedProblemsWithLargeSMatchGLPK)
{
  for(unsigned seed = 1; seed <= 12; ++seed)
  {
    const Random_problem rp = random_problem(100 + seed, false, 1000., seed % 2 == 0);
    double smax = 0;
    for(double s : rp.P.s) smax = std::max(smax, std::abs(s));
    EXPECT_GT(smax, 100.);
    expect_matches_glpk(rp.P, all_algorithms[seed % n_algorithms], "non-closed s, seed " + std::to_string(seed));
  }
}

TEST(LemonResidual, AllAlgorithmsAgree)
{
  for(unsigned seed = 1; seed <= 4; ++seed)
  {
    const Random_problem rp = random_problem(200 + seed, seed % 2 == 0, seed % 2 == 0 ? 5. : 500., true);
    std::vector<double> objectives;
    for(Lemon::Algorithm a : all_algorithms)
    {
      Lemon lemon(with_algorithm(a));
      std::vector<double> sigma;
      ASSERT_TRUE(lemon.solve_residual(rp.P, sigma)) << lemon.error();
      EXPECT_EQ(lemon.statistics().algorithm, a);
      EXPECT_FALSE(lemon.statistics().fallback);
      EXPECT_LE(rp.P.max_violation(sigma), 1e-9);
      objectives.push_back(rp.P.objective(sigma));
    }
    for(double o : objectives) EXPECT_NEAR(o, objectives[0], 1e-10 * (1 + objectives[0]));
  }
}

// The multilevel solver with a deep hierarchy (coarsest level of 12 nodes, clusters of 4, bands of
// radius 1 and 2): bands, descent steps along barriers, refinements around barriers and the final
// certificate are all exercised, and the optimum is GLPK's. Without descent steps, barriers are
// handled by band refinements alone.
TEST(LemonResidual, MultilevelHierarchyMatchesGLPK)
{
  for(std::size_t descent : {std::size_t(0), std::size_t(30)})
  {
    std::size_t refined = 0, deep = 0, descended = 0;
    for(unsigned seed = 1; seed <= 16; ++seed)
    {
      const bool closed = seed % 4 != 0;
      const Random_problem rp = random_problem(300 + seed, closed, closed ? 10. : 100., seed % 3 == 0);
      Lemon lemon(deep_options(8, descent));
      expect_solver_matches_glpk(lemon, rp.P, "multilevel, descent " + std::to_string(descent) + ", seed " + std::to_string(seed));
      const Lemon::Statistics& st = lemon.statistics();
      if(descent == 0) EXPECT_EQ(st.descent_steps, 0u);
      if(!st.fallback)
      {
        EXPECT_EQ(st.algorithm, Options::MULTILEVEL);
        EXPECT_GE(st.levels, 3u) << "seed " << seed;
        EXPECT_LT(st.largest_band, rp.P.number_of_faces + 3) << "seed " << seed;
        deep += st.levels >= 3;
        refined += st.refinements > 0;
        descended += st.descent_steps > 0;
      }
    }
    EXPECT_GE(deep, 12u);   // the hierarchy certified most answers without network simplex on the whole
    if(descent == 0)
      EXPECT_GT(refined, 0u);   // some only after a refinement around a barrier
    else
      EXPECT_GT(descended, 0u);   // some only after descent steps along barriers
    std::printf("multilevel, descent steps %zu: %zu of 16 certified through the hierarchy, %zu after refinements, "
                "%zu after descent steps\n", descent, deep, refined, descended);
  }
}

// Descent steps alone (no band refinement allowed): where the certificate of the finest level is
// refused, the steps along its barriers reach the optimum that GLPK finds; without them, the same
// settings need network simplex on the whole problem. Among the 40 problems, some barriers fall
// apart into pieces that each get their own line search.
TEST(LemonResidual, DescentStepsReachTheOptimumWithoutBands)
{
  std::size_t fallbacks_without = 0, certified_by_descent = 0, several_pieces = 0;
  for(unsigned seed = 1; seed <= 40; ++seed)
  {
    const bool closed = seed % 4 != 0;
    const Random_problem rp = random_problem(600 + seed, closed, closed ? 10. : 100., seed % 3 == 0);
    Lemon without(deep_options(0, 0)), with(deep_options(0, 1000));
    expect_solver_matches_glpk(without, rp.P, "no refinement, no descent, seed " + std::to_string(seed));
    expect_solver_matches_glpk(with, rp.P, "no refinement, descent, seed " + std::to_string(seed));
    EXPECT_EQ(with.statistics().refinements, 0u);
    // each connected piece of a barrier rises by its own line search
    EXPECT_GE(with.statistics().descent_pieces, with.statistics().descent_steps);
    several_pieces += with.statistics().descent_pieces > with.statistics().descent_steps;
    if(without.statistics().fallback)
    {
      ++fallbacks_without;
      EXPECT_FALSE(with.statistics().fallback) << "seed " << seed;   // descent certified where bands were needed
      EXPECT_GT(with.statistics().descent_steps, 0u) << "seed " << seed;
      certified_by_descent += with.statistics().certified && !with.statistics().fallback;
    }
  }
  EXPECT_GE(fallbacks_without, 3u);   // the settings do leave refused certificates on the finest level
  EXPECT_EQ(certified_by_descent, fallbacks_without);
  EXPECT_GT(several_pieces, 0u);   // some barriers fall apart into several pieces, each with its line search
  std::printf("descent without bands: %zu of 40 with a barrier of several pieces\n", several_pieces);
}

TEST(LemonResidual, SymmetricTorusWithALongGapIsCertifiedByDescentSteps)
{
  // a regular 160 x 139 torus (44k faces) with an 8-vertex piece of a meridian (a gap of 131 edges) and a
  // small closed loop: many completions of the meridian have the same length. With gamma from the
  // 2-form Laplacian the finest level needed about 80 descent steps, and with at most 30 (the default
  // until 2026-12-03) the rest went to band refinements of up to 51k nodes at ~10 s each
  // (benchmark/residual_solvers.md); with gamma projected on the harmonic basis it needs 8. Either
  // way the finest level must be certified by descent steps, without any band refinement
  Mesh m;
  const int nu = 160, nv = 139;
  auto vs = torus_mesh(m, nu, nv);
  auto V = [&](int i, int j) { return vs[std::size_t(i * nv + j)]; };
  std::vector<Vertex> a, loop;
  for(int j = 0; j <= 7; ++j) a.push_back(V(2, j));
  for(int i = 8; i <= 12; ++i) loop.push_back(V(i, 2));
  for(int j = 3; j <= 5; ++j) loop.push_back(V(12, j));
  for(int i = 11; i >= 8; --i) loop.push_back(V(i, 5));
  for(int j = 4; j >= 2; --j) loop.push_back(V(8, j));
  auto chain = get(CGAL::dynamic_edge_property_t<int>(), m);
  for(auto e : edges(m)) put(chain, e, 0);
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, a, chain));
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, loop, chain));
  std::map<Mesh::Face_index, int> labels;
  Lemon lemon;
  EXPECT_GE(lemon.options().descent_steps, 200u);
  SWN::Solve_report report;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(labels),
                                            SWN::parameters::lp_solver(std::ref(lemon), SWN::parameters::report(std::ref(report)))))
    << report.error;
  const Lemon::Statistics& st = lemon.statistics();
  EXPECT_TRUE(st.certified);
  EXPECT_EQ(st.refinements, 0u);
  EXPECT_GT(st.descent_steps, 0u);
  int inside = 0;
  for(const auto& l : labels) inside += l.second == 1;
  EXPECT_EQ(inside, 2 * 4 * 3);
}

// The certificate's maximum flow, whichever algorithm finishes it (push-relabel alone, Boost's
// Boykov-Kolmogorov alone, or push-relabel stopped early by a tiny work budget and completed by
// Boykov-Kolmogorov), certifies the same optimum as GLPK.
TEST(LemonResidual, MultilevelMaxFlowAlgorithmsAgree)
{
  std::size_t handed_over = 0;
  for(unsigned seed = 1; seed <= 8; ++seed)
  {
    const bool closed = seed % 4 != 0;
    const Random_problem rp = random_problem(500 + seed, closed, closed ? 10. : 100., seed % 3 == 0);
    for(double budget : {-1., 0., 0.5, 200.})
    {
      Options o = deep_options();
      o.max_flow_budget = budget;
      Lemon lemon(o);
      expect_solver_matches_glpk(lemon, rp.P, "max-flow budget " + std::to_string(budget) + ", seed " + std::to_string(seed));
      const Lemon::Statistics& st = lemon.statistics();
      EXPECT_GT(st.certificates, 0u);
      if(budget <= 0) EXPECT_EQ(st.max_flow_fallbacks, 0u);
      if(budget == 0.5) handed_over += st.max_flow_fallbacks;
    }
  }
  EXPECT_GT(handed_over, 0u);   // the tiny budget did hand flows over to Boykov-Kolmogorov
}

// Which maximum flow a certificate ends with does not change the shifts: Boykov-Kolmogorov alone,
// push-relabel alone and the default hand-over give the same sigma, to the last bit, on instances
// whose certificates are refused (descent steps taken). (Where optima tie, the same shifts rest on
// the barrier rule of mark_barrier(), the same set for every maximum flow; these instances did not
// show a tie: the test also passed with another rule for Boykov-Kolmogorov's barrier.)
TEST(LemonResidual, MaximumFlowAlgorithmsLeaveTheSameShifts)
{
  std::size_t descents = 0;
  for(unsigned seed = 1; seed <= 8; ++seed)
  {
    const bool closed = seed % 4 != 0;
    const Random_problem rp = random_problem(600 + seed, closed, closed ? 10. : 100., seed % 3 == 0);
    std::vector<double> reference;
    struct Setting { const char* name; double budget; };
    for(const Setting& setting : {Setting{"default budget", 200.}, Setting{"Boykov-Kolmogorov alone", 0.},
                                  Setting{"push-relabel alone", -1.}, Setting{"tiny budget", 0.5}})
    {
      Options o = deep_options();
      o.max_flow_budget = setting.budget;
      Lemon lemon(o);
      std::vector<double> sigma;
      ASSERT_TRUE(lemon.solve_residual(rp.P, sigma)) << lemon.error();
      EXPECT_TRUE(lemon.statistics().certified) << setting.name << ", seed " << seed;
      if(reference.empty())
      {
        reference = sigma;
        descents += lemon.statistics().descent_steps;
      }
      else
        EXPECT_EQ(sigma, reference) << setting.name << ", seed " << seed;
    }
  }
  EXPECT_GT(descents, 0u);   // the instances do refuse certificates
}

// The certificates of a level reuse their maximum flows: the graph is built by the first run and
// later problems only reset the capacities (reset_arc) and the imbalances. Five problems in a row on
// one random graph: the reused objects move the same value, find the same outcome and the same
// flow as objects built afresh for each problem (both algorithms are deterministic).
TEST(LemonResidual, MaximumFlowsReusedOnTheSameGraphAnswerAsNewOnes)
{
  typedef long long Int;
  typedef SI::Warm_push_relabel<Int> PR;
  typedef SI::Boykov_kolmogorov_flow<Int> BK;
  std::size_t problems = 0, cuts = 0;
  for(unsigned seed = 1; seed <= 60; ++seed)
  {
    std::mt19937 gen(seed);
    const std::size_t n = 5 + gen() % 40, m = n + gen() % (3 * n);
    std::vector<std::size_t> tail(m), head(m);
    for(std::size_t i = 0; i < m; ++i)
    {
      tail[i] = gen() % n;
      head[i] = (tail[i] + 1 + gen() % (n - 1)) % n;
    }
    PR pr_kept(n);
    BK bk_kept(n);
    for(int round = 0; round < 5; ++round, ++problems)
    {
      std::vector<Int> cap(m), back(m), b(n, 0);
      for(std::size_t i = 0; i < m; ++i)
      {
        cap[i] = Int(gen() % 12);
        back[i] = gen() % 3 == 0 ? 0 : Int(gen() % 12);
      }
      add_zero_sum_imbalances(gen, b);
      PR pr_new(n);
      BK bk_new(n);
      for(std::size_t i = 0; i < m; ++i)
      {
        pr_new.add_arc(tail[i], head[i], cap[i], back[i]);
        bk_new.add_arc(tail[i], head[i], cap[i], back[i]);
        if(round == 0) { pr_kept.add_arc(tail[i], head[i], cap[i], back[i]); bk_kept.add_arc(tail[i], head[i], cap[i], back[i]); }
        else { pr_kept.reset_arc(i, cap[i], back[i]); bk_kept.reset_arc(i, cap[i], back[i]); }
      }
      ASSERT_EQ(pr_kept.number_of_arcs(), m);
      ASSERT_EQ(bk_kept.number_of_arcs(), m);
      for(std::size_t v = 0; v < n; ++v)
      {
        pr_new.set_terminal(v, b[v]); pr_kept.set_terminal(v, b[v]);
        bk_new.set_terminal(v, b[v]); bk_kept.set_terminal(v, b[v]);
      }
      const PR::Outcome outcome = pr_new.run();
      EXPECT_EQ(pr_kept.run(), outcome) << "seed " << seed << ", round " << round;
      const bool balanced = bk_new.run();
      EXPECT_EQ(bk_kept.run(), balanced) << "seed " << seed << ", round " << round;
      EXPECT_EQ(balanced, outcome == PR::BALANCED) << "seed " << seed << ", round " << round;
      EXPECT_EQ(bk_kept.value(), bk_new.value()) << "seed " << seed << ", round " << round;
      if(outcome == PR::CUT) ++cuts;
      for(std::size_t i = 0; i < m; ++i)
      {
        EXPECT_EQ(pr_kept.flow(i), pr_new.flow(i)) << "seed " << seed << ", round " << round;
        EXPECT_EQ(bk_kept.flow(i), bk_new.flow(i)) << "seed " << seed << ", round " << round;
      }
      for(std::size_t v = 0; v < n; ++v)
      {
        EXPECT_EQ(pr_kept.source_side(v), pr_new.source_side(v)) << "seed " << seed << ", round " << round;
        EXPECT_EQ(bk_kept.source_side(v), bk_new.source_side(v)) << "seed " << seed << ", round " << round;
      }
    }
  }
  EXPECT_EQ(problems, 300u);
  EXPECT_GT(cuts, 0u);
  EXPECT_LT(cuts, problems);
}
