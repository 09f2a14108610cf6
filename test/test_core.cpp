// Stage-by-stage tests of the numerical core (flat tables), of the LP traits and of the solver class.
// One GoogleTest suite per stage (include/CGAL/Surface_winding_numbers/internal/), in pipeline order:
//   MeshTables (mesh_tables.h), UnionFind (union_find.h), LocalityOrder (locality_order.h),
//   CotanWeights (cotan_weights.h), JumpLaplace (jump_laplace.h), NestedDissection
//   (nested_dissection.h), Derivatives (derivatives.h), HarmonicPart (harmonic_part.h), Residual
//   (residual.h), LinearProgramTraits (GLPK_linear_program_traits.h), WindingNumber
//   (winding_number.h), NonboundingChain (nonbounding_chain.h), ReducedResidual (reduced_residual.h),
//   Solver (pipeline.h and the solver class, end to end).
//
// The stages are spread over test_core*.cpp, all built into the binary test_core; this file holds the
// last two.
#include "test_core_support.h"

// =============================================================================================
// ReducedResidual (reduced_residual.h) and end-to-end solves on one torus
// =============================================================================================

namespace {
// A torus_mesh(24, 12) carrying a meridian broken by a one-edge gap and a 5 x 4 contractible loop
// broken by a one-edge gap, far apart ("e:chain"), and two sets of outputs (labels, G) to compare.
struct Broken_meridian_and_loop
{
  static constexpr int nu = 24, nv = 12;
  Mesh m;
  Mesh::Property_map<Mesh::Edge_index, int> chain;
  Mesh::Property_map<Mesh::Face_index, int> l1, l2;
  Mesh::Property_map<Mesh::Edge_index, int> G1, G2;

  Broken_meridian_and_loop()
  {
    const auto vs = torus_mesh(m, nu, nv);
    chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    l1 = m.add_property_map<Mesh::Face_index, int>("f:l1", 0).first;
    l2 = m.add_property_map<Mesh::Face_index, int>("f:l2", 0).first;
    G1 = m.add_property_map<Mesh::Edge_index, int>("e:G1", 0).first;
    G2 = m.add_property_map<Mesh::Edge_index, int>("e:G2", 0).first;
    for(const auto& p : {meridian_piece(vs, nv, 2, 0, 4), meridian_piece(vs, nv, 2, 6, nv),
                         without_last(rect_loop(torus_vertex(vs, nv), 10, 2, 15, 6), 1)})   // one-edge gap left open
      EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
  }

  // solve k (1 or 2) into l_k and G_k with the named parameters np
  template <class NP>
  bool solve(int k, const NP& np)
  {
    return CGAL::surface_winding_numbers(m, chain, k == 1 ? l1 : l2, SWN::parameters::nonbounding_chain_map(k == 1 ? G1 : G2, np));
  }

  // the two agree face by face and edge by edge, and give the analytic answer: label 1 on the
  // 2 x 5 x 4 faces inside the loop, the completed meridian (nv edges) as G
  void expect_same_analytic_answer() const
  {
    int inside = 0, nG = 0;
    for(auto f : faces(m)) { EXPECT_EQ(l1[f], l2[f]); inside += l1[f] == 1; }
    for(auto e : edges(m)) { EXPECT_EQ(G1[e], G2[e]); nG += G1[e] != 0; }
    EXPECT_EQ(inside, 2 * 5 * 4);
    EXPECT_EQ(nG, nv);
  }
};
} // namespace

TEST(ReducedResidual, ShortestPathsCompleteTheGaps)
{
  // a chord with a two-edge gap: the straight path across the gap (the unique shortest one on a
  // regular grid); a path from the border that stops two edges short of the other side: completed to
  // the nearest border vertex. The completed curves are closed relative to the border.
  const Grid_tables g(8, 9, 0.);
  const SI::Mesh_tables& t = g.tables();
  const std::vector<Vertex> row_left = {g.V(0, 4), g.V(1, 4), g.V(2, 4), g.V(3, 4)},
                            row_right = {g.V(5, 4), g.V(6, 4), g.V(7, 4), g.V(8, 4)};
  struct Case { std::vector<std::vector<Vertex>> curve, completion; };
  for(const Case& c : {Case{{row_left, row_right}, {{g.V(3, 4), g.V(4, 4), g.V(5, 4)}}},
                       Case{{grid_column(g.vs, g.n, 4, 0, 6)}, {grid_column(g.vs, g.n, 4, 6, 8)}}})
  {
    const std::vector<double> chain = g.chain(c.curve);
    const std::vector<double> completion = SI::shortest_path_completion(t, chain);
    EXPECT_EQ(completion, g.chain(c.completion));
    std::vector<int> completed(t.ne);
    for(std::size_t e = 0; e < t.ne; ++e) completed[e] = int(chain[e] + completion[e]);
    EXPECT_TRUE(SI::is_relatively_closed(t, completed));
  }
}

