// The exact residual solver's building blocks and edge cases (maximum flows, bounds, fixed arcs, infeasible
// and malformed problems) and its agreement with GLPK on real instances and whole solves.
#include "test_residual_support.h"
// internal::Warm_push_relabel on random networks with scattered excesses and deficits, by push-relabel
// (run()) and by augmenting paths (run_paths()): the flow it
// moves is a maximum flow (the value of internal::Boykov_kolmogorov_flow, Boost's, from scratch), stays within the
// capacities and conserves every imbalance it does not absorb; on a cut, no residual arc leaves
// the source side and every excess left is on it. The same checks hold for Boykov-Kolmogorov's flow.
TEST(LemonResidual, WarmPushRelabelIsAMaximumFlow)
{
  typedef long long Int;
  typedef SI::Warm_push_relabel<Int> PR;
  std::size_t balanced = 0, cut = 0, with_gaps = 0, path_gaps = 0;
  for(unsigned run = 0; run < 400; ++run)
  {
    const unsigned seed = run / 2 + 1;
    const bool paths = run % 2 == 1;
    std::mt19937 gen(seed);
    const std::size_t n = 5 + gen() % 60, m = n + gen() % (3 * n);
    std::vector<std::size_t> tail(m), head(m);
    std::vector<Int> cap(m), back(m), b(n, 0);
    for(std::size_t i = 0; i < m; ++i)
    {
      tail[i] = gen() % n;
      head[i] = (tail[i] + 1 + gen() % (n - 1)) % n;
      cap[i] = Int(gen() % 12);
      back[i] = gen() % 3 == 0 ? 0 : Int(gen() % 12);
    }
    add_zero_sum_imbalances(gen, b);
    PR pr(n);
    for(std::size_t i = 0; i < m; ++i) pr.add_arc(tail[i], head[i], cap[i], back[i]);
    for(std::size_t v = 0; v < n; ++v) pr.set_terminal(v, b[v]);
    const PR::Outcome outcome = paths ? pr.run_paths() : pr.run();
    ASSERT_NE(outcome, PR::OVER_BUDGET);
    if(pr.gaps() > 0) ++(paths ? path_gaps : with_gaps);
    // what a flow (push-relabel's or Boykov-Kolmogorov's) leaves at each node; its arcs stay within
    // their capacities
    auto left_by = [&](const auto& flow) {
      std::vector<Int> left = b;
      for(std::size_t i = 0; i < m; ++i)
      {
        const Int f = flow.flow(i);
        EXPECT_LE(f, cap[i]) << "seed " << seed;
        EXPECT_GE(f, -back[i]) << "seed " << seed;
        left[tail[i]] -= f;
        left[head[i]] += f;
      }
      return left;
    };
    // the arcs that cross a flow's cut are saturated away from its source side
    auto expect_cut_saturated = [&](const auto& flow) {
      for(std::size_t i = 0; i < m; ++i)
      {
        const Int f = flow.flow(i);
        if(flow.source_side(tail[i]) && !flow.source_side(head[i])) EXPECT_EQ(f, cap[i]) << "seed " << seed;
        if(flow.source_side(head[i]) && !flow.source_side(tail[i])) EXPECT_EQ(f, -back[i]) << "seed " << seed;
      }
    };
    // what is left at each node, and the value moved
    const std::vector<Int> left = left_by(pr);
    // a node never sends more than it holds, so no node goes below its own deficit; the value is
    // what the deficits absorbed (excess left anywhere stays in the source side of the cut)
    Int total = 0, value = 0;
    for(std::size_t v = 0; v < n; ++v)
    {
      EXPECT_GE(left[v], std::min(b[v], Int(0))) << "seed " << seed;
      if(b[v] > 0) total += b[v];
      if(b[v] < 0) value += std::min(left[v], Int(0)) - b[v];
    }
    SI::Boykov_kolmogorov_flow<Int> bk(n);   // the reference, from scratch
    for(std::size_t i = 0; i < m; ++i) bk.add_arc(tail[i], head[i], cap[i], back[i]);
    for(std::size_t v = 0; v < n; ++v) bk.set_terminal(v, b[v]);
    EXPECT_EQ(bk.run(), outcome == PR::BALANCED) << "seed " << seed;
    EXPECT_EQ(value, bk.value()) << "seed " << seed;
    {
      // Boykov-Kolmogorov's own flow: within the capacities, conserving what it does not absorb,
      // moving bk.value(), and saturating the arcs that leave its source side
      const std::vector<Int> bk_left = left_by(bk);
      Int bk_value = 0;
      for(std::size_t v = 0; v < n; ++v)
      {
        if(b[v] >= 0) EXPECT_GE(bk_left[v], 0) << "seed " << seed;
        if(b[v] <= 0) { EXPECT_LE(bk_left[v], 0) << "seed " << seed; EXPECT_GE(bk_left[v], b[v]) << "seed " << seed; }
        if(b[v] == 0) EXPECT_EQ(bk_left[v], 0) << "seed " << seed;
        if(b[v] < 0) bk_value += bk_left[v] - b[v];
        if(bk_left[v] > 0) EXPECT_TRUE(bk.source_side(v)) << "seed " << seed;
      }
      EXPECT_EQ(bk_value, bk.value()) << "seed " << seed;
      expect_cut_saturated(bk);
    }
    if(outcome == PR::BALANCED)
    {
      ++balanced;
      EXPECT_EQ(value, total) << "seed " << seed;
      for(std::size_t v = 0; v < n; ++v) EXPECT_EQ(left[v], 0) << "seed " << seed;
      continue;
    }
    ++cut;
    EXPECT_LT(value, total) << "seed " << seed;
    for(std::size_t v = 0; v < n; ++v)
    {
      if(left[v] > 0) EXPECT_TRUE(pr.source_side(v)) << "seed " << seed;
      if(left[v] < 0) EXPECT_FALSE(pr.source_side(v)) << "seed " << seed;
    }
    expect_cut_saturated(pr);
  }
  EXPECT_GT(balanced, 20u);
  EXPECT_GT(cut, 20u);
  EXPECT_GT(with_gaps, 10u);   // the gap heuristic took part
  EXPECT_GT(path_gaps, 10u);
  std::printf("push-relabel and augmenting paths: %zu balanced, %zu cuts, gaps found in %zu and %zu runs\n", balanced, cut,
              with_gaps, path_gaps);
}

