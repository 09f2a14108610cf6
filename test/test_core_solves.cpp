// test_core: the linear solves (JumpLaplace, NestedDissection).
#include "test_core_support.h"

#include <map>
#include <utility>

// =============================================================================================
// JumpLaplace (jump_laplace.h)
// =============================================================================================

TEST(JumpLaplace, ChainBoundaryAndInteriorEndpoints)
{
  // a path between interior vertices traversed twice, a path from the border into the mesh and a
  // closed loop: the boundary counts arrivals minus departures, and only vertices off the border
  // with a boundary are interior endpoints
  const Grid_tables g(8, 2, 0.);
  const SI::Mesh_tables& t = g.tables();
  const std::vector<Vertex> inner = {g.V(2, 4), g.V(3, 4), g.V(4, 4), g.V(5, 4), g.V(6, 4)},
                            from_border = {g.V(0, 2), g.V(1, 2), g.V(2, 2), g.V(3, 2)};
  const std::vector<double> chain = g.chain({inner, inner, from_border, square_loop(g.vs, g.n, 5, 5, 7, 7)});
  std::map<Vertex, long> expected = {{g.V(2, 4), -2}, {g.V(6, 4), 2}, {g.V(0, 2), -1}, {g.V(3, 2), 1}};
  const std::vector<double> d = SI::chain_boundary(t, chain);
  std::vector<int> integer_chain(chain.begin(), chain.end());
  const std::vector<long> dl = SI::chain_boundary<long>(t, integer_chain);
  const std::vector<char> endpoint = SI::interior_endpoints(t, chain);
  for(Vertex v : vertices(g.mesh))
  {
    const std::size_t i = g.solver->vertex_index(v);
    const long x = expected.count(v) ? expected[v] : 0;
    EXPECT_EQ(d[i], double(x)) << "vertex " << v;
    EXPECT_EQ(dl[i], x) << "vertex " << v;
    EXPECT_EQ(endpoint[i] != 0, x != 0 && v != g.V(0, 2)) << "vertex " << v;
  }
}

TEST(JumpLaplace, ReducedCoordinatesRealiseTheJumps)
{
  const Grid_tables g(12, 3);
  const SI::Mesh_tables& t = g.tables();
  // an open path (two interior endpoints) plus a closed loop crossing it
  std::vector<Vertex> path, loop = square_loop(g.vs, g.n, 2, 2, 8, 7);
  for(int i = 1; i <= 10; ++i) path.push_back(g.V(i, 5));
  const std::vector<double> chain = g.chain({path, loop});
  const std::vector<char> endpoint = SI::interior_endpoints(t, chain);
  EXPECT_EQ(std::count(endpoint.begin(), endpoint.end(), 1), 2);
  const std::vector<double> jumps = SI::arc_jumps_from_chain(t, chain);
  const std::vector<double> c = SI::reduced_coordinates(t, jumps, endpoint);
  for(std::size_t a = 0; a < t.arcs.size(); ++a)
    for(int k = 0; k < 2; ++k)
    {
      const std::size_t v = t.ev[2 * t.arcs[a].edge + k];
      if(endpoint[v]) continue;
      EXPECT_NEAR(SI::corner_jump_at(t, c, a, k), chain[t.arcs[a].edge], 1e-14);
    }
  // off the curves, where no jump is measured, every corner keeps c = 0; the defect is |dGamma|: 1 at
  // the path's two ends, 0 elsewhere (the loop's crossing with the path included)
  std::vector<char> on_curve(t.nv, 0);
  for(std::size_t e = 0; e < t.ne; ++e)
    if(chain[e] != 0) on_curve[t.ev[2 * e]] = on_curve[t.ev[2 * e + 1]] = 1;
  std::size_t off = 0;
  for(std::size_t k = 0; k < 3 * t.nf; ++k)
    if(!on_curve[t.fv[k]]) { ++off; EXPECT_EQ(c[k], 0.) << "corner " << k; }
  EXPECT_GT(off, t.nf);
  std::vector<double> defect;
  const std::vector<double> c_all = SI::reduced_coordinates(t, jumps, std::vector<char>(t.nv, 0), &defect);
  ASSERT_EQ(defect.size(), t.nv);
  for(std::size_t v = 0; v < t.nv; ++v) EXPECT_NEAR(defect[v], endpoint[v] ? 1. : 0., 1e-14) << "vertex " << v;
  for(std::size_t k = 0; k < 3 * t.nf; ++k)
    if(!endpoint[t.fv[k]]) EXPECT_EQ(c_all[k], c[k]) << "corner " << k;
}

