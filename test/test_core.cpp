// Stage-by-stage tests of the numerical core (flat tables), of the LP traits and of the solver class.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#include <CGAL/Surface_winding_numbers/internal/pipeline.h>

#include <Eigen/SparseCholesky>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <cmath>
#include <limits>
#include <string>
#include <map>
#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SI = CGAL::Surface_winding_numbers::internal;
typedef SI::Default_sparse_solver LA;

// n x n grid on [0,1]^2 (a disk), diagonals chosen at random
std::vector<Vertex> grid_disk(Mesh& m, int n, unsigned seed = 1, double jitter = 0.2)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-jitter / n, jitter / n);
  std::vector<Vertex> vs;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      vs.push_back(m.add_vertex(K::Point_3(double(i) / n + (border ? 0 : U(rng)), double(j) / n + (border ? 0 : U(rng)), 0)));
    }
  auto V = [&](int i, int j) { return vs[j * (n + 1) + i]; };
  std::bernoulli_distribution coin(0.5);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      if(coin(rng)) { m.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1)); m.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1)); }
      else { m.add_face(V(i, j), V(i + 1, j), V(i, j + 1)); m.add_face(V(i + 1, j), V(i + 1, j + 1), V(i, j + 1)); }
  return vs;
}

std::vector<Vertex> torus_mesh(Mesh& m, int nu, int nv)
{
  const double pi = 3.14159265358979323846;
  std::vector<Vertex> vs;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
      vs.push_back(m.add_vertex(K::Point_3((1 + 0.4 * std::cos(b)) * std::cos(a), (1 + 0.4 * std::cos(b)) * std::sin(a), 0.4 * std::sin(b))));
    }
  auto V = [&](int i, int j) { return vs[((i % nu + nu) % nu) * nv + (j % nv + nv) % nv]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) { m.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1)); m.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1)); }
  return vs;
}

// the chain of a vertex polyline as a vector indexed like the solver's tables
std::vector<double> table_chain(const Mesh& m, const SWN::Surface_winding_numbers_solver<Mesh>& s,
                                const std::vector<std::vector<Vertex>>& polylines)
{
  auto map = get(CGAL::dynamic_edge_property_t<int>(), m);
  for(auto e : edges(m)) put(map, e, 0);
  for(const auto& p : polylines) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, map));
  std::vector<double> c(num_edges(m), 0.);
  for(auto e : edges(m)) c[s.edge_index(e)] = get(map, e);
  return c;
}

std::vector<Vertex> square_loop(const std::vector<Vertex>& vs, int n, int i0, int j0, int i1, int j1)
{
  auto V = [&](int i, int j) { return vs[j * (n + 1) + i]; };
  std::vector<Vertex> loop;
  for(int i = i0; i < i1; ++i) loop.push_back(V(i, j0));
  for(int j = j0; j < j1; ++j) loop.push_back(V(i1, j));
  for(int i = i1; i > i0; --i) loop.push_back(V(i, j1));
  for(int j = j1; j >= j0; --j) loop.push_back(V(i0, j));
  return loop;
}
} // namespace

TEST(MeshTables, GridIsADiskWithConsistentArcs)
{
  Mesh m;
  grid_disk(m, 6);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  ASSERT_TRUE(s.is_valid()) << s.report().error;
  const SI::Mesh_tables& t = s.tables();
  EXPECT_EQ(t.nf, 72u);
  EXPECT_EQ(t.n_components, 1u);
  EXPECT_EQ(t.component_euler_characteristic[0], 1);
  EXPECT_EQ(t.component_border_edges[0], 24u);
  EXPECT_TRUE(t.all_components_disks_or_spheres());
  EXPECT_EQ(t.arcs.size() + 24, t.ne);
  for(const SI::Arc& a : t.arcs)
  {
    EXPECT_EQ(t.fs[a.left_side], 1);
    EXPECT_EQ(t.fs[a.right_side], -1);
    EXPECT_EQ(t.tail(a.left_side), t.head(a.right_side));
    EXPECT_EQ(t.head(a.left_side), t.tail(a.right_side));
  }
}

TEST(MeshTables, TorusAndTwoComponents)
{
  Mesh m;
  torus_mesh(m, 8, 6);
  Mesh::Vertex_index a = m.add_vertex(K::Point_3(5, 0, 0)), b = m.add_vertex(K::Point_3(6, 0, 0)),
                     c = m.add_vertex(K::Point_3(5, 1, 0));
  m.add_face(a, b, c);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  ASSERT_TRUE(s.is_valid());
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 2u);
  EXPECT_EQ(t.component_euler_characteristic[0], 0);
  EXPECT_EQ(t.component_euler_characteristic[1], 1);
  EXPECT_FALSE(t.all_components_disks_or_spheres());
  EXPECT_EQ(s.report().genus, 1);
  EXPECT_EQ(s.report().border_loops, 1u);
}

namespace {
// a copy of m with the same vertices (same indices) and its faces added in a shuffled order
Mesh scrambled_copy(const Mesh& m, unsigned seed)
{
  Mesh s;
  for(Vertex v : vertices(m)) s.add_vertex(m.point(v));
  std::vector<std::array<Vertex, 3>> tris;
  for(auto f : faces(m))
  {
    std::array<Vertex, 3> t;
    int k = 0;
    for(Vertex v : vertices_around_face(halfedge(f, m), m)) t[k++] = v;
    tris.push_back(t);
  }
  std::mt19937 rng(seed);
  std::shuffle(tris.begin(), tris.end(), rng);
  for(const auto& t : tris) s.add_face(t[0], t[1], t[2]);
  return s;
}

// marks slot i of a numbering of size n as used; false if it is out of range or used twice
bool take_slot(std::vector<char>& seen, std::size_t i)
{
  if(i >= seen.size() || seen[i]) return false;
  seen[i] = 1;
  return true;
}
} // namespace