// Without refinements, an answer the certificate refuses goes to network simplex on the whole:
// the result is optimal either way.
TEST(LemonResidual, MultilevelFallsBackToNetworkSimplex)
{
  std::size_t fallbacks = 0;
  for(unsigned seed = 1; seed <= 16; ++seed)
  {
    const Random_problem rp = random_problem(400 + seed, true, 10., false);
    Options o = deep_options(0, 0);
    o.coarsest_nodes = 6;   // coarse clusters, no band beyond the jumps, no descent
    o.cluster_size = 8;
    o.band_radius = 0;
    o.finest_band_radius = 0;
    Lemon lemon(o);
    expect_solver_matches_glpk(lemon, rp.P, "multilevel without refinement, seed " + std::to_string(seed));
    if(lemon.statistics().fallback)
    {
      ++fallbacks;
      EXPECT_EQ(lemon.statistics().algorithm, Options::NETWORK_SIMPLEX);
    }
  }
  EXPECT_GT(fallbacks, 0u);
}

TEST(LemonResidual, BoundsWithMultiplicityAndInfiniteBounds)
{
  // a cycle of 4 faces: three free arcs and one arc with bounds [G, 0] or [0, G]; the period of s
  // around the cycle forces a total jump, which goes to the cheap bounded arc as long as it fits
  for(double G : {-3., -2., 2., 3.})
    for(double period : {-2.5, -1.5, 1.5, 2.5, 0.4})
    {
      SWN::Residual_problem P;
      P.number_of_faces = 4;
      P.left = {0, 1, 2, 3};
      P.right = {1, 2, 3, 0};
      P.s = {0.3, -0.1, 0.2, period - 0.4};   // sum = period
      P.cost = {1., 1., 1., 0.01};
      P.lower = {-inf, -inf, -inf, std::min(0., G)};
      P.upper = {inf, inf, inf, std::max(0., G)};
      P.gauge_faces = {2};
      // the jumps sum to the period: J3 takes clamp(period, [lower, upper]), the rest goes on one free arc
      const double J3 = std::min(std::max(period, P.lower[3]), P.upper[3]);
      const double expected = 0.01 * std::abs(J3) + std::abs(period - J3);
      // (LEMON 1.3.1's CostScaling AUGMENT and PARTIAL_AUGMENT loop forever on some of these)
      for(Lemon::Algorithm a : all_algorithms)
      {
        Lemon lemon(with_algorithm(a));
        std::vector<double> sigma;
        ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
        EXPECT_NEAR(P.objective(sigma), expected, 1e-11) << "G " << G << " period " << period;
        EXPECT_LE(P.max_violation(sigma), 1e-12);
        EXPECT_EQ(sigma[2], 0.);
      }
      expect_matches_glpk(P, Options::NETWORK_SIMPLEX, "cycle");
    }
}