TEST(ReducedResidual, AgreesWithTheExactResidualOnSeparatedCurves)
{
  // broken meridian + broken contractible loop, far apart: the reduced problem (Sec. 6) gives the
  // same labels and the same G as Eq. 11, with far fewer LP variables
  Broken_meridian_and_loop c;
  ASSERT_FALSE(::testing::Test::HasFailure());
  SWN::Solve_report exact, reduced;
  ASSERT_TRUE(c.solve(1, SWN::parameters::report(std::ref(exact))));
  ASSERT_TRUE(c.solve(2, SWN::parameters::use_reduced_residual(true, SWN::parameters::report(std::ref(reduced))))) << reduced.error;
  EXPECT_TRUE(reduced.reduced_residual);
  EXPECT_LT(reduced.lp_variables * 10, exact.lp_variables);
  c.expect_same_analytic_answer();
}

// =============================================================================================
// Solver (pipeline.h, the solver class and the free function, end to end)
// =============================================================================================

TEST(Solver, ManyCurvesOnOneMeshMatchTheFreeFunction)
{
  Mesh m;
  const int nu = 20, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  Solver solver(m);
  ASSERT_TRUE(solver.is_valid());
  for(int i0 = 0; i0 < 3; ++i0)
  {
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    for(auto e : edges(m)) chain[e] = 0;
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, meridian_piece(vs, nv, 2 + 5 * i0, 0, 3 + i0), chain));
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, meridian_piece(vs, nv, 2 + 5 * i0, 5 + i0, nv), chain));
    Labels_and_G by_solver, by_function;
    ASSERT_TRUE(by_solver.solve(solver, chain));
    ASSERT_TRUE(by_function.solve(m, chain));
    by_solver.expect_equal(by_function);
    int nG = 0;
    for(auto e : edges(m)) nG += by_solver.G[e] != 0;
    EXPECT_EQ(nG, nv);   // the completed meridian
    EXPECT_TRUE(solver.report().hodge_projection);
    m.remove_property_map(chain);
  }
}

TEST(Solver, CurvesWithoutEndpointsShareTheKeptJumpLaplacian)
{
  // on a torus: an open curve, then closed loops, whose jump Laplacian is the mesh's 0-form Laplacian:
  // the solver class keeps its factorization, and the answers are those of the free function, which
  // factorizes anew every time; keep_hodge_factorization(false) drops it
  Mesh m;
  const int nu = 20, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  const auto V = torus_vertex(vs, nv);
  Solver solver(m);
  struct Curve { std::vector<std::vector<Vertex>> polylines; bool open; int inside; };
  const std::vector<Vertex> square = rect_loop(V, 5, 2, 8, 5), big = rect_loop(V, 10, 1, 15, 4);
  const std::vector<Curve> curves = {{{meridian_piece(vs, nv, 2, 0, 3)}, true, 0},   // open piece of a meridian
                                     {{square}, false, 2 * 3 * 3},
                                     {{big, meridian_piece(vs, nv, 17, 0, nv)}, false, 2 * 5 * 3},   // with a nonbounding loop
                                     {{square}, false, 2 * 3 * 3}};
  std::vector<bool> reused;
  for(int keep = 1; keep >= 0; --keep)
    for(const Curve& c : curves)
    {
      auto chain = get(CGAL::dynamic_edge_property_t<int>(), m);
      for(auto e : edges(m)) put(chain, e, 0);
      for(const auto& p : c.polylines) ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
      Labels_and_G by_solver, by_function;
      ASSERT_TRUE(by_solver.solve(solver, chain, SWN::parameters::keep_hodge_factorization(keep == 1))) << solver.report().error;
      reused.push_back(solver.report().jump_laplacian_reused);
      EXPECT_EQ(solver.report().interior_endpoints > 0, c.open);
      ASSERT_TRUE(by_function.solve(m, chain));
      by_solver.expect_equal(by_function);
      int inside = 0;
      for(const auto& l : by_solver.labels) inside += l.second == 1;
      if(!c.open) EXPECT_EQ(inside, c.inside);
    }
  // kept: the open curve's harmonic basis keeps the 0-form Laplacian it factorized on the second
  // thread, which the closed curves then use as it is; dropped: nothing is reused
  EXPECT_EQ(reused, std::vector<bool>({false, true, true, true, false, false, false, false}));
}