TEST(MeshTables, LocalityNumberingIsABijectionAndKeepsTheMesh)
{
  // faces added in a scrambled order, plus an isolated vertex: the solver's tables are renumbered
  // (locality_order.h) and must describe the same mesh through the solver's index maps
  Mesh m;
  torus_mesh(m, 48, 32);
  Mesh shuffled = scrambled_copy(m, 7);
  const Vertex lonely = shuffled.add_vertex(K::Point_3(9, 9, 9));
  SWN::Surface_winding_numbers_solver<Mesh> s(shuffled);
  ASSERT_TRUE(s.is_valid()) << s.report().error;
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.nv, num_vertices(shuffled));
  ASSERT_EQ(t.ne, num_edges(shuffled));
  ASSERT_EQ(t.nf, num_faces(shuffled));
  std::vector<char> seen_v(t.nv, 0), seen_e(t.ne, 0), seen_f(t.nf, 0);
  std::size_t moved = 0;
  for(Vertex v : vertices(shuffled))
  {
    const std::size_t i = s.vertex_index(v);
    ASSERT_TRUE(take_slot(seen_v, i));
    EXPECT_EQ(t.input_vertex_index(i), std::size_t(v));
    EXPECT_EQ(t.point(i)[0], shuffled.point(v).x());
    EXPECT_EQ(t.point(i)[2], shuffled.point(v).z());
    if(i != std::size_t(v)) ++moved;
  }
  EXPECT_EQ(s.vertex_index(lonely), t.nv - 1);   // used by no face: last
  for(auto e : edges(shuffled))
  {
    const std::size_t i = s.edge_index(e);
    ASSERT_TRUE(take_slot(seen_e, i));
    EXPECT_EQ(t.input_edge_index(i), std::size_t(e));
    EXPECT_EQ(t.ev[2 * i], s.vertex_index(source(halfedge(e, shuffled), shuffled)));   // reference direction kept
    EXPECT_EQ(t.ev[2 * i + 1], s.vertex_index(target(halfedge(e, shuffled), shuffled)));
  }
  for(auto f : faces(shuffled))
  {
    const std::size_t i = s.face_index(f);
    ASSERT_TRUE(take_slot(seen_f, i));
    EXPECT_EQ(t.input_face_index(i), std::size_t(f));
    auto h = halfedge(f, shuffled);
    for(std::size_t k = 0; k < 3; ++k, h = next(h, shuffled))   // corner order kept
    {
      EXPECT_EQ(t.fv[3 * i + k], s.vertex_index(source(h, shuffled)));
      EXPECT_EQ(t.fe[3 * i + k], s.edge_index(edge(h, shuffled)));
    }
  }
  EXPECT_GT(moved, t.nv / 2);   // the scrambled input was really renumbered
  EXPECT_EQ(s.report().genus, 1);
  EXPECT_EQ(t.arcs.size(), t.ne);
}

TEST(MeshTables, CoherentNumberingIsKeptAndScatteredOneReplaced)
{
  // a grid written row by row is numbered coherently: the tables keep the mesh's order; the same
  // grid with its faces shuffled is scattered and gets renumbered
  Mesh m;
  grid_disk(m, 40);
  SWN::Surface_winding_numbers_solver<Mesh> coherent(m);
  ASSERT_TRUE(coherent.is_valid());
  EXPECT_TRUE(coherent.tables().input_face.empty());
  for(auto f : faces(m)) EXPECT_EQ(coherent.face_index(f), std::size_t(f));
  for(auto v : vertices(m)) EXPECT_EQ(coherent.vertex_index(v), std::size_t(v));
  EXPECT_FALSE(SI::numbering_is_scattered(coherent.tables()));
  Mesh s = scrambled_copy(m, 5);
  SWN::Surface_winding_numbers_solver<Mesh> scattered(s);
  ASSERT_TRUE(scattered.is_valid());
  EXPECT_EQ(scattered.tables().input_face.size(), num_faces(s));
  EXPECT_FALSE(SI::numbering_is_scattered(scattered.tables()));   // renumbered: coherent now
  std::size_t moved = 0;
  for(auto f : faces(s)) moved += scattered.face_index(f) != std::size_t(f) ? 1 : 0;
  EXPECT_GT(moved, num_faces(s) / 2);
}

TEST(MeshTables, ErrorsNameElementsInTheInputNumbering)
{
  // the same scrambled grid with one face made degenerate, then one vertex made non-finite: the
  // messages give the mesh's own indices, not the renumbered ones
  for(int pass = 0; pass < 2; ++pass)
  {
    Mesh m;
    grid_disk(m, 40, 3, 0.);
    Mesh s = scrambled_copy(m, 11);
    std::string expected;
    if(pass == 0)
    {
      // flatten face 57 (its third corner onto the middle of its first side); neighbours of that
      // corner may flatten too: the first degenerate face in the mesh's order is reported
      auto h = halfedge(Mesh::Face_index(57), s);
      s.point(target(next(h, s), s)) = CGAL::midpoint(s.point(source(h, s)), s.point(target(h, s)));
      std::size_t first = num_faces(s);
      for(auto f : faces(s))
      {
        auto g = halfedge(f, s);
        if(CGAL::collinear(s.point(source(g, s)), s.point(target(g, s)), s.point(target(next(g, s), s))))
          first = std::min(first, std::size_t(f));
      }
      ASSERT_LE(first, 57u);
      expected = "face " + std::to_string(first) + " has zero area";
    }
    else
    {
      s.point(Vertex(83)) = K::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
      expected = "vertex 83 has a non-finite coordinate";
    }
    SWN::Surface_winding_numbers_solver<Mesh> solver(s);
    EXPECT_FALSE(solver.is_valid());
    EXPECT_NE(solver.report().error.find(expected), std::string::npos) << solver.report().error;
  }
}

TEST(MeshTables, ChainErrorsNameEdgesInTheInputNumbering)
{
  // a chain on two border edges of a renumbered (scrambled) grid: the message names the one that
  // comes first in edges(tm), with its own vertex indices
  Mesh m;
  grid_disk(m, 40, 3, 0.);
  Mesh s = scrambled_copy(m, 13);
  SWN::Surface_winding_numbers_solver<Mesh> solver(s);
  ASSERT_TRUE(solver.is_valid());
  ASSERT_FALSE(solver.tables().input_edge.empty());
  auto chain = get(CGAL::dynamic_edge_property_t<int>(), s);
  std::vector<Mesh::Edge_index> border;
  for(auto e : edges(s))
  {
    put(chain, e, 0);
    if(is_border(e, s)) border.push_back(e);
  }
  // two border edges whose order in the solver's tables is the reverse of their order in edges(tm)
  std::size_t j = 1;
  while(j < border.size() && solver.edge_index(border[j]) > solver.edge_index(border[0])) ++j;
  ASSERT_LT(j, border.size());
  const Mesh::Edge_index first = border[0], later = border[j];
  put(chain, later, 1);
  put(chain, first, 1);
  auto labels = get(CGAL::dynamic_face_property_t<int>(), s);
  EXPECT_FALSE(solver.solve(chain, labels));
  const auto h = halfedge(first, s);
  const std::string expected = "edge " + std::to_string(std::size_t(first)) + " (vertices " +
                               std::to_string(std::size_t(source(h, s))) + ", " +
                               std::to_string(std::size_t(target(h, s))) + ") is on the border";
  EXPECT_NE(solver.report().error.find(expected), std::string::npos) << solver.report().error;
}