TEST(LemonResidual, OneSidedBoundsAndZeroCosts)
{
  std::mt19937 rng(7);
  for(int rep = 0; rep < 6; ++rep)
  {
    Random_problem rp = random_problem(300 + rep, rep % 2 == 0, 20., rep % 3 == 0);
    std::uniform_real_distribution<double> U01(0., 1.);
    for(std::size_t a = 0; a < rp.P.number_of_arcs(); ++a)
    {
      if(rp.P.is_bounded(a)) continue;
      const double r = U01(rng);
      if(r < 0.05) { rp.P.lower[a] = 0; }                       // [0, inf)
      else if(r < 0.1) { rp.P.upper[a] = 0; }                   // (-inf, 0]
      else if(r < 0.13) { rp.P.cost[a] = 0; }                   // free and weightless
      // keep feasibility: these are only forced if the jump of a feasible sigma allows; GLPK decides
    }
    // skip infeasible instances (GLPK says so); otherwise both agree
    SWN::GLPK_linear_program_traits lp;
    std::size_t nv = 0, nr = 0;
    std::vector<double> sg;
    bool feasible = true;
    try { sg = SI::solve_residual_with_lp(rp.P, lp, nv, nr); }
    catch(const SWN::Solver_failure&) { feasible = false; }
    Lemon lemon;
    std::vector<double> sigma;
    const bool ok = lemon.solve_residual(rp.P, sigma);
    EXPECT_EQ(ok, feasible) << lemon.error();
    if(feasible) expect_matches_glpk(rp.P, Options::MULTILEVEL, "one-sided bounds " + std::to_string(rep));
  }
}

TEST(LemonResidual, FixedArcsAreContracted)
{
  // closed s on a torus grid; a few arcs get a fixed nonzero jump
  for(unsigned seed = 1; seed <= 4; ++seed)
  {
    Random_problem rp = random_problem(400 + seed, true, 10., false);
    SWN::Residual_problem& P = rp.P;
    const std::size_t na = P.number_of_arcs();
    // on a periodic grid every cell has three consecutive arcs, its diagonal first: fix the diagonal
    // of every 7th cell to the jump 0.25 (disjoint face pairs: never a cycle)
    std::size_t fixed = 0;
    for(std::size_t a = 0; a < na; a += 3)
    {
      if((a / 3) % 7 != 3) continue;
      P.lower[a] = P.upper[a] = 0.25;
      ++fixed;
    }
    ASSERT_GT(fixed, 0u);
    Lemon lemon;
    std::vector<double> sigma;
    ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
    EXPECT_EQ(lemon.statistics().fixed_arcs, fixed);
    EXPECT_EQ(lemon.statistics().nodes, P.number_of_faces - fixed);
    expect_matches_glpk(P, Options::MULTILEVEL, "fixed arcs, seed " + std::to_string(seed));
  }
}