TEST(Solver, SurfaceMeshWithGarbageAndScaleInvariance)
{
  Mesh m;
  const int n = 14;
  auto vs = grid_disk(m, n, 9);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, square_loop(vs, n, 3, 3, 9, 10), chain));
  // remove a corner face without collecting the garbage
  Mesh::Face_index corner = face(halfedge(vs[0], vs[1], m).first, m);
  CGAL::Euler::remove_face(halfedge(corner, m), m);
  ASSERT_TRUE(m.has_garbage());
  auto labels = m.add_property_map<Mesh::Face_index, int>("f:label", -7).first;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, labels));
  std::map<int, int> hist;
  for(auto f : faces(m)) ++hist[labels[f]];
  ASSERT_EQ(hist.size(), 2u);
  EXPECT_EQ(hist[1], 2 * 6 * 7);
  for(double scale : {1e8, 1e-8})
  {
    Mesh m2 = m;
    for(auto v : vertices(m2)) m2.point(v) = K::Point_3(scale * m2.point(v).x() + 3, scale * m2.point(v).y() - 1, 2);
    auto chain2 = m2.property_map<Mesh::Edge_index, int>("e:chain").first;
    auto labels2 = m2.add_property_map<Mesh::Face_index, int>("f:label2", -7).first;
    ASSERT_TRUE(CGAL::surface_winding_numbers(m2, chain2, labels2));
    for(auto f : faces(m2)) EXPECT_EQ(labels2[f], labels[f]);
  }
}

#include <CGAL/boost/graph/Face_filtered_graph.h>

TEST(Solver, FaceFilteredGraphSolvesOneComponent)
{
  // two grids side by side; the filtered graph keeps the second one only
  Mesh m;
  const int n = 10;
  grid_disk(m, n, 2);
  Mesh other;
  auto vs2 = grid_disk(other, n, 4);
  std::vector<Vertex> loop2 = square_loop(vs2, n, 2, 2, 6, 7);
  const std::size_t offset = num_vertices(m);
  m.join(other);
  std::vector<Vertex> loop;
  for(Vertex v : loop2) loop.push_back(Vertex(std::size_t(v) + offset));
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, loop, chain));
  std::vector<Mesh::Face_index> selected;
  for(auto f : faces(m)) if(std::size_t(f) >= std::size_t(2 * n * n)) selected.push_back(f);
  CGAL::Face_filtered_graph<Mesh> ffg(m, selected);
  ASSERT_EQ(num_faces(ffg), std::size_t(2 * n * n));
  auto labels = m.add_property_map<Mesh::Face_index, int>("f:label", -5).first;
  ASSERT_TRUE(CGAL::surface_winding_numbers(ffg, chain, labels));
  std::map<int, int> hist;
  for(auto f : faces(m)) ++hist[labels[f]];
  EXPECT_EQ(hist[-5], 2 * n * n);      // faces outside the filtered graph untouched
  EXPECT_EQ(hist[1], 2 * 4 * 5);
  EXPECT_EQ(hist[0], 2 * n * n - 2 * 4 * 5);
}