TEST(CotanWeights, ValuesClampAndScaleInvariance)
{
  SI::Mesh_tables t;
  t.nv = 3; t.nf = 1; t.ne = 3;
  const double h = std::sqrt(3.) / 2;
  t.points = {0, 0, 0, 1, 0, 0, 0.5, h, 0};
  t.fv = {0, 1, 2};
  t.fe = {0, 1, 2};
  t.ev = {0, 1, 1, 2, 2, 0};
  SI::finalize_mesh_tables(t);
  std::vector<double> w;
  EXPECT_EQ(SI::cotan_weights(t, w), 0u);
  for(double x : w) EXPECT_NEAR(x, 0.5 / std::sqrt(3.), 1e-14);   // cot 60 / 2
  for(double& x : t.points) x *= 1e8;
  std::vector<double> w2;
  SI::cotan_weights(t, w2);
  for(int k = 0; k < 3; ++k) EXPECT_NEAR(w2[k], w[k], 1e-14);
  // right angle at vertex 0: the side opposite gets cot 90 / 2 = 0 -> clamped
  t.points = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  EXPECT_EQ(SI::cotan_weights(t, w), 1u);
  EXPECT_DOUBLE_EQ(w[1], SI::min_cotan_weight);
  EXPECT_NEAR(w[0], 0.5, 1e-14);
}

TEST(CotanWeights, DegenerateAndNonFiniteInputAreRejected)
{
  SI::Mesh_tables t;
  t.nv = 3; t.nf = 1; t.ne = 3;
  t.points = {0, 0, 0, 1, 0, 0, 2, 0, 0};   // collinear
  t.fv = {0, 1, 2};
  t.fe = {0, 1, 2};
  t.ev = {0, 1, 1, 2, 2, 0};
  SI::finalize_mesh_tables(t);
  EXPECT_THROW(SI::check_geometry(t), SWN::Invalid_input);
  t.points = {0, 0, 0, 1, 0, 0, 0, std::nan(""), 0};
  EXPECT_THROW(SI::check_geometry(t), SWN::Invalid_input);
}

TEST(JumpLaplace, ReducedCoordinatesRealiseTheJumps)
{
  Mesh m;
  const int n = 12;
  auto vs = grid_disk(m, n, 3);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  const SI::Mesh_tables& t = s.tables();
  // an open path (two interior endpoints) plus a closed loop crossing it
  std::vector<Vertex> path, loop = square_loop(vs, n, 2, 2, 8, 7);
  for(int i = 1; i <= 10; ++i) path.push_back(vs[5 * (n + 1) + i]);
  const std::vector<double> chain = table_chain(m, s, {path, loop});
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
}

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

TEST(NestedDissection, OrdersAreFillReducingPermutations)
{
  // the nested-dissection orders of both Laplacians' graphs: permutations of the vertices and of the faces whose
  // Cholesky fill is a fraction of the mesh's own numbering's and near AMD's (on a 150 x 150 grid:
  // 1.1-1.3x AMD's; the nested dissection pays above 150k unknowns, where it is used)
  Mesh m;
  grid_disk(m, 150);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  const SI::Mesh_tables& t = s.tables();
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
    std::vector<std::size_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted.size(), n);
    for(std::size_t k = 0; k < n; ++k) ASSERT_EQ(sorted[k], k);
    const long nd = cholesky_fill(n, first, adjacent, &order);
    const long own = cholesky_fill(n, first, adjacent, nullptr);
    const long amd = cholesky_fill(n, first, adjacent, nullptr, true);
    EXPECT_LT(3 * nd, own) << (faces ? "faces" : "vertices");
    EXPECT_LT(double(nd), 1.5 * double(amd)) << (faces ? "faces" : "vertices");
    std::cout << (faces ? "faces" : "vertices") << ": fill " << nd << " (mesh order " << own << ", AMD " << amd << ")\n";
  }
}

TEST(JumpLaplace, ClosedLoopGivesTwoValuedFunctionAndExactJumps)
{
  Mesh m;
  const int n = 16;
  auto vs = grid_disk(m, n, 5);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  const SI::Mesh_tables& t = s.tables();
  const std::vector<double> chain = table_chain(m, s, {square_loop(vs, n, 4, 3, 11, 12)});
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

namespace {
// the period of a 1-form (per table edge) along a closed vertex loop
double period(const Mesh& m, const SWN::Surface_winding_numbers_solver<Mesh>& s, const std::vector<Vertex>& loop,
              const std::vector<double>& form)
{
  double sum = 0;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const auto h = halfedge(loop[i], loop[(i + 1) % loop.size()], m);
    if(!h.second)
    {
      ADD_FAILURE() << "consecutive loop vertices are not joined by an edge";
      return std::numeric_limits<double>::quiet_NaN();   // fails every comparison that follows
    }
    const std::size_t e = s.edge_index(edge(h.first, m));
    sum += (s.tables().ev[2 * e] == s.vertex_index(loop[i]) ? 1. : -1.) * form[e];
  }
  return sum;
}

double max_abs(const std::vector<double>& x)
{
  double r = 0;
  for(double v : x) r = std::max(r, std::abs(v));
  return r;
}

// d0^T S1 form per vertex (the divergence of the form)
std::vector<double> codifferential(const SI::Mesh_tables& t, const std::vector<double>& star, const std::vector<double>& form)
{
  std::vector<double> d(t.nv, 0.);
  for(std::size_t e = 0; e < t.ne; ++e)
  {
    d[t.ev[2 * e + 1]] += star[e] * form[e];
    d[t.ev[2 * e]] -= star[e] * form[e];
  }
  return d;
}

// omega = D u (Eq. 5) of the first jump Laplace solve of a table chain; `w` gets the cotan weights
std::vector<double> omega_of_chain(const SI::Mesh_tables& t, const std::vector<double>& chain, std::vector<double>& w)
{
  const std::vector<char> endpoint = SI::interior_endpoints(t, chain);
  SI::cotan_weights(t, w);
  SI::Jump_laplace_system<LA> L;
  L.jump_laplacian(t, w, endpoint);
  const std::vector<double> u = L.solve_jump_laplace(SI::reduced_coordinates(t, SI::arc_jumps_from_chain(t, chain), endpoint));
  return SI::darboux_derivative(t, u, endpoint);
}
} // namespace