TEST(JumpLaplace, ClosedLoopGivesTwoValuedFunctionAndExactJumps)
{
  const Grid_tables g(16, 5);
  const SI::Mesh_tables& t = g.tables();
  const std::vector<double> chain = g.chain({square_loop(g.vs, g.n, 4, 3, 11, 12)});
  const std::vector<char> endpoint = SI::interior_endpoints(t, chain);
  std::vector<double> w;
  SI::cotan_weights(t, w);
  SI::Jump_laplace_system<LA> L;
  L.jump_laplacian(t, w, endpoint);
  EXPECT_EQ(L.size(), t.nv - 1);   // one pinned vertex
  const std::vector<double> u = L.solve_jump_laplace(SI::reduced_coordinates(t, SI::arc_jumps_from_chain(t, chain), endpoint));
  double lo = 1e9, hi = -1e9;
  for(double x : u) { lo = std::min(lo, x); hi = std::max(hi, x); }
  EXPECT_NEAR(hi - lo, 1., 1e-9);
  for(std::size_t a = 0; a < t.arcs.size(); ++a)
    for(int k = 0; k < 2; ++k) EXPECT_NEAR(SI::corner_jump_at(t, u, a, k), chain[t.arcs[a].edge], 1e-9);
  // omega = D u vanishes for a two-valued u
  for(double o : SI::darboux_derivative(t, u, endpoint)) EXPECT_NEAR(o, 0., 1e-9);
}

TEST(JumpLaplace, SolutionIsLinearInTheJumpsAndConstantWithoutThem)
{
  // one factorization on a torus (nothing excluded): reduced coordinates without jumps (a vertex
  // function) give a constant u, and u is linear in the prescribed jumps
  const Torus_tables torus(16, 9);
  const SI::Mesh_tables& t = torus.tables();
  const std::vector<char> none(t.nv, 0);
  SI::Jump_laplace_system<LA> L;
  L.jump_laplacian(t, torus.w, none);
  const std::vector<double> phi = random_values(t.nv, 5);
  std::vector<double> c(3 * t.nf);
  for(std::size_t k = 0; k < c.size(); ++k) c[k] = phi[t.fv[k]];
  const std::vector<double> u = L.solve_jump_laplace(c);
  EXPECT_LT(*std::max_element(u.begin(), u.end()) - *std::min_element(u.begin(), u.end()), 1e-9);
  EXPECT_LT(max_abs(L.solve_jump_laplace(std::vector<double>(3 * t.nf, 0.))), 1e-12);

  const std::vector<double> loop = torus.chain({rect_loop(torus_vertex(torus.vs, 9), 3, 2, 7, 5)});
  const std::vector<double> meridian = torus.chain({meridian_piece(torus.vs, 9, 11, 0, 9)});
  std::vector<double> both(t.ne);
  for(std::size_t e = 0; e < t.ne; ++e) both[e] = loop[e] - 2 * meridian[e];
  auto solve = [&](const std::vector<double>& chain) {
    return L.solve_jump_laplace(SI::reduced_coordinates(t, SI::arc_jumps_from_chain(t, chain), none));
  };
  const std::vector<double> u1 = solve(loop), u2 = solve(meridian), u12 = solve(both);
  EXPECT_GT(max_abs(u2), 0.1);
  for(std::size_t k = 0; k < u12.size(); ++k) EXPECT_NEAR(u12[k], u1[k] - 2 * u2[k], 1e-9) << "corner " << k;
}

