// test_core: the jump Laplacian of curves with interior endpoints as a low-rank update of the kept
// 0-form Laplacian (Jump_laplace_system::exclude_by_update), and the solver class that uses it.
#include "test_core_support.h"

namespace {
// u of L for per-corner offsets c, compared with u of a fresh factorization for the same excluded
// vertices: equal up to one constant on a connected mesh (the pinned vertices may differ)
double max_difference_up_to_a_constant(const SI::Mesh_tables& t, const std::vector<double>& a, const std::vector<double>& b,
                                       const std::vector<char>& excluded)
{
  double shift = 0, worst = 0;
  bool first = true;
  for(std::size_t k = 0; k < 3 * t.nf; ++k)
  {
    if(excluded[t.fv[k]]) continue;
    if(first) { shift = a[k] - b[k]; first = false; }
    worst = std::max(worst, std::abs(a[k] - b[k] - shift));
  }
  return worst;
}
} // namespace

TEST(JumpLaplace, EndpointUpdateAgreesWithAFreshFactorization)
{
  const int nv = 9;
  const Torus_with_0form_laplacian torus(16, nv);
  const SI::Mesh_tables& t = torus.tables();
  const SI::Jump_laplace_system<LA>& L0 = torus.L0;
  const std::vector<double> c = random_values(3 * t.nf, 3);
  const auto compare = [&](const std::vector<char>& excluded, const std::string& what) {
    SI::Jump_laplace_system<LA> fresh, updated(L0);
    fresh.jump_laplacian(t, torus.w, excluded);
    if(!updated.exclude_by_update(excluded)) return false;
    EXPECT_TRUE(updated.excludes(excluded)) << what;
    EXPECT_GT(updated.update_rank(), std::size_t(std::count(excluded.begin(), excluded.end(), 1))) << what;
    EXPECT_LT(max_difference_up_to_a_constant(t, updated.solve_jump_laplace(c), fresh.solve_jump_laplace(c), excluded), 1e-9)
      << what;
    return true;
  };
  // a broken meridian: its two interior endpoints
  const std::vector<double> chain =
    torus.chain({meridian_piece(torus.vs, nv, 3, 0, 4), meridian_piece(torus.vs, nv, 3, 6, nv)});
  const std::vector<char> endpoint = SI::interior_endpoints(t, chain);
  ASSERT_EQ(std::count(endpoint.begin(), endpoint.end(), 1), 2);
  EXPECT_TRUE(compare(endpoint, "broken meridian"));
  // every vertex alone: all but the pinned one (one component) are updates
  std::size_t refused = 0;
  for(std::size_t v = 0; v < t.nv; ++v)
  {
    std::vector<char> one(t.nv, 0);
    one[v] = 1;
    refused += compare(one, "vertex " + std::to_string(v)) ? 0 : 1;
  }
  EXPECT_EQ(refused, 1u);
  // five vertices at random, several times
  for(unsigned seed = 1; seed <= 5; ++seed)
  {
    std::vector<char> some(t.nv, 0);
    const std::vector<double> r = random_values(5, seed);
    for(double x : r) some[std::size_t((x + 1) / 2 * double(t.nv)) % t.nv] = 1;
    compare(some, "seed " + std::to_string(seed));   // may be refused if it hits the pinned vertex
  }
}

TEST(JumpLaplace, EndpointUpdatesKeepTheColumnsOfTheInverse)
{
  // With a factorization that offers no sparse forward solves (Eigen's LDLT), the columns of A^-1 an
  // update solves are kept for the next updates of the same factorization: a stroke kept (its
  // endpoints) costs no solve the next time, and the answer is that of a fresh factorization whether
  // the columns are kept, taken from the cache, or not kept at all. With the package's supernodal
  // factorization (sparse forward solves of the unit vectors instead) no column is kept.
  typedef SI::Eigen_LDLT_sparse_solver LDLT;
  static_assert(!SI::Has_unit_forward<LDLT>::value, "Eigen's LDLT offers no sparse forward solves");
  const int nv = 9;
  const Torus_with_0form_laplacian torus(16, nv);
  const SI::Mesh_tables& t = torus.tables();
  const std::vector<double> c = random_values(3 * t.nf, 4);
  SI::Jump_laplace_system<LDLT> L0;   // its copies share its cache
  L0.jump_laplacian(t, torus.w, std::vector<char>(t.nv, 0));
  const auto V = torus_vertex(torus.vs, nv);
  std::vector<char> first(t.nv, 0), second(t.nv, 0), both(t.nv, 0);
  first[torus.solver->vertex_index(V(3, 2))] = 1;
  second[torus.solver->vertex_index(V(10, 5))] = 1;
  for(std::size_t v = 0; v < t.nv; ++v) both[v] = first[v] | second[v];
  const auto agrees = [&](const auto& base, const std::vector<char>& excluded, std::size_t column_bytes, const std::string& what) {
    std::decay_t<decltype(base)> fresh, updated(base);
    fresh.jump_laplacian(t, torus.w, excluded);
    ASSERT_TRUE(updated.exclude_by_update(excluded, SI::jump_laplacian_max_update_rank, column_bytes)) << what;
    EXPECT_LT(max_difference_up_to_a_constant(t, updated.solve_jump_laplace(c), fresh.solve_jump_laplace(c), excluded), 1e-9)
      << what;
  };
  const std::size_t all = SI::column_cache_bytes, column = L0.size() * sizeof(double);
  agrees(L0, both, 0, "columns not kept (too large): two solves");
  EXPECT_EQ(L0.cached_columns(), 0u);
  agrees(L0, first, all, "one endpoint");
  const std::size_t one = L0.cached_columns();   // the endpoint and its neighbours
  EXPECT_GE(one, 4u);
  agrees(L0, first, all, "the same endpoint again, from the cache");
  EXPECT_EQ(L0.cached_columns(), one);   // nothing solved anew
  agrees(L0, both, all, "that endpoint and another");
  EXPECT_EQ(L0.cached_columns(), 2 * one);   // only the second endpoint's columns were solved
  // room for one endpoint's columns and one more: the latest kept, the oldest out
  agrees(L0, second, (one + 1) * column, "the second endpoint, in a smaller cache");
  EXPECT_EQ(L0.cached_columns(), one + 1);
  agrees(L0, first, (one + 1) * column, "the first endpoint again, mostly solved anew");
  EXPECT_EQ(L0.cached_columns(), one + 1);
  if(SI::Has_unit_forward<LA>::value)
  {
    agrees(torus.L0, both, all, "two endpoints, sparse forward solves");
    agrees(torus.L0, first, all, "one endpoint, sparse forward solves");
    EXPECT_EQ(torus.L0.cached_columns(), 0u);
  }
}