TEST(HarmonicPart, GammaIsClosedToRoundOffAndKeepsThePeriod)
{
  Mesh m;
  const int nu = 24, nv = 12;
  auto vs = torus_mesh(m, nu, nv);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  const SI::Mesh_tables& t = s.tables();
  std::vector<Vertex> a, b;   // a meridian with a 2-edge gap
  for(int j = 0; j <= 4; ++j) a.push_back(vs[3 * nv + j]);
  for(int j = 6; j <= nv; ++j) b.push_back(vs[3 * nv + j % nv]);
  const std::vector<double> chain = table_chain(m, s, {a, b});
  std::vector<double> w;
  const std::vector<double> omega = omega_of_chain(t, chain, w);
  const std::vector<double> star = SI::edge_hodge_star(t, w);
  SI::Two_form_laplacian<LA> B;
  B.assemble(t, star);
  const std::vector<double> gamma = B.harmonic_part(omega);
  EXPECT_GT(max_abs(SI::face_curl(t, omega)), 1e-3);
  EXPECT_LT(max_abs(SI::face_curl(t, gamma)), 1e-12);
  // the period of gamma along a longitude (a loop crossing the meridian once) is in (0, 1]
  std::vector<Vertex> longitude;
  for(int i = 0; i < nu; ++i) longitude.push_back(vs[i * nv + 6]);
  const double p = period(m, s, longitude, gamma);
  EXPECT_GT(std::abs(p), 0.3);
  EXPECT_LE(std::abs(p), 1. + 1e-9);
}

TEST(HarmonicPart, CohomologyGeneratorsSpanTheClassesOfEveryComponent)
{
  // one mesh, two components: a torus (2 classes) and a torus with two holes (2g + b - 1 = 3)
  Mesh m;
  const int nu = 12, nv = 8;
  const auto vs = torus_mesh(m, nu, nv);
  torus_mesh(m, 14, 9);
  for(int f : {2 * nu * nv + 10, 2 * nu * nv + 130}) CGAL::Euler::remove_face(halfedge(Mesh::Face_index(f), m), m);
  m.collect_garbage();
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 2u);
  const SI::Cohomology_generators gen = SI::cohomology_generators(t);
  EXPECT_TRUE(gen.complete);
  ASSERT_EQ(gen.size(), 5u);
  std::vector<std::size_t> classes(2, 0);
  for(std::size_t e : gen.edges) ++classes[t.face_component[t.edge_sides[t.edge_side_begin[e]] / 3]];
  EXPECT_EQ(classes[t.face_component[0]], 2u);
  EXPECT_EQ(classes[1 - t.face_component[0]], 3u);

  std::vector<double> w;
  SI::cotan_weights(t, w);
  const std::vector<double> star = SI::edge_hodge_star(t, w);
  SI::Jump_laplace_system<LA> L0;   // nothing excluded: the 0-form Laplacian
  L0.jump_laplacian(t, w, std::vector<char>(t.nv, 0));
  SI::Harmonic_basis<LA> basis;
  basis.assemble(t, star, gen, L0);   // throws if the Gram matrix of the h_k is singular
  ASSERT_TRUE(basis.assembled());
  std::vector<Vertex> meridian, longitude;
  for(int j = 0; j < nv; ++j) meridian.push_back(vs[std::size_t(3 * nv + j)]);
  for(int i = 0; i < nu; ++i) longitude.push_back(vs[std::size_t(i * nv + 5)]);
  double largest_period = 0;
  for(std::size_t k = 0; k < gen.size(); ++k)
  {
    std::vector<double> zeta(t.ne, 0.);
    for(const auto& z : gen.closed_form(t, k))
    {
      EXPECT_EQ(std::abs(z.second), 1.);
      zeta[z.first] = z.second;
    }
    EXPECT_EQ(zeta[gen.edges[k]], 1.);
    for(std::size_t j = 0; j < gen.size(); ++j)
      if(j != k) EXPECT_EQ(zeta[gen.edges[j]], 0.);
    EXPECT_EQ(max_abs(SI::face_curl(t, zeta)), 0.);   // exactly closed
    // its harmonic part is closed and co-closed, a projection, and differs from zeta by an exact
    // form: the same periods
    const std::vector<double> h = basis.harmonic_part(zeta);
    EXPECT_LT(max_abs(SI::face_curl(t, h)), 1e-12);
    EXPECT_LT(max_abs(codifferential(t, star, h)), 1e-10);
    const std::vector<double> hh = basis.harmonic_part(h);
    for(std::size_t e = 0; e < t.ne; ++e) EXPECT_NEAR(hh[e], h[e], 1e-10);
    for(const auto& loop : {meridian, longitude})
    {
      const double p = period(m, s, loop, zeta);
      EXPECT_NEAR(period(m, s, loop, h), p, 1e-10);
      largest_period = std::max(largest_period, std::abs(p));
    }
  }
  EXPECT_EQ(largest_period, 1.);   // the torus's classes are dual to its meridian and longitude
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

namespace {
// a torus mesh (torus_mesh(nu, nv)), its tables and their cotan weights, for the 0-form Laplacian's solves
struct Torus_tables
{
  Mesh mesh;
  std::unique_ptr<SWN::Surface_winding_numbers_solver<Mesh>> solver;
  std::vector<double> w;
  Torus_tables(int nu, int nv)
  {
    torus_mesh(mesh, nu, nv);
    solver.reset(new SWN::Surface_winding_numbers_solver<Mesh>(mesh));
    SI::cotan_weights(solver->tables(), w);
  }
};
} // namespace