TEST(LemonResidual, FixedCycles)
{
  // a triangle of faces with all three arcs fixed: consistent iff the fixed jumps match s around it
  SWN::Residual_problem P;
  P.number_of_faces = 4;
  P.left = {0, 1, 2, 2};
  P.right = {1, 2, 0, 3};
  P.s = {0.5, 0.25, -0.75, 0.1};   // sum 0
  P.cost = {1, 1, 1, 1};
  P.lower = {0, 0, 0, -inf};
  P.upper = {0, 0, 0, inf};
  P.gauge_faces = {0};
  Lemon lemon;
  std::vector<double> sigma;
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_LE(P.max_violation(sigma), 1e-12);
  EXPECT_NEAR(P.objective(sigma), 0., 1e-12);
  EXPECT_EQ(lemon.statistics().nodes, 2u);
  EXPECT_EQ(sigma[0], 0.);
  // an arc between two merged faces has a constant jump: fine if within its bounds
  P.left.push_back(1); P.right.push_back(0); P.s.push_back(0.7); P.cost.push_back(2.);
  P.lower.push_back(0.); P.upper.push_back(2.);
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_EQ(lemon.statistics().constant_arcs, 1u);
  EXPECT_NEAR(P.objective(sigma), 2 * 1.2, 1e-12);   // sigma1 - sigma0 = 0.5 (first arc), J = 0.7 + 0.5
  // ... and infeasible if not
  P.upper.back() = 1.;
  EXPECT_FALSE(lemon.solve_residual(P, sigma));
  EXPECT_NE(lemon.error().find("infeasible"), std::string::npos) << lemon.error();
  P.upper.back() = 2.;
  // contradicting fixed arcs
  P.s[0] = 0.6;
  EXPECT_FALSE(lemon.solve_residual(P, sigma));
  EXPECT_NE(lemon.error().find("contradict"), std::string::npos) << lemon.error();
}

TEST(LemonResidual, InfeasibleProblemFailsWithAReason)
{
  // a cycle of bounded arcs whose period does not fit: J0 + J1 + J2 = period with J in [0, 1] each
  SWN::Residual_problem P;
  P.number_of_faces = 3;
  P.left = {0, 1, 2};
  P.right = {1, 2, 0};
  P.s = {1., 1., 1.5};   // period 3.5 > 3
  P.cost = {1, 1, 1};
  P.lower = {0, 0, 0};
  P.upper = {1, 1, 1};
  P.gauge_faces = {0};
  for(Lemon::Algorithm a : all_algorithms)
  {
    Lemon lemon(with_algorithm(a));
    std::vector<double> sigma;
    EXPECT_FALSE(lemon.solve_residual(P, sigma));
    EXPECT_NE(lemon.error().find("infeasible"), std::string::npos) << lemon.error();
    ASSERT_EQ(sigma.size(), 3u);   // the least-violation solution
    EXPECT_GT(lemon.statistics().max_violation, 0.1);
  }
  P.s[2] = 0.5;   // period 2.5: feasible
  Lemon lemon;
  std::vector<double> sigma;
  EXPECT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_NEAR(P.objective(sigma), 2.5, 1e-12);
}

TEST(LemonResidual, EmptyAndTrivialProblems)
{
  Lemon lemon;
  std::vector<double> sigma = {1, 2, 3};
  SWN::Residual_problem P;
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_TRUE(sigma.empty());
  P.number_of_faces = 5;
  P.gauge_faces = {0, 3};
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_EQ(sigma, std::vector<double>(5, 0.));
  // one free arc: optimum 0
  P.left = {1}; P.right = {2}; P.s = {123.456}; P.cost = {1.}; P.lower = {-inf}; P.upper = {inf};
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_NEAR(P.objective(sigma), 0., 1e-12);
  // an arc from a face to itself: constant jump
  P.left = {1}; P.right = {1}; P.s = {0.5}; P.lower = {0}; P.upper = {1};
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << lemon.error();
  EXPECT_NEAR(P.objective(sigma), 0.5, 1e-15);
}