TEST(JumpLaplace, EndpointUpdateRefusesSplitComponentsAndLargeRanks)
{
  const int nv = 9;
  const Torus_with_0form_laplacian torus(16, nv);
  const SI::Mesh_tables& t = torus.tables();
  const SI::Jump_laplace_system<LA>& L0 = torus.L0;
  // two meridian rings out: the torus falls apart into two cylinders, each needs its pinned vertex
  std::vector<char> rings(t.nv, 0);
  const auto V = torus_vertex(torus.vs, nv);
  for(int j = 0; j < nv; ++j) rings[torus.solver->vertex_index(V(4, j))] = rings[torus.solver->vertex_index(V(11, j))] = 1;
  SI::Jump_laplace_system<LA> updated(L0);
  EXPECT_FALSE(updated.exclude_by_update(rings));
  EXPECT_FALSE(updated.excludes(rings));
  EXPECT_EQ(updated.update_rank(), 0u);
  SI::Jump_laplace_system<LA> fresh;
  fresh.jump_laplacian(t, torus.w, rings);
  EXPECT_EQ(fresh.size(), t.nv - 2 * nv - 2);   // two pinned vertices
  // one ring out: still connected, an update of rank 3 nv (the ring and its two neighbouring rings)
  std::vector<char> ring(t.nv, 0);
  for(int j = 0; j < nv; ++j) ring[torus.solver->vertex_index(V(7, j))] = 1;
  SI::Jump_laplace_system<LA> one(L0), capped(L0);
  const bool pinned_on_ring = !one.exclude_by_update(ring);
  if(!pinned_on_ring) EXPECT_EQ(one.update_rank(), std::size_t(3 * nv));
  EXPECT_FALSE(capped.exclude_by_update(ring, 3 * nv - 1));   // above the largest rank asked for
}

TEST(Solver, BrokenStrokesUseTheKeptFactorizationWithAnUpdate)
{
  // a sketching session on a torus: broken strokes one after the other; after the first, each uses the
  // kept 0-form Laplacian with a low-rank update for its endpoints, and gives the labels and G of the
  // free function (which factorizes its jump Laplacian anew)
  Mesh m;
  const int nu = 24, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  const auto V = torus_vertex(vs, nv);
  Solver solver(m);
  std::vector<std::vector<std::vector<Vertex>>> strokes;
  for(int k = 0; k < 4; ++k)
  {
    std::vector<Vertex> square = rect_loop(V, 2 + 5 * k, 2, 6 + 5 * k, 6);
    square.erase(square.begin(), square.begin() + 1 + k);   // a gap of k + 1 edges
    strokes.push_back({square, meridian_piece(vs, nv, 1 + 5 * k, 0, 3 + k % 2), meridian_piece(vs, nv, 1 + 5 * k, 6, nv)});
  }
  std::size_t warm_starts = 0;
  for(int keep = 1; keep >= 0; --keep)
    for(std::size_t k = 0; k < strokes.size(); ++k)
    {
      auto chain = get(CGAL::dynamic_edge_property_t<int>(), m);
      for(auto e : edges(m)) put(chain, e, 0);
      for(const auto& p : strokes[k]) ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
      Labels_and_G by_solver, by_function;
      ASSERT_TRUE(by_solver.solve(solver, chain, SWN::parameters::keep_hodge_factorization(keep == 1)));
      const SWN::Solve_report rep = solver.report();
      ASSERT_TRUE(by_function.solve(m, chain));
      SCOPED_TRACE("stroke " + std::to_string(k));
      by_solver.expect_equal(by_function);
      int nG = 0;
      for(const auto& g : by_solver.G) nG += g.second != 0;
      EXPECT_GE(nG, nv) << "stroke " << k;   // at least the completed meridian
      EXPECT_EQ(rep.interior_endpoints, 4u);
      const bool expect_update = keep == 1 && k > 0;
      EXPECT_EQ(rep.jump_laplacian_reused, expect_update) << "stroke " << k;
      // the residual starts from the last answer (another stroke on the same mesh), never on the first solve
      if(keep == 1 && k == 0) EXPECT_FALSE(rep.residual_warm_started);
      warm_starts += rep.residual_warm_started;
      EXPECT_EQ(rep.jump_laplacian_update_rank > 0, expect_update) << "stroke " << k;
    }
#ifdef CGAL_SWN_USE_LEMON
  EXPECT_GE(warm_starts, 5u);   // of 7 solves after the first
#endif
}