TEST(HarmonicPart, ManyColumnSolveAgreesWithColumnByColumn)
{
  // more right-hand sides than one block of the many-column solve, the last block partial
  const Torus_tables torus(16, 9);
  const SI::Mesh_tables& t = torus.solver->tables();
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

TEST(HarmonicPart, ManyColumnSolveSharedWithAHelperThreadGivesTheSameColumns)
{
  // the Hodge step's many-column solve, its blocks shared with a thread that calls help() (as the
  // solving thread does once it has solved for u), against the same solve alone: the same blocks
  // go through the same solves, so the columns agree exactly whichever thread solved them
  const Torus_tables torus(24, 13);
  const SI::Mesh_tables& t = torus.solver->tables();
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
    std::thread helper;
    if(helper_first) helper = std::thread([&] { share.help(); });   // waits for the work to be published
    std::thread owner([&] {
      shared = A.solve_vertex_laplace(k, rhs, &share);
      share.finish();
    });
    if(!helper_first) helper = std::thread([&] { share.help(); });
    owner.join();
    helper.join();
    ASSERT_EQ(shared.size(), alone.size());
    for(std::size_t i = 0; i < alone.size(); ++i) ASSERT_EQ(shared[i], alone[i]) << "entry " << i;
  }
}

TEST(HarmonicPart, SharedWorkIsDoneOnceAndHelpersNeverWaitForever)
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
    std::thread helper;
    if(helper_first) helper = std::thread([&] { share.help(); });
    std::size_t done_at_return = 0;
    std::thread owner([&] {
      share.run(work);
      done_at_return = std::size_t(std::count(done.begin(), done.end(), 1));
      share.finish();
    });
    if(!helper_first) helper = std::thread([&] { share.help(); });
    owner.join();
    helper.join();
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

TEST(HarmonicPart, HarmonicBasisAndTwoFormLaplacianGiveTheSameGamma)
{
  // an open curve on a torus with a hole (2g + b - 1 = 2 classes): omega of the jump harmonic function has no exact part
  // (App. A), so removing its coexact part (2-form Laplacian) and projecting on the harmonic forms
  // give the same gamma
  Mesh m;
  const int nu = 20, nv = 10;
  const auto vs = torus_mesh(m, nu, nv);
  CGAL::Euler::remove_face(halfedge(Mesh::Face_index(2 * (12 * nv + 3)), m), m);
  m.collect_garbage();
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  const SI::Mesh_tables& t = s.tables();
  std::vector<Vertex> a, loop;
  for(int j = 0; j <= 6; ++j) a.push_back(vs[std::size_t(2 * nv + j)]);
  for(int i = 5; i <= 9; ++i) loop.push_back(vs[std::size_t(i * nv + 1)]);
  for(int j = 2; j <= 4; ++j) loop.push_back(vs[std::size_t(9 * nv + j)]);
  const std::vector<double> chain = table_chain(m, s, {a, loop});
  std::vector<double> w;
  const std::vector<double> omega = omega_of_chain(t, chain, w);
  const std::vector<double> star = SI::edge_hodge_star(t, w);
  SI::Two_form_laplacian<LA> B;
  B.assemble(t, star);
  SI::Harmonic_basis<LA> H;
  const SI::Cohomology_generators gen = SI::cohomology_generators(t);
  ASSERT_TRUE(gen.complete);
  EXPECT_EQ(gen.size(), 2u);
  SI::Jump_laplace_system<LA> L0;
  L0.jump_laplacian(t, w, std::vector<char>(t.nv, 0));
  H.assemble(t, star, gen, L0);
  const std::vector<double> g1 = B.harmonic_part(omega), g2 = H.harmonic_part(omega);
  EXPECT_GT(max_abs(g1), 0.01);
  for(std::size_t e = 0; e < t.ne; ++e) EXPECT_NEAR(g1[e], g2[e], 1e-9);
  EXPECT_LT(max_abs(SI::face_curl(t, g2)), 1e-12);
}

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

TEST(ResidualFunction, OptimumSatisfiesConstraintsAndMatchesTheAuthorsFormulation)
{
  Mesh m;
  const int nu = 20, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  const SI::Mesh_tables& t = solver.tables();
  std::vector<Vertex> a, b, loop;   // broken meridian + broken contractible loop
  for(int j = 0; j <= 3; ++j) a.push_back(vs[2 * nv + j]);
  for(int j = 5; j <= nv; ++j) b.push_back(vs[2 * nv + j % nv]);
  for(int i = 8; i <= 12; ++i) loop.push_back(vs[i * nv + 2]);
  for(int j = 3; j <= 5; ++j) loop.push_back(vs[12 * nv + j]);
  for(int i = 11; i >= 9; --i) loop.push_back(vs[i * nv + 5]);
  const std::vector<double> chain = table_chain(m, solver, {a, b, loop});
  const SWN::Residual_problem P = solver.core().residual_problem_of(chain, 0.01);
  SWN::GLPK_linear_program_traits lp;
  double objective = 0;
  std::size_t nvar = 0, nrow = 0;
  const std::vector<double> sigma = SI::residual_function(P, lp, objective, nvar, nrow);
  for(std::size_t k = 0; k < P.number_of_arcs(); ++k)
  {
    const double G = chain[t.arcs[k].edge];
    if(G == 0) { EXPECT_FALSE(P.is_bounded(k)); continue; }
    const double J = P.jump(sigma, k);
    EXPECT_GE(J / G, -1e-7);
    EXPECT_LE(J / G, 1 + 1e-7);
  }
  EXPECT_GT(objective, 0.);
  EXPECT_NEAR(objective, reference_residual_objective(t, P, chain), 1e-7 * (1 + objective));
}