namespace {
// solves with CHOLMOD (the default) and with Eigen's LDLT, checks that both give the same labels and
// the same w (to 1e-8), and returns the number of faces labelled 1
template <class ChainMap>
int faces_labelled_one_by_both_sparse_solvers(Mesh& m, const ChainMap& chain)
{
  auto l1 = m.add_property_map<Mesh::Face_index, int>("f:l1", 0).first;
  auto l2 = m.add_property_map<Mesh::Face_index, int>("f:l2", 0).first;
  auto w1 = m.add_property_map<Mesh::Halfedge_index, double>("h:w1", 0).first;
  auto w2 = m.add_property_map<Mesh::Halfedge_index, double>("h:w2", 0).first;
  EXPECT_TRUE(CGAL::surface_winding_numbers(m, chain, l1, SWN::parameters::winding_number_map(w1)));
  SI::Eigen_LDLT_sparse_solver ldlt;
  EXPECT_TRUE(CGAL::surface_winding_numbers(m, chain, l2, SWN::parameters::winding_number_map(w2).sparse_linear_solver(ldlt)));
  int inside = 0;
  std::size_t differing = 0;
  for(auto f : faces(m)) { differing += l1[f] != l2[f]; inside += l1[f] == 1; }
  EXPECT_EQ(differing, 0u) << "faces labelled differently by CHOLMOD and LDLT";
  double largest = 0;
  for(auto h : halfedges(m))
    if(!is_border(h, m) && std::isfinite(w1[h])) largest = std::max(largest, std::abs(w1[h] - w2[h]));
  EXPECT_LT(largest, 1e-8) << "largest difference of w between CHOLMOD and LDLT";
  return inside;
}
} // namespace

TEST(Solver, SparseSolversAgree)
{
  Mesh m;
  const int nu = 20, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, meridian_piece(vs, nv, 2, 0, 7), chain));   // open meridian piece
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, rect_loop(torus_vertex(vs, nv), 8, 2, 12, 5), chain));
  EXPECT_EQ(faces_labelled_one_by_both_sparse_solvers(m, chain), 2 * 4 * 3);
}