TEST(LemonResidual, MalformedProblemsFailWithoutAborting)
{
  const Random_problem good = random_problem(5, true, 1., false);
  auto expect_fail = [](const SWN::Residual_problem& P, const char* what) {
    Lemon lemon;
    std::vector<double> sigma;
    EXPECT_FALSE(lemon.solve_residual(P, sigma)) << what;
    EXPECT_FALSE(lemon.error().empty()) << what;
  };
  SWN::Residual_problem P = good.P;
  P.s.pop_back();
  expect_fail(P, "sizes");
  P = good.P; P.right[3] = P.number_of_faces;
  expect_fail(P, "face index");
  P = good.P; P.cost[2] = -1;
  expect_fail(P, "negative cost");
  P = good.P; P.cost[2] = std::numeric_limits<double>::quiet_NaN();
  expect_fail(P, "NaN cost");
  P = good.P; P.s[2] = inf;
  expect_fail(P, "infinite s");
  P = good.P; P.lower[2] = 1; P.upper[2] = 0;
  expect_fail(P, "empty bounds");
  P = good.P; P.lower[2] = inf;
  expect_fail(P, "lower = +inf");
  P = good.P; P.gauge_faces.push_back(P.number_of_faces);
  expect_fail(P, "gauge face");
  P = good.P; P.s[2] = 1e300;
  expect_fail(P, "huge s");
}

TEST(LemonResidual, PipelineInstancesMatchGLPK)
{
  {
    Mesh m;
    const int nu = 20, nv = 10;
    auto vs = torus_mesh(m, nu, nv);
    const SWN::Residual_problem P = pipeline_problem(m, broken_curves(vs, nv, 2, 8));
    for(Lemon::Algorithm a : all_algorithms) expect_matches_glpk(P, a, "torus 20x10, broken meridian + broken loop");
  }
  {
    // finer torus, two broken curves, and a second torus: two components
    const SWN::Residual_problem P = two_tori_problem();
    EXPECT_EQ(P.gauge_faces.size(), 2u);
    double o = 0;
    expect_matches_glpk(P, Options::MULTILEVEL, "two tori", &o);
    EXPECT_GT(o, 0.);
    Lemon lemon(deep_options());
    double o2 = 0;
    expect_solver_matches_glpk(lemon, P, "two tori, multilevel", &o2);
    EXPECT_NEAR(o2, o, 1e-9 * (1 + o));
    EXPECT_GE(lemon.statistics().levels, 3u);
  }
}