TEST(Solver, ManyCurvesOnOneMeshMatchTheFreeFunction)
{
  Mesh m;
  const int nu = 20, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  ASSERT_TRUE(solver.is_valid());
  for(int i0 = 0; i0 < 3; ++i0)
  {
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    for(auto e : edges(m)) chain[e] = 0;
    std::vector<Vertex> a, b;
    for(int j = 0; j <= 3 + i0; ++j) a.push_back(vs[(2 + 5 * i0) * nv + j]);
    for(int j = 5 + i0; j <= nv; ++j) b.push_back(vs[(2 + 5 * i0) * nv + j % nv]);
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, a, chain));
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, b, chain));
    std::map<Mesh::Face_index, int> l1, l2;
    std::map<Mesh::Edge_index, int> G1, G2;
    auto L1 = boost::make_assoc_property_map(l1);
    auto L2 = boost::make_assoc_property_map(l2);
    ASSERT_TRUE(solver.solve(chain, L1, SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G1))));
    ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, L2, SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G2))));
    EXPECT_EQ(l1, l2);
    EXPECT_EQ(G1, G2);
    int nG = 0;
    for(auto e : edges(m)) nG += G1[e] != 0;
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
  auto V = [&](int i, int j) { return vs[std::size_t(i * nv + j)]; };
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  struct Curve { std::vector<std::vector<Vertex>> polylines; bool open; int inside; };
  std::vector<Curve> curves;
  curves.push_back({{{V(2, 0), V(2, 1), V(2, 2), V(2, 3)}}, true, 0});    // open piece of a meridian
  std::vector<Vertex> square, big, meridian;
  for(int i = 5; i < 8; ++i) square.push_back(V(i, 2));
  for(int j = 2; j < 5; ++j) square.push_back(V(8, j));
  for(int i = 8; i > 5; --i) square.push_back(V(i, 5));
  for(int j = 5; j >= 2; --j) square.push_back(V(5, j));
  for(int i = 10; i < 15; ++i) big.push_back(V(i, 1));
  for(int j = 1; j < 4; ++j) big.push_back(V(15, j));
  for(int i = 15; i > 10; --i) big.push_back(V(i, 4));
  for(int j = 4; j >= 1; --j) big.push_back(V(10, j));
  for(int j = 0; j <= nv; ++j) meridian.push_back(V(17, j % nv));
  curves.push_back({{square}, false, 2 * 3 * 3});
  curves.push_back({{big, meridian}, false, 2 * 5 * 3});   // with a nonbounding loop
  curves.push_back({{square}, false, 2 * 3 * 3});
  std::vector<bool> reused;
  for(int keep = 1; keep >= 0; --keep)
    for(const Curve& c : curves)
    {
      auto chain = get(CGAL::dynamic_edge_property_t<int>(), m);
      for(auto e : edges(m)) put(chain, e, 0);
      for(const auto& p : c.polylines) ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
      std::map<Mesh::Face_index, int> l1, l2;
      std::map<Mesh::Edge_index, int> G1, G2;
      ASSERT_TRUE(solver.solve(chain, boost::make_assoc_property_map(l1),
                               SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G1),
                               SWN::parameters::keep_hodge_factorization(keep == 1)))) << solver.report().error;
      reused.push_back(solver.report().jump_laplacian_reused);
      EXPECT_EQ(solver.report().interior_endpoints > 0, c.open);
      ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(l2),
                                                SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G2))));
      EXPECT_EQ(l1, l2);
      EXPECT_EQ(G1, G2);
      int inside = 0;
      for(const auto& l : l1) inside += l.second == 1;
      if(!c.open) EXPECT_EQ(inside, c.inside);
    }
  // kept: the closed curves after the first reuse its jump Laplacian (the open curve's harmonic basis
  // does not keep its own 0-form Laplacian); dropped: nothing is reused
  EXPECT_EQ(reused, std::vector<bool>({false, false, true, true, false, false, false, false}));
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
  auto vs = grid_disk(m, n, 2);
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

TEST(Solver, SparseSolversAgree)
{
  Mesh m;
  const int nu = 20, nv = 10;
  auto vs = torus_mesh(m, nu, nv);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  std::vector<Vertex> a, loop;
  for(int j = 0; j <= 7; ++j) a.push_back(vs[2 * nv + j]);   // open meridian piece
  for(int i = 8; i <= 12; ++i) loop.push_back(vs[i * nv + 2]);
  for(int j = 3; j <= 5; ++j) loop.push_back(vs[12 * nv + j]);
  for(int i = 11; i >= 8; --i) loop.push_back(vs[i * nv + 5]);
  for(int j = 4; j >= 2; --j) loop.push_back(vs[8 * nv + j]);
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, a, chain));
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, loop, chain));
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
    SWN::Surface_winding_numbers_solver<Mesh> s(m);
    ASSERT_GE(s.tables().nv, SI::nested_dissection_unknowns);
    std::vector<std::size_t> order = SI::vertex_elimination_order(s.tables());
    std::sort(order.begin(), order.end());
    ASSERT_EQ(order.size(), s.tables().nv);
    for(std::size_t k = 0; k < order.size(); ++k) ASSERT_EQ(order[k], k);
  }
  EXPECT_EQ(faces_labelled_one_by_both_sparse_solvers(m, chain), 2 * 200 * 170);
}

namespace {
// On an nu x nv torus (nu >= 16, nv >= 7), a meridian broken by a one-edge gap and a 5 x 4
// contractible loop broken by a one-edge gap, far apart; returns the chain map ("e:chain")
Mesh::Property_map<Mesh::Edge_index, int> broken_meridian_and_loop(Mesh& m, int nu, int nv)
{
  auto vs = torus_mesh(m, nu, nv);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  std::vector<Vertex> a, b, loop;
  for(int j = 0; j <= 4; ++j) a.push_back(vs[2 * nv + j]);
  for(int j = 6; j <= nv; ++j) b.push_back(vs[2 * nv + j % nv]);
  for(int i = 10; i <= 15; ++i) loop.push_back(vs[i * nv + 2]);
  for(int j = 3; j <= 6; ++j) loop.push_back(vs[15 * nv + j]);
  for(int i = 14; i >= 10; --i) loop.push_back(vs[i * nv + 6]);
  for(int j = 5; j >= 3; --j) loop.push_back(vs[10 * nv + j]);   // one-edge gap left open
  for(const auto& p : {a, b, loop}) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
  return chain;
}

// labels and G of two solves on the mesh of broken_meridian_and_loop, to compare
struct Two_solves
{
  explicit Two_solves(Mesh& m)
    : l1(m.add_property_map<Mesh::Face_index, int>("f:l1", 0).first),
      l2(m.add_property_map<Mesh::Face_index, int>("f:l2", 0).first),
      G1(m.add_property_map<Mesh::Edge_index, int>("e:G1", 0).first),
      G2(m.add_property_map<Mesh::Edge_index, int>("e:G2", 0).first)
  {}