namespace {
// sparse solver traits without an Eigen solver() accessor: solve_columns() then solves column by column
struct Opaque_solver_traits
{
  typedef LA::Matrix Matrix;
  typedef LA::Vector Vector;
  typedef LA::NT NT;
  bool factor(const Matrix& A, NT& D) { return la.factor(A, D); }
  bool linear_solver(const Vector& B, Vector& X) { return la.linear_solver(B, X); }
  LA la;
};
} // namespace

TEST(JumpLaplace, ManyColumnSolveAgreesWithColumnByColumn)
{
  // more right-hand sides than one block of the many-column solve, the last block partial
  const Torus_tables torus(16, 9);
  const SI::Mesh_tables& t = torus.tables();
  const std::vector<double>& w = torus.w;
  const std::vector<char> none(t.nv, 0);
  SI::Jump_laplace_system<LA> A;
  SI::Jump_laplace_system<Opaque_solver_traits> B;
  A.jump_laplacian(t, w, none);
  B.jump_laplacian(t, w, none);
  const std::size_t k = SI::vertex_laplace_block + 3;
  const auto rhs = [&](std::size_t j, std::vector<double>& b) {   // zero sum: in the range of the Laplacian
    b[(7 * j + 1) % t.nv] += 1;
    b[(11 * j + 40) % t.nv] -= 1;
  };
  const std::vector<double> xa = A.solve_vertex_laplace(k, rhs), xb = B.solve_vertex_laplace(k, rhs);
  ASSERT_EQ(xa.size(), k * t.nv);
  ASSERT_EQ(xb.size(), k * t.nv);
  double largest = 0;
  for(std::size_t i = 0; i < k * t.nv; ++i)
  {
    EXPECT_NEAR(xa[i], xb[i], 1e-10);
    largest = std::max(largest, std::abs(xa[i]));
  }
  EXPECT_GT(largest, 0.01);
  // every column solves L x_j = b_j at every vertex (the pinned one too, as b_j sums to zero)
  for(std::size_t j = 0; j < k; ++j)
  {
    std::vector<double> Lx(t.nv, 0.), b(t.nv, 0.);
    rhs(j, b);
    const double* x = xa.data() + j * t.nv;
    for(std::size_t f = 0; f < t.nf; ++f)
      for(std::size_t c = 0; c < 3; ++c)
      {
        const std::size_t side = 3 * f + c, a = t.tail(side), h = t.head(side);
        Lx[a] += w[side] * (x[a] - x[h]);
        Lx[h] += w[side] * (x[h] - x[a]);
      }
    for(std::size_t v = 0; v < t.nv; ++v) EXPECT_NEAR(Lx[v], b[v], 1e-9) << "column " << j << ", vertex " << v;
  }
}

namespace {
// Runs `owner` on one thread and share.help() on another, the helper started before the owner
// (helper_first) or after it: the two orders in which the Hodge step's threads may meet.
void run_with_a_helper(SI::Shared_work& share, bool helper_first, const std::function<void()>& owner)
{
  std::thread helper;
  if(helper_first) helper = std::thread([&] { share.help(); });   // waits for the work to be published
  std::thread owning(owner);
  if(!helper_first) helper = std::thread([&] { share.help(); });
  owning.join();
  helper.join();
}
} // namespace