// The hierarchy's parameters (coarsest size, cluster size, band radius, descent steps, narrow curve
// bands, bands in halves, routing of carried-down flows) change how the multilevel solver gets there, never where: on a pipeline instance (two tori,
// broken curves) every setting certifies network simplex's optimum, through hierarchies of different
// depths.
TEST(LemonResidual, MultilevelParametersChangeTheTimeNotTheOptimum)
{
  const SWN::Residual_problem P = two_tori_problem();
  Lemon reference(with_algorithm(Options::NETWORK_SIMPLEX));
  std::vector<double> sigma;
  ASSERT_TRUE(reference.solve_residual(P, sigma)) << reference.error();
  const double o = P.objective(sigma);
  ASSERT_GT(o, 0.);
  struct Setting { std::size_t coarsest, cluster; int radius; };
  const Setting settings[] = {{12, 2, 0}, {12, 4, 1}, {12, 16, 6}, {12, 64, 2}, {50, 16, 0}, {2000, 16, 6}};
  std::set<std::size_t> depths;
  std::size_t refined = 0, descended = 0, narrower = 0, wide_band = 0, split = 0, routed = 0;
  for(const Setting& s : settings)
    for(std::size_t descent : {std::size_t(0), std::size_t(30)})
      for(std::size_t narrow : {std::size_t(0), std::size_t(1000000)})   // off, on
        for(std::size_t halves : {std::size_t(0), std::size_t(40)})        // first bands in halves: never, from 40 nodes
    {
      const std::string what = "coarsest " + std::to_string(s.coarsest) + ", clusters of " + std::to_string(s.cluster) +
                               ", radius " + std::to_string(s.radius) + ", descent steps " + std::to_string(descent) +
                               ", narrow curve bands up to " + std::to_string(narrow) + " nodes, bands in halves from " +
                               std::to_string(halves) + " nodes";
      Options opt;
      opt.coarsest_nodes = s.coarsest;
      opt.cluster_size = s.cluster;
      opt.band_radius = s.radius;
      opt.finest_band_radius = 2 * s.radius;
      opt.descent_steps = descent;
      opt.narrow_curve_band_nodes = narrow;
      opt.split_band_nodes = halves;
      opt.concurrent = descent == 0;   // the halves on two threads or on one
      // the carried-down flows balanced inside the coarser regions on every level, or on none
      opt.carried_flow_routing_nodes = halves == 0 ? 0 : std::size_t(-1);
      Lemon lemon(opt);
      ASSERT_TRUE(lemon.solve_residual(P, sigma)) << what << ": " << lemon.error();
      EXPECT_LE(P.max_violation(sigma), 1e-9) << what;
      EXPECT_NEAR(P.objective(sigma), o, 1e-9 * (1 + o)) << what;
      EXPECT_TRUE(lemon.statistics().certified) << what;
      EXPECT_FALSE(lemon.statistics().fallback) << what;   // certified by the hierarchy, not by a whole solve
      depths.insert(lemon.statistics().levels);
      if(halves == 0)
      {
        EXPECT_EQ(lemon.statistics().split_bands, 0u) << what;
        if(narrow == 0) wide_band = lemon.statistics().largest_band;
        else narrower += lemon.statistics().largest_band < wide_band;
      }
      else EXPECT_EQ(lemon.statistics().routed_levels, 0u) << what;
      split += lemon.statistics().split_bands > 0;
      routed += lemon.statistics().routed_levels > 0;
      refined += lemon.statistics().refinements > 0;
      descended += lemon.statistics().descent_steps > 0;
    }
  EXPECT_GE(depths.size(), 4u);   // the settings did build different hierarchies (1 to 10 levels when written)
  EXPECT_GE(refined, 2u);         // some were certified only after refinements around barriers
  EXPECT_GE(descended, 2u);       // and some after descent steps along them
  EXPECT_GE(narrower, 2u);        // narrow curve bands did shrink the largest band
  EXPECT_GE(split, 4u);           // bands were solved in halves (then certified all the same)
  EXPECT_GE(routed, 4u);          // and carried-down flows were balanced inside the coarser regions
  EXPECT_EQ(*depths.begin(), 1u);   // coarsest 2000: the problem is its own coarsest level
}

TEST(LemonResidual, WholeSolveGivesTheSameLabelsAsGLPK)
{
  auto compare = [](const Mesh& m, const std::vector<std::vector<Vertex>>& polylines, const std::string& what) {
    auto chain = get(CGAL::dynamic_edge_property_t<int>(), m);
    for(auto e : edges(m)) put(chain, e, 0);
    for(const auto& p : polylines) ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
    std::map<Mesh::Face_index, int> l1, l2;
    std::map<Mesh::Edge_index, int> G1, G2;
    Lemon lemon;
    SWN::GLPK_linear_program_traits glpk;
    SWN::Solve_report r1, r2;
    ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(l1),
                                              SWN::parameters::lp_solver(std::ref(lemon),
                                              SWN::parameters::report(std::ref(r1),
                                              SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G1))))))
      << what << ": " << r1.error;
    ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(l2),
                                              SWN::parameters::lp_solver(std::ref(glpk),
                                              SWN::parameters::report(std::ref(r2),
                                              SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G2))))))
      << what << ": " << r2.error;
    EXPECT_TRUE(r1.lp_ran) << what;
    EXPECT_NEAR(r1.lp_objective, r2.lp_objective, 1e-7 * (1 + r2.lp_objective)) << what;
    EXPECT_EQ(l1, l2) << what;
    EXPECT_EQ(G1, G2) << what;
    int nG = 0;
    for(const auto& g : G1) nG += g.second != 0;
    EXPECT_GT(nG, 0) << what;
    // the default solver (LEMON when built with it) gives the same result
    std::map<Mesh::Face_index, int> l3;
    ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(l3))) << what;
    EXPECT_EQ(l1, l3) << what;
  };
  {
    Mesh m;
    auto vs = torus_mesh(m, 20, 10);
    compare(m, broken_curves(vs, 10, 2, 8), "torus 20x10");
  }
  {
    Mesh m;
    auto vs = torus_mesh(m, 30, 14, 1, 0.35);
    compare(m, broken_curves(vs, 14, 20, 4), "torus 30x14");
  }
  {
    Mesh m;
    auto vs = torus_mesh(m, 24, 12);
    auto vs2 = torus_mesh(m, 16, 8, 1.2, 0.5, 5.);
    auto curves = broken_curves(vs, 12, 3, 10);
    for(auto& c : broken_curves(vs2, 8, 5, 9)) curves.push_back(c);
    compare(m, curves, "two tori");
  }
}