  // the two agree face by face and edge by edge, and give the analytic answer: label 1 on the
  // 2 x 5 x 4 faces inside the loop, the completed meridian (nv edges) as G
  void expect_same_analytic_answer(const Mesh& m, int nv) const
  {
    int inside = 0, nG = 0;
    for(auto f : faces(m)) { EXPECT_EQ(l1[f], l2[f]); inside += l1[f] == 1; }
    for(auto e : edges(m)) { EXPECT_EQ(G1[e], G2[e]); nG += G1[e] != 0; }
    EXPECT_EQ(inside, 2 * 5 * 4);
    EXPECT_EQ(nG, nv);
  }

  Mesh::Property_map<Mesh::Face_index, int> l1, l2;
  Mesh::Property_map<Mesh::Edge_index, int> G1, G2;
};
} // namespace

namespace {
// the weight of a deviation from g per edge: its length, doubled on the input curve
double deviation_weight(const SI::Mesh_tables& t, const std::vector<double>& curve, std::size_t e)
{
  return t.edge_length(e) * (curve[e] != 0 ? SI::curve_deviation_factor : 1.);
}

// sum_e weight_e |C_e - g_e| over the interior edges
double nearest_chain_cost(const SI::Mesh_tables& t, const std::vector<double>& g, const std::vector<double>& curve,
                          const std::vector<int>& C)
{
  double c = 0;
  for(const SI::Arc& a : t.arcs) c += deviation_weight(t, curve, a.edge) * std::abs(C[a.edge] - g[a.edge]);
  return c;
}

// The nearest closed integer chain by GLPK's simplex: an oracle independent of the shortest paths.
// Per arc, G_a = r_a + p_a + P_a - n_a - N_a with r = round(g); p_a, n_a in [0, 1] carry the first
// step up or down (cost c_a (|r_a +- 1 - g_a| - |r_a - g_a|), c_a the deviation weight), P_a, N_a >= 0
// the further ones (cost c_a each); dG = 0 at interior vertices. The cost is exact at integer points and the constraint
// matrix is a network matrix, so an integral optimal vertex is the integer optimum.
double nearest_closed_chain_cost_by_lp(const SI::Mesh_tables& t, const std::vector<double>& g,
                                       const std::vector<double>& curve)
{
  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MIN);
  const int na = int(t.arcs.size());
  glp_add_cols(lp, 4 * na);
  std::vector<int> row_of_vertex(t.nv, 0);
  int rows = 0;
  for(std::size_t v = 0; v < t.nv; ++v)
    if(!t.vertex_on_border[v]) row_of_vertex[v] = ++rows;
  glp_add_rows(lp, rows);
  std::vector<double> rhs(rows + 1, 0.);
  std::vector<int> ia(1), ja(1);
  std::vector<double> ar(1);
  double constant = 0;
  for(int a = 0; a < na; ++a)
  {
    const std::size_t e = t.arcs[a].edge;
    const double l = deviation_weight(t, curve, e), r = double(SI::round_half_away(g[e]));
    constant += l * std::abs(r - g[e]);
    const double up = l * (std::abs(r + 1 - g[e]) - std::abs(r - g[e])), down = l * (std::abs(r - 1 - g[e]) - std::abs(r - g[e]));
    const double cost[4] = {up, l, down, l}, sign[4] = {1, 1, -1, -1};
    const int tail = row_of_vertex[t.ev[2 * e]], head = row_of_vertex[t.ev[2 * e + 1]];
    if(tail) rhs[tail] += r;   // dG = 0: sum over the arcs of -G at the tail, +G at the head
    if(head) rhs[head] -= r;
    for(int k = 0; k < 4; ++k)
    {
      const int c = 4 * a + k + 1;
      glp_set_col_bnds(lp, c, k % 2 == 0 ? GLP_DB : GLP_LO, 0, 1);
      glp_set_obj_coef(lp, c, cost[k]);
      if(tail) { ia.push_back(tail); ja.push_back(c); ar.push_back(-sign[k]); }
      if(head) { ia.push_back(head); ja.push_back(c); ar.push_back(sign[k]); }
    }
  }
  for(int r = 1; r <= rows; ++r) glp_set_row_bnds(lp, r, GLP_FX, rhs[r], rhs[r]);
  glp_load_matrix(lp, int(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  double cost = -1;
  if(glp_simplex(lp, &parm) == 0 && glp_get_status(lp) == GLP_OPT)
  {
    bool integral = true;
    for(int c = 1; c <= 4 * na; ++c)
      integral = integral && std::abs(glp_get_col_prim(lp, c) - std::round(glp_get_col_prim(lp, c))) < 1e-9;
    if(integral) cost = constant + glp_get_obj_val(lp);
  }
  glp_delete_prob(lp);
  return cost;
}
} // namespace

// G (paper Sec. 3.6): round(g) where that is closed, otherwise the closed integer chain nearest to
// g, checked against a network linear program on a torus and a disk (border) in one mesh.
TEST(NonboundingChain, ClosesRoundingAtTheLeastCost)
{
  Mesh m;
  const std::vector<Vertex> tv = torus_mesh(m, 9, 7);
  grid_disk(m, 6, 3);
  SWN::Surface_winding_numbers_solver<Mesh> s(m);
  ASSERT_TRUE(s.is_valid()) << s.report().error;
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 2u);
  // a meridian of the torus: the input curve, and the integer closed chain g is a perturbation of
  std::vector<Vertex> meridian;
  for(int j = 0; j <= 7; ++j) meridian.push_back(tv[3 * 7 + j % 7]);
  const std::vector<double> C = table_chain(m, s, {meridian});

  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-0.75, 0.75);
  std::bernoulli_distribution perturb(0.3), half(0.1);
  int opened = 0, kept = 0;
  for(int trial = 0; trial < 40; ++trial)
  {
    std::vector<double> g(t.ne, 0.);
    for(const SI::Arc& a : t.arcs)
    {
      g[a.edge] = C[a.edge];
      if(trial % 4 == 0) { if(perturb(rng)) g[a.edge] += 0.6 * noise(rng); }   // rounding gives C back
      else if(perturb(rng)) g[a.edge] += noise(rng);
      else if(half(rng)) g[a.edge] += (trial % 2 ? 0.5 : -0.5);   // ties of the rounding
    }
    std::size_t units = 99;
    const std::vector<int> G = SI::nonbounding_chain(t, g, C, &units);
    const std::vector<int> rounded = SI::rounded_chain(g);
    ASSERT_TRUE(SI::is_relatively_closed(t, G)) << "trial " << trial;
    for(std::size_t e = 0; e < t.ne; ++e)
      if(t.edge_arc[e] == SI::npos) ASSERT_EQ(G[e], 0) << "G on a border edge, trial " << trial;
    if(SI::is_relatively_closed(t, rounded))
    {
      ++kept;
      EXPECT_EQ(units, 0u);
      EXPECT_EQ(G, rounded) << "trial " << trial;
    }
    else
    {
      ++opened;
      EXPECT_GT(units, 0u);
      const double best = nearest_closed_chain_cost_by_lp(t, g, C);
      ASSERT_GE(best, 0.) << "GLPK failed or its optimum is not integral, trial " << trial;
      EXPECT_NEAR(nearest_chain_cost(t, g, C, G), best, 1e-9 * (1 + best)) << "trial " << trial;
    }
  }
  EXPECT_GT(opened, 20);   // the instances exercise the closing
  EXPECT_GT(kept, 0);
}