TEST(JumpLaplace, ManyColumnSolveSharedWithAHelperThreadGivesTheSameColumns)
{
  // the Hodge step's many-column solve, its blocks shared with a thread that calls help() (as the
  // solving thread does once it has solved for u), against the same solve alone: the same blocks
  // go through the same solves, so the columns agree exactly whichever thread solved them
  const Torus_tables torus(24, 13);
  const SI::Mesh_tables& t = torus.tables();
  SI::Jump_laplace_system<LA> A;
  A.jump_laplacian(t, torus.w, std::vector<char>(t.nv, 0));
  const std::size_t k = 4 * SI::vertex_laplace_block + 5;
  const auto rhs = [&](std::size_t j, std::vector<double>& b) {
    b[(13 * j + 3) % t.nv] += 1;
    b[(29 * j + 70) % t.nv] -= 1;
  };
  const std::vector<double> alone = A.solve_vertex_laplace(k, rhs);
  for(int helper_first = 0; helper_first < 2; ++helper_first)
  {
    SI::Shared_work share;
    std::vector<double> shared;
    run_with_a_helper(share, helper_first == 1, [&] {
      shared = A.solve_vertex_laplace(k, rhs, &share);
      share.finish();
    });
    ASSERT_EQ(shared.size(), alone.size());
    for(std::size_t i = 0; i < alone.size(); ++i) ASSERT_EQ(shared[i], alone[i]) << "entry " << i;
  }
}

TEST(JumpLaplace, SharedWorkIsDoneOnceAndHelpersNeverWaitForever)
{
  // every piece done once, and all of them when run() returns (the owner then reads the results),
  // whether the helper joins before the work is published or after; a helper that comes after
  // finish() returns at once
  for(int helper_first = 0; helper_first < 2; ++helper_first)
  {
    SI::Shared_work share;
    const std::size_t pieces = 2000;
    std::vector<int> done(pieces, 0);
    std::atomic<std::size_t> next(0);
    const std::function<void()> work = [&] {
      for(std::size_t p; (p = next.fetch_add(1)) < pieces;) ++done[p];
    };
    std::size_t done_at_return = 0;
    run_with_a_helper(share, helper_first == 1, [&] {
      share.run(work);
      done_at_return = std::size_t(std::count(done.begin(), done.end(), 1));
      share.finish();
    });
    EXPECT_EQ(done_at_return, pieces);
    for(std::size_t p = 0; p < pieces; ++p) ASSERT_EQ(done[p], 1) << "piece " << p;
  }
  SI::Shared_work finished;
  finished.finish();
  finished.help();   // returns: nothing will be published
  SI::Shared_work never_published;
  std::thread owner([&] { never_published.finish(); });   // as the Hodge thread does when it needs no basis
  never_published.help();
  owner.join();
}

// =============================================================================================
// NestedDissection (nested_dissection.h)
// =============================================================================================

namespace {
// entries of the Cholesky factor of (graph Laplacian + I) eliminated in `order` (nullptr: by node)
long cholesky_fill(std::size_t n, const std::vector<std::size_t>& first, const std::vector<std::size_t>& adjacent,
                   const std::vector<std::size_t>* order, bool amd = false)
{
  std::vector<int> pos(n);
  for(std::size_t k = 0; k < n; ++k) pos[order ? (*order)[k] : k] = int(k);
  std::vector<Eigen::Triplet<double>> T;
  for(std::size_t v = 0; v < n; ++v)
  {
    T.emplace_back(pos[v], pos[v], 1. + double(first[v + 1] - first[v]));
    for(std::size_t k = first[v]; k < first[v + 1]; ++k) T.emplace_back(pos[v], pos[adjacent[k]], -1.);
  }
  Eigen::SparseMatrix<double> A(static_cast<int>(n), static_cast<int>(n));
  A.setFromTriplets(T.begin(), T.end());
  if(amd)
  {
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> llt(A);
    Eigen::SparseMatrix<double> L = llt.matrixL();
    return L.nonZeros();
  }
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> llt(A);
  Eigen::SparseMatrix<double> L = llt.matrixL();
  return L.nonZeros();
}

} // namespace