TEST(Solver, LargeMeshInNestedDissectionOrderAgreesWithLDLT)
{
  // 160k unknowns: CHOLMOD (the default) factorizes the jump Laplacian in the package's
  // nested-dissection order (no ordering of its own), Eigen's LDLT with AMD; a closed square loop
  const int n = 400;
  Mesh m;
  auto vs = grid_disk(m, n);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, square_loop(vs, n, 100, 120, 300, 290), chain));
  {
    Solver s(m);
    ASSERT_GE(s.tables().nv, SI::nested_dissection_unknowns);
    expect_permutation(SI::vertex_elimination_order(s.tables()), s.tables().nv);
    if(::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_EQ(faces_labelled_one_by_both_sparse_solvers(m, chain), 2 * 200 * 170);
}

TEST(Solver, HarmonicBasisAndTwoFormLaplacianGiveTheSameAnswer)
{
  // the same solve with the Hodge projection on the harmonic basis (the default at 2 classes) and
  // with the 2-form Laplacian (harmonic_basis_max_classes = 0)
  Broken_meridian_and_loop c;
  ASSERT_FALSE(::testing::Test::HasFailure());
  std::vector<SI::Core_result> results;
  std::vector<SWN::Solve_report> reports;
  for(std::size_t max_classes : {SI::harmonic_basis_max_classes, std::size_t(0)})
  {
    Solver s(c.m);
    std::vector<double> chain(num_edges(c.m), 0.);
    for(auto e : edges(c.m)) chain[s.edge_index(e)] = get(c.chain, e);
    SI::Solve_options options;
    options.harmonic_basis_max_classes = max_classes;
    SI::Default_linear_program_traits lp;
    reports.emplace_back();
    results.push_back(s.core().solve(chain, options, lp, reports.back()));
    EXPECT_TRUE(reports.back().hodge_projection);
  }
  EXPECT_EQ(results[0].labels, results[1].labels);
  EXPECT_EQ(results[0].G, results[1].G);
  for(std::size_t k = 0; k < results[0].w.size(); ++k)
    if(std::isfinite(results[0].w[k]) || std::isfinite(results[1].w[k])) EXPECT_NEAR(results[0].w[k], results[1].w[k], 1e-8);
  EXPECT_NEAR(reports[0].lp_objective, reports[1].lp_objective, 1e-9 * (1 + reports[1].lp_objective));
  int inside = 0;
  for(int l : results[0].labels) inside += l == 1;
  EXPECT_EQ(inside, 2 * 5 * 4);
}

TEST(Solver, ConcurrentFactorizationsGiveTheSameAnswerAsSequential)
{
  // broken meridian + broken contractible loop: the Hodge projection is needed, and by default its
  // harmonic basis is built on a second thread (the 0-form Laplacian's factorization there, the
  // cohomology generators on this thread meanwhile); the answer is the analytic one and the same as
  // with everything on this thread, also when the solver object is reused
  Broken_meridian_and_loop c;
  ASSERT_FALSE(::testing::Test::HasFailure());
  Mesh& m = c.m;
  auto w1 = m.add_property_map<Mesh::Halfedge_index, double>("h:w1", 0).first;
  auto w2 = m.add_property_map<Mesh::Halfedge_index, double>("h:w2", 0).first;
  SWN::Solve_report concurrent, sequential;
  ASSERT_TRUE(c.solve(1, SWN::parameters::winding_number_map(w1, SWN::parameters::report(std::ref(concurrent)))));
  ASSERT_TRUE(c.solve(2, SWN::parameters::winding_number_map(w2, SWN::parameters::concurrency(CGAL::Sequential_tag(),
                SWN::parameters::report(std::ref(sequential)))))) << sequential.error;
  EXPECT_TRUE(concurrent.hodge_projection);
  EXPECT_TRUE(sequential.hodge_projection);
  c.expect_same_analytic_answer();
  auto expect_same_w = [&](Mesh::Property_map<Mesh::Halfedge_index, double> w) {
    for(auto h : halfedges(m))
      if(std::isfinite(w1[h]) || std::isfinite(w[h])) EXPECT_NEAR(w1[h], w[h], 1e-9);
  };
  expect_same_w(w2);
  EXPECT_NEAR(concurrent.lp_objective, sequential.lp_objective, 1e-9 * (1 + sequential.lp_objective));

  // the solver class keeps the harmonic basis built on the second thread for its next solve
  Solver solver(m);
  auto l3 = m.add_property_map<Mesh::Face_index, int>("f:l3", 0).first;
  auto expect_labels_of_the_first_solve = [&] {
    for(auto f : faces(m)) EXPECT_EQ(l3[f], c.l1[f]);
  };
  for(int k = 0; k < 2; ++k)
  {
    ASSERT_TRUE(solver.solve(c.chain, l3)) << solver.report().error;
    EXPECT_TRUE(solver.report().hodge_projection);
    expect_labels_of_the_first_solve();
  }
  // freed after a solve (keep_hodge_factorization(false)), it is factorized again by the next one,
  // and the answers stay the same
  auto w3 = m.add_property_map<Mesh::Halfedge_index, double>("h:w3", 0).first;
  for(int k = 0; k < 2; ++k)
  {
    ASSERT_TRUE(solver.solve(c.chain, l3, SWN::parameters::keep_hodge_factorization(false,
                                          SWN::parameters::winding_number_map(w3)))) << solver.report().error;
    EXPECT_TRUE(solver.report().hodge_projection);
    expect_labels_of_the_first_solve();
    expect_same_w(w3);
  }
  ASSERT_TRUE(solver.solve(c.chain, l3)) << solver.report().error;
  expect_labels_of_the_first_solve();
}

#ifdef CGAL_SWN_USE_CHOLMOD
// The package's supernodal factorization (the default sparse solver) on a matrix that is not a mesh
// Laplacian: a 2D grid with a dense block coupled to it (supernodes of one column to dozens), against
// Eigen's LLT, one and many columns, from two threads at once, and the halves of a solve (forward of unit
// vectors, sparse, included); a matrix that is not positive definite is reported, never solved.
TEST(SupernodalCholesky, AgreesWithEigenAndReportsIndefiniteMatrices)
{
  typedef Eigen::SparseMatrix<double> SM;
  const int g = 30, dense = 40, n = g * g + dense;
  std::vector<Eigen::Triplet<double>> t;
  for(int i = 0; i < g; ++i)
    for(int j = 0; j < g; ++j)
    {
      const int v = i * g + j;
      t.emplace_back(v, v, 4.5 + 0.01 * (v % 5));
      if(i + 1 < g) { t.emplace_back(v, v + g, -1); t.emplace_back(v + g, v, -1); }
      if(j + 1 < g) { t.emplace_back(v, v + 1, -1); t.emplace_back(v + 1, v, -1); }
    }
  for(int a = 0; a < dense; ++a)
  {
    t.emplace_back(g * g + a, g * g + a, 2.0 * dense);
    for(int b = 0; b < a; ++b) { t.emplace_back(g * g + a, g * g + b, 0.5); t.emplace_back(g * g + b, g * g + a, 0.5); }
    t.emplace_back(g * g + a, 17 * a, -1);
    t.emplace_back(17 * a, g * g + a, -1);
  }
  SM A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  SI::Supernodal_cholesky<SM> S;
  ASSERT_EQ(S.compute(A).info(), Eigen::Success);
  EXPECT_GT(S.factor_entries(), std::size_t(A.nonZeros() / 2));
  Eigen::SimplicialLLT<SM> reference(A);
  ASSERT_EQ(reference.info(), Eigen::Success);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, 11);
  const Eigen::MatrixXd X = reference.solve(B);
  EXPECT_LT((S.solve(B) - X).norm(), 1e-12 * X.norm());
  EXPECT_LT((S.solve(B.col(3)) - X.col(3)).norm(), 1e-12 * X.norm());
  double difference[2] = {1, 1};
  std::thread other([&] {
    SI::Supernodal_cholesky<SM>::Solve_workspace ws;
    const Eigen::Map<const Eigen::MatrixXd> x(S.solve_with_workspace(B.data(), std::size_t(n), 11, ws), n, 11);
    difference[1] = (x - X).norm();
  });
  SI::Supernodal_cholesky<SM>::Solve_workspace ws;
  const Eigen::Map<const Eigen::MatrixXd> x(S.solve_with_workspace(B.data(), std::size_t(n), 11, ws), n, 11);
  difference[0] = (x - X).norm();
  other.join();
  EXPECT_LT(difference[0], 1e-12 * X.norm());
  EXPECT_LT(difference[1], 1e-12 * X.norm());
  // the halves of a solve, and the forward half of unit vectors (A = Q^T L L^T Q): g_d = L^-1 Q e_d is
  // that of the whole forward half, nonzero on few entries, and g_i . g_j = (A^-1)_ij
  std::vector<double> w, scratch, y;
  Eigen::VectorXd x0(n);
  S.forward(B.col(0).data(), w, scratch);
  S.backward(w, x0.data(), scratch);
  EXPECT_LT((x0 - X.col(0)).norm(), 1e-12 * X.norm());
  const int unknowns[3] = {0, 17 * 9, g * g + 5};
  SI::Sparse_column gs[3];
  for(int a = 0; a < 3; ++a)
  {
    const int d = unknowns[a];
    S.unit_forward(std::size_t(d), gs[a], y);
    EXPECT_TRUE(std::all_of(y.begin(), y.end(), [](double v) { return v == 0; }));   // left as it came
    EXPECT_LT(gs[a].index.size(), std::size_t(n));
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, d);
    S.forward(e.data(), w, scratch);
    Eigen::VectorXd sparse = Eigen::VectorXd::Zero(n);
    for(std::size_t k = 0; k < gs[a].index.size(); ++k)
    {
      if(k > 0) EXPECT_LT(gs[a].index[k - 1], gs[a].index[k]);
      sparse[Eigen::Index(gs[a].index[k])] = gs[a].value[k];
    }
    EXPECT_LT((sparse - Eigen::Map<const Eigen::VectorXd>(w.data(), n)).norm(), 1e-14 * sparse.norm());
  }
  EXPECT_LT(gs[0].index.size(), std::size_t(n / 4));   // a corner of the grid: a short path in the elimination tree
  for(int a = 0; a < 3; ++a)
  {
    const Eigen::VectorXd column = reference.solve(Eigen::VectorXd::Unit(n, unknowns[a]));
    for(int b = 0; b < 3; ++b)
    {
      double dot = 0;
      for(std::size_t k = 0; k < gs[a].index.size(); ++k)
        for(std::size_t l = 0; l < gs[b].index.size(); ++l)
          if(gs[a].index[k] == gs[b].index[l]) dot += gs[a].value[k] * gs[b].value[l];
      EXPECT_NEAR(dot, column[unknowns[b]], 1e-12 * std::abs(column[unknowns[a]]));
    }
  }
  SM indefinite = A;
  indefinite.coeffRef(g * g + 3, g * g + 3) = -1;
  SI::Supernodal_cholesky<SM> F;
  EXPECT_NE(F.compute(indefinite).info(), Eigen::Success);
  EXPECT_EQ(F.solve_with_workspace(B.data(), std::size_t(n), 1, ws), nullptr);
  EXPECT_FALSE(std::isfinite(F.solve(B.col(0))(0)));
}
#endif