TEST(ReducedResidual, AgreesWithTheExactResidualOnSeparatedCurves)
{
  // broken meridian + broken contractible loop, far apart: the reduced problem (Sec. 6) gives the
  // same labels and the same G as Eq. 11, with far fewer LP variables
  Mesh m;
  const int nu = 24, nv = 12;
  const auto chain = broken_meridian_and_loop(m, nu, nv);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const Two_solves s(m);
  SWN::Solve_report exact, reduced;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, s.l1, SWN::parameters::nonbounding_chain_map(s.G1, SWN::parameters::report(std::ref(exact)))));
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, s.l2, SWN::parameters::nonbounding_chain_map(s.G2,
                SWN::parameters::use_reduced_residual(true, SWN::parameters::report(std::ref(reduced)))))) << reduced.error;
  EXPECT_TRUE(reduced.reduced_residual);
  EXPECT_LT(reduced.lp_variables * 10, exact.lp_variables);
  s.expect_same_analytic_answer(m, nv);
}

TEST(Solver, HarmonicBasisAndTwoFormLaplacianGiveTheSameAnswer)
{
  // the same solve with the Hodge projection on the harmonic basis (the default at 2 classes) and
  // with the 2-form Laplacian (harmonic_basis_max_classes = 0)
  Mesh m;
  const int nu = 24, nv = 12;
  const auto chain_map = broken_meridian_and_loop(m, nu, nv);
  ASSERT_FALSE(::testing::Test::HasFailure());
  std::vector<SI::Core_result> results;
  std::vector<SWN::Solve_report> reports;
  for(std::size_t max_classes : {SI::harmonic_basis_max_classes, std::size_t(0)})
  {
    SWN::Surface_winding_numbers_solver<Mesh> s(m);
    std::vector<double> chain(num_edges(m), 0.);
    for(auto e : edges(m)) chain[s.edge_index(e)] = get(chain_map, e);
    SI::Solve_options options;
    options.harmonic_basis_max_classes = max_classes;
    SWN::LEMON_residual_solver lp;
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

TEST(ConcurrentFactorizations, SameAnswerAsSequential)
{
  // broken meridian + broken contractible loop: the Hodge projection is needed, and by default its
  // harmonic basis is built on a second thread (the 0-form Laplacian's factorization there, the
  // cohomology generators on this thread meanwhile); the answer is the analytic one and the same as
  // with everything on this thread, also when the solver object is reused
  Mesh m;
  const int nu = 24, nv = 12;
  const auto chain = broken_meridian_and_loop(m, nu, nv);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const Two_solves s(m);
  auto w1 = m.add_property_map<Mesh::Halfedge_index, double>("h:w1", 0).first;
  auto w2 = m.add_property_map<Mesh::Halfedge_index, double>("h:w2", 0).first;
  SWN::Solve_report concurrent, sequential;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, s.l1, SWN::parameters::nonbounding_chain_map(s.G1,
                SWN::parameters::winding_number_map(w1, SWN::parameters::report(std::ref(concurrent))))));
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, s.l2, SWN::parameters::nonbounding_chain_map(s.G2,
                SWN::parameters::winding_number_map(w2, SWN::parameters::concurrency(CGAL::Sequential_tag(),
                SWN::parameters::report(std::ref(sequential))))))) << sequential.error;
  EXPECT_TRUE(concurrent.hodge_projection);
  EXPECT_TRUE(sequential.hodge_projection);
  s.expect_same_analytic_answer(m, nv);
  for(auto h : halfedges(m))
    if(std::isfinite(w1[h]) || std::isfinite(w2[h])) EXPECT_NEAR(w1[h], w2[h], 1e-9);
  EXPECT_NEAR(concurrent.lp_objective, sequential.lp_objective, 1e-9 * (1 + sequential.lp_objective));

  // the solver class keeps the harmonic basis built on the second thread for its next solve
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  auto l3 = m.add_property_map<Mesh::Face_index, int>("f:l3", 0).first;
  for(int k = 0; k < 2; ++k)
  {
    ASSERT_TRUE(solver.solve(chain, l3)) << solver.report().error;
    EXPECT_TRUE(solver.report().hodge_projection);
    for(auto f : faces(m)) EXPECT_EQ(l3[f], s.l1[f]);
  }
  // freed after a solve (keep_hodge_factorization(false)), it is factorized again by the next one,
  // and the answers stay the same
  auto w3 = m.add_property_map<Mesh::Halfedge_index, double>("h:w3", 0).first;
  for(int k = 0; k < 2; ++k)
  {
    ASSERT_TRUE(solver.solve(chain, l3, SWN::parameters::keep_hodge_factorization(false,
                                        SWN::parameters::winding_number_map(w3)))) << solver.report().error;
    EXPECT_TRUE(solver.report().hodge_projection);
    for(auto f : faces(m)) EXPECT_EQ(l3[f], s.l1[f]);
    for(auto h : halfedges(m))
      if(std::isfinite(w1[h]) || std::isfinite(w3[h])) EXPECT_NEAR(w1[h], w3[h], 1e-9);
  }
  ASSERT_TRUE(solver.solve(chain, l3)) << solver.report().error;
  for(auto f : faces(m)) EXPECT_EQ(l3[f], s.l1[f]);
}