// internal::assembled_matrix(): a traits matrix that wraps an Eigen matrix is filled through it, any other
// by add_coef(); both sum duplicate entries, and the entry list is emptied with its memory
TEST(JumpLaplace, AssembledMatricesSumDuplicateEntriesWithEitherFill)
{
  struct Map_matrix   // a traits matrix that only has add_coef()
  {
    std::map<std::pair<int, int>, double> a;
    Map_matrix(int, int) {}
    void add_coef(int i, int j, double v) { a[{i, j}] += v; }
  };
  const std::vector<SI::Matrix_entry> list = {{0, 0, 1.}, {1, 0, 2.}, {0, 0, 3.}, {2, 2, -1.}, {1, 0, 0.5}, {0, 2, 7.}};
  std::vector<SI::Matrix_entry> by_add = list, by_eigen = list;
  const auto M = SI::assembled_matrix<Map_matrix>(3, by_add);
  const auto E = SI::assembled_matrix<CGAL::Eigen_sparse_matrix<double>>(3, by_eigen);
  EXPECT_TRUE(by_add.empty() && by_eigen.empty());
  EXPECT_EQ(by_add.capacity() + by_eigen.capacity(), 0u);
  EXPECT_EQ(M->a.size(), 4u);
  EXPECT_EQ(M->a.at({0, 0}), 4.);
  EXPECT_EQ(M->a.at({1, 0}), 2.5);
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      EXPECT_EQ(E->get_coef(i, j), M->a.count({i, j}) ? M->a.at({i, j}) : 0.) << i << ", " << j;
}

TEST(NestedDissection, OrdersAreFillReducingPermutations)
{
  // the nested-dissection orders of both Laplacians' graphs: permutations of the vertices and of the faces whose
  // Cholesky fill is a fraction of the mesh's own numbering's and near AMD's (on a 150 x 150 grid:
  // 1.1-1.3x AMD's; the nested dissection pays above 150k unknowns, where it is used)
  const Grid_tables g(150);
  const SI::Mesh_tables& t = g.tables();
  for(int faces = 0; faces < 2; ++faces)
  {
    const std::size_t n = faces ? t.nf : t.nv;
    // below nested_dissection_unknowns the mesh's numbering is kept (and CHOLMOD orders by AMD)
    EXPECT_TRUE((faces ? SI::face_elimination_order(t) : SI::vertex_elimination_order(t)).empty());
    std::vector<double> xyz = t.points;
    if(faces)
    {
      xyz.assign(3 * t.nf, 0.);
      for(std::size_t c = 0; c < 3 * t.nf; ++c)
        for(int k = 0; k < 3; ++k) xyz[3 * (c / 3) + k] += t.points[3 * t.fv[c] + k] / 3;
    }
    // the graph: mesh edges, or faces across interior edges
    std::vector<std::vector<std::size_t>> nb(n);
    for(std::size_t e = 0; e < t.ne; ++e)
    {
      if(!faces) { nb[t.ev[2 * e]].push_back(t.ev[2 * e + 1]); nb[t.ev[2 * e + 1]].push_back(t.ev[2 * e]); continue; }
      for(std::size_t i = t.edge_side_begin[e]; i < t.edge_side_begin[e + 1]; ++i)
        for(std::size_t j = t.edge_side_begin[e]; j < t.edge_side_begin[e + 1]; ++j)
          if(i != j) nb[t.edge_sides[i] / 3].push_back(t.edge_sides[j] / 3);
    }
    std::vector<std::size_t> first(1, 0), adjacent;
    for(const auto& a : nb) { adjacent.insert(adjacent.end(), a.begin(), a.end()); first.push_back(adjacent.size()); }
    const std::vector<std::size_t> order = SI::nested_dissection_order(first, adjacent, xyz);
    expect_permutation(order, n);
    if(::testing::Test::HasFatalFailure()) return;
    const long nd = cholesky_fill(n, first, adjacent, &order);
    const long own = cholesky_fill(n, first, adjacent, nullptr);
    const long amd = cholesky_fill(n, first, adjacent, nullptr, true);
    EXPECT_LT(3 * nd, own) << (faces ? "faces" : "vertices");
    EXPECT_LT(double(nd), 1.5 * double(amd)) << (faces ? "faces" : "vertices");
    std::cout << (faces ? "faces" : "vertices") << ": fill " << nd << " (mesh order " << own << ", AMD " << amd << ")\n";
  }
}