// Options::warm_start (the sketching use): a solver that keeps its last answer reaches the optimum of
// each new problem on the same graph (a broken meridian kept, a broken loop moved step by step, which
// changes the jumps s everywhere a little through the harmonic part), starting from the last answer;
// a problem on another graph, and a warm start that cannot be repaired, are solved afresh.
TEST(LemonResidual, WarmStartsReachTheOptimumOfEachNewProblem)
{
  Mesh m;
  const int nu = 30, nv = 12;
  auto vs = torus_mesh(m, nu, nv);
  for(std::size_t refinements : {std::size_t(8), std::size_t(0)})
  {
    Options o = deep_options(refinements, refinements == 0 ? 0 : 30);
    o.warm_start = true;
    Lemon warm(o), cold(with_algorithm(Options::NETWORK_SIMPLEX));
    std::size_t warm_started = 0;
    for(int step = 0; step < 6; ++step)
    {
      const std::string what = "loop at " + std::to_string(10 + step) + ", max_refinements " + std::to_string(refinements);
      const SWN::Residual_problem P = pipeline_problem(m, broken_curves(vs, nv, 3, 10 + step));
      std::vector<double> sigma, reference;
      ASSERT_TRUE(cold.solve_residual(P, reference)) << cold.error();
      ASSERT_TRUE(warm.solve_residual(P, sigma)) << what << ": " << warm.error();
      EXPECT_TRUE(warm.statistics().certified) << what;
      EXPECT_LE(P.max_violation(sigma), 1e-9) << what;
      EXPECT_NEAR(P.objective(sigma), P.objective(reference), 1e-9 * (1 + P.objective(reference))) << what;
      if(step == 0) EXPECT_FALSE(warm.statistics().warm_started);
      warm_started += warm.statistics().warm_started;
    }
    // with bands and descent steps the moved loop's changes are repaired (5 of 5 when written); without
    // them the carried answer is not optimal for a moved loop and each is solved afresh
    if(refinements > 0) EXPECT_GE(warm_started, 4u);
    else EXPECT_EQ(warm_started, 0u);
    // another graph: solved afresh, then warm again on it
    const SWN::Residual_problem Q = two_tori_problem();
    std::vector<double> sigma;
    ASSERT_TRUE(warm.solve_residual(Q, sigma)) << warm.error();
    EXPECT_FALSE(warm.statistics().warm_started);
    ASSERT_TRUE(warm.solve_residual(Q, sigma)) << warm.error();
    EXPECT_TRUE(warm.statistics().warm_started);   // the same problem again: its own optimum, certified at once
    // the solver keeps the last problem's storage and adjacency for the next one: the same problem with
    // its faces renumbered (as many nodes and arcs, joined otherwise) is another graph, with the same optimum
    SWN::Residual_problem R = Q;
    const auto rotated = [&](std::size_t f) { return (f + 1) % Q.number_of_faces; };
    for(std::size_t a = 0; a < Q.number_of_arcs(); ++a)
    {
      R.left[a] = rotated(Q.left[a]);
      R.right[a] = rotated(Q.right[a]);
    }
    for(std::size_t& f : R.gauge_faces) f = rotated(f);
    std::vector<double> rho;
    ASSERT_TRUE(warm.solve_residual(R, rho)) << warm.error();
    EXPECT_FALSE(warm.statistics().warm_started);
    EXPECT_TRUE(warm.statistics().certified);
    EXPECT_LE(R.max_violation(rho), 1e-9);
    EXPECT_NEAR(R.objective(rho), Q.objective(sigma), 1e-9 * (1 + Q.objective(sigma)));
  }
  // off by default
  EXPECT_FALSE(Options().warm_start);
}
