// Stage-by-stage tests of the numerical core (flat tables), of the LP traits and of the solver class.
// One GoogleTest suite per stage (include/CGAL/Surface_winding_numbers/internal/), in pipeline order:
//   MeshTables (mesh_tables.h), UnionFind (union_find.h), LocalityOrder (locality_order.h),
//   CotanWeights (cotan_weights.h), JumpLaplace (jump_laplace.h), NestedDissection
//   (nested_dissection.h), Derivatives (derivatives.h), HarmonicPart (harmonic_part.h), Residual
//   (residual.h), LinearProgramTraits (GLPK_linear_program_traits.h), WindingNumber
//   (winding_number.h), NonboundingChain (nonbounding_chain.h), ReducedResidual (reduced_residual.h),
//   Solver (pipeline.h and the solver class, end to end).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/surface_winding_numbers.h>
#ifdef CGAL_USE_GLPK
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#endif
#include <CGAL/Surface_winding_numbers/internal/locality_order.h>
#include <CGAL/Surface_winding_numbers/internal/pipeline.h>

#include <Eigen/SparseCholesky>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <map>
#include <memory>
#include <random>
#include <thread>
#include <utility>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SI = CGAL::Surface_winding_numbers::internal;
typedef SI::Default_sparse_solver LA;
typedef SWN::Surface_winding_numbers_solver<Mesh> Solver;

const double inf = std::numeric_limits<double>::infinity();
const double NaN = std::numeric_limits<double>::quiet_NaN();

// n x n grid on [0,1]^2 (a disk), diagonals chosen at random; vertex (i, j) is vs[j * (n + 1) + i]
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

// nu x nv torus of revolution; vertex (i, j) is vs[i * nv + j], cell (i, j) the faces 2 (i nv + j) and 2 (i nv + j) + 1
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

// the chain of vertex polylines as a vector indexed like the solver's tables
std::vector<double> table_chain(const Mesh& m, const Solver& s, const std::vector<std::vector<Vertex>>& polylines)
{
  auto map = get(CGAL::dynamic_edge_property_t<int>(), m);
  for(auto e : edges(m)) put(map, e, 0);
  for(const auto& p : polylines) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, map));
  std::vector<double> c(num_edges(m), 0.);
  for(auto e : edges(m)) c[s.edge_index(e)] = get(map, e);
  return c;
}

std::vector<double> negated(std::vector<double> x)
{
  for(double& v : x) v = -v;
  return x;
}

// the rectangle of grid vertices at(i, j) with corners (i0, j0), (i1, j1), walked counter-clockwise in
// (i, j) from (i0, j0) back to it
template <class At>
std::vector<Vertex> rect_loop(const At& at, int i0, int j0, int i1, int j1)
{
  std::vector<Vertex> loop;
  for(int i = i0; i < i1; ++i) loop.push_back(at(i, j0));
  for(int j = j0; j < j1; ++j) loop.push_back(at(i1, j));
  for(int i = i1; i > i0; --i) loop.push_back(at(i, j1));
  for(int j = j1; j >= j0; --j) loop.push_back(at(i0, j));
  return loop;
}

// vertex (i, j) of grid_disk(n), of torus_mesh(nu, nv) (j modulo nv)
std::function<Vertex(int, int)> grid_vertex(const std::vector<Vertex>& vs, int n)
{
  return [&vs, n](int i, int j) { return vs[std::size_t(j * (n + 1) + i)]; };
}
std::function<Vertex(int, int)> torus_vertex(const std::vector<Vertex>& vs, int nv)
{
  return [&vs, nv](int i, int j) { return vs[std::size_t(i * nv + j % nv)]; };
}

std::vector<Vertex> square_loop(const std::vector<Vertex>& vs, int n, int i0, int j0, int i1, int j1)
{
  return rect_loop(grid_vertex(vs, n), i0, j0, i1, j1);
}

// the polyline (i, j0), (i, j0 + 1), ..., (i, j1) of a grid_disk(n): a vertical path
std::vector<Vertex> grid_column(const std::vector<Vertex>& vs, int n, int i, int j0, int j1)
{
  std::vector<Vertex> p;
  for(int j = j0; j <= j1; ++j) p.push_back(grid_vertex(vs, n)(i, j));
  return p;
}

// the polyline (i, j0), ..., (i, j1) along a meridian of torus_mesh(nu, nv) (j modulo nv)
std::vector<Vertex> meridian_piece(const std::vector<Vertex>& vs, int nv, int i, int j0, int j1)
{
  std::vector<Vertex> p;
  for(int j = j0; j <= j1; ++j) p.push_back(torus_vertex(vs, nv)(i, j));
  return p;
}

// the polyline without its last k vertices
std::vector<Vertex> without_last(std::vector<Vertex> p, std::size_t k)
{
  p.resize(p.size() - k);
  return p;
}

// per face of the tables: 1 if the centroid lies in the open rectangle (x0, x1) x (y0, y1)
std::vector<char> faces_in_rect(const SI::Mesh_tables& t, double x0, double y0, double x1, double y1)
{
  std::vector<char> in(t.nf, 0);
  for(std::size_t f = 0; f < t.nf; ++f)
  {
    double x = 0, y = 0;
    for(int k = 0; k < 3; ++k) { x += t.point(t.fv[3 * f + k])[0] / 3; y += t.point(t.fv[3 * f + k])[1] / 3; }
    in[f] = x > x0 && x < x1 && y > y0 && y < y1;
  }
  return in;
}

// per corner: the value of its face
std::vector<double> per_corner(const std::vector<double>& per_face)
{
  std::vector<double> w(3 * per_face.size());
  for(std::size_t c = 0; c < w.size(); ++c) w[c] = per_face[c / 3];
  return w;
}

// the corner of face f at vertex v, found without Mesh_tables::corner_at
std::size_t corner_of(const SI::Mesh_tables& t, std::size_t f, std::size_t v)
{
  for(std::size_t c = 3 * f; c < 3 * f + 3; ++c)
    if(t.fv[c] == v) return c;
  ADD_FAILURE() << "vertex " << v << " is not a corner of face " << f;
  return 3 * f;
}

double max_abs(const std::vector<double>& x)
{
  double r = 0;
  for(double v : x) r = std::max(r, std::abs(v));
  return r;
}

std::vector<double> random_values(std::size_t n, unsigned seed, double lo = -1, double hi = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(lo, hi);
  std::vector<double> x(n);
  for(double& v : x) v = U(rng);
  return x;
}

// the differential of a vertex function: phi(head) - phi(tail) on every edge
std::vector<double> differential(const SI::Mesh_tables& t, const std::vector<double>& phi)
{
  std::vector<double> d(t.ne);
  for(std::size_t e = 0; e < t.ne; ++e) d[e] = phi[t.ev[2 * e + 1]] - phi[t.ev[2 * e]];
  return d;
}

// the message of the Solver_failure that f throws, "<none>" if it throws none
template <class F>
std::string failure_message(F f)
{
  try { f(); }
  catch(const SWN::Solver_failure& e) { return e.what(); }
  return "<none>";
}

// a generated mesh, its vertices in the generator's order, and its solver (built by the derived class)
struct Mesh_and_tables
{
  Mesh mesh;
  std::vector<Vertex> vs;
  std::unique_ptr<Solver> solver;
  void make_solver()
  {
    solver.reset(new Solver(mesh));
    EXPECT_TRUE(solver->is_valid()) << solver->report().error;
  }
  const SI::Mesh_tables& tables() const { return solver->tables(); }
  // vertex polylines as a chain indexed like the tables
  std::vector<double> chain(const std::vector<std::vector<Vertex>>& polylines) const { return table_chain(mesh, *solver, polylines); }
};

// grid_disk(n, seed, jitter): vertex V(i, j)
struct Grid_tables : Mesh_and_tables
{
  int n;
  Grid_tables(int n_, unsigned seed = 1, double jitter = 0.2) : n(n_)
  {
    vs = grid_disk(mesh, n, seed, jitter);
    make_solver();
  }
  Vertex V(int i, int j) const { return grid_vertex(vs, n)(i, j); }
};

// torus_mesh(nu, nv) and its cotan weights w
struct Torus_tables : Mesh_and_tables
{
  std::vector<double> w;
  Torus_tables(int nu, int nv)
  {
    vs = torus_mesh(mesh, nu, nv);
    make_solver();
    SI::cotan_weights(tables(), w);
  }
};
} // namespace

// =============================================================================================
// MeshTables (mesh_tables.h)
// =============================================================================================

TEST(MeshTables, GridIsADiskWithConsistentArcs)
{
  const Grid_tables grid(6);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const SI::Mesh_tables& t = grid.tables();
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
  Solver s(m);
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
      s.point(Vertex(83)) = K::Point_3(NaN, 0, 0);
      expected = "vertex 83 has a non-finite coordinate";
    }
    Solver solver(s);
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
  Solver solver(s);
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

// =============================================================================================
// UnionFind (union_find.h)
// =============================================================================================

TEST(UnionFind, SetsAreTheConnectedComponentsWithTheirSmallestElementAsRepresentative)
{
  // random unions on 100 elements against the components of the same graph found by a
  // breadth-first search; the representative of every set is its smallest element
  const std::size_t n = 100;
  SI::Union_find sets(n);
  std::vector<std::vector<std::size_t>> adjacent(n);
  std::mt19937 rng(16);
  std::uniform_int_distribution<std::size_t> element(0, n - 1);
  for(int k = 0; k < 70; ++k)
  {
    const std::size_t a = element(rng), b = element(rng);
    sets.unite(a, b);
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  std::vector<std::size_t> smallest(n, SI::npos);
  for(std::size_t root = 0; root < n; ++root)   // in increasing order: the first one met is the smallest
  {
    if(smallest[root] != SI::npos) continue;
    std::vector<std::size_t> queue(1, root);
    smallest[root] = root;
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(std::size_t x : adjacent[queue[q]])
        if(smallest[x] == SI::npos) { smallest[x] = root; queue.push_back(x); }
  }
  std::size_t singletons = 0, shared = 0;
  for(std::size_t x = 0; x < n; ++x)
  {
    EXPECT_EQ(sets.find(x), smallest[x]) << "element " << x;
    (smallest[x] == x && adjacent[x].empty() ? singletons : shared) += 1;
  }
  EXPECT_GT(singletons, 0u);
  EXPECT_GT(shared, n / 2);
}

// =============================================================================================
// LocalityOrder (locality_order.h)
// =============================================================================================

TEST(LocalityOrder, MortonCodesSpreadBitKToBit3K)
{
  for(int k = 0; k < 21; ++k) EXPECT_EQ(SI::spread_bits_3(std::uint64_t(1) << k), std::uint64_t(1) << (3 * k)) << k;
  EXPECT_EQ(SI::spread_bits_3(std::uint64_t(1) << 21), 0u);   // only the 21 low bits count
  EXPECT_EQ(SI::spread_bits_3(0x1fffff), 0x1249249249249249ULL);
  EXPECT_EQ(SI::spread_bits_3(0b101), 0b1000001u);
}

TEST(LocalityOrder, NumberingIsABijectionAndKeepsTheMesh)
{
  // faces added in a scrambled order, plus an isolated vertex: the solver's tables are renumbered
  // (locality_order.h) and must describe the same mesh through the solver's index maps
  Mesh m;
  torus_mesh(m, 48, 32);
  Mesh shuffled = scrambled_copy(m, 7);
  const Vertex lonely = shuffled.add_vertex(K::Point_3(9, 9, 9));
  Solver s(shuffled);
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

TEST(LocalityOrder, CoherentNumberingIsKeptAndScatteredOneReplaced)
{
  // a grid written row by row is numbered coherently: the tables keep the mesh's order; the same
  // grid with its faces shuffled is scattered and gets renumbered
  Mesh m;
  grid_disk(m, 40);
  Solver coherent(m);
  ASSERT_TRUE(coherent.is_valid());
  EXPECT_TRUE(coherent.tables().input_face.empty());
  for(auto f : faces(m)) EXPECT_EQ(coherent.face_index(f), std::size_t(f));
  for(auto v : vertices(m)) EXPECT_EQ(coherent.vertex_index(v), std::size_t(v));
  EXPECT_FALSE(SI::numbering_is_scattered(coherent.tables()));
  Mesh s = scrambled_copy(m, 5);
  Solver scattered(s);
  ASSERT_TRUE(scattered.is_valid());
  EXPECT_EQ(scattered.tables().input_face.size(), num_faces(s));
  EXPECT_FALSE(SI::numbering_is_scattered(scattered.tables()));   // renumbered: coherent now
  std::size_t moved = 0;
  for(auto f : faces(s)) moved += scattered.face_index(f) != std::size_t(f) ? 1 : 0;
  EXPECT_GT(moved, num_faces(s) / 2);
}

// =============================================================================================
// CotanWeights (cotan_weights.h)
// =============================================================================================

namespace {
// tables of one triangle (vertices 0, 1, 2; edges 01, 12, 20) with the given coordinates
SI::Mesh_tables one_triangle(const std::vector<double>& points)
{
  SI::Mesh_tables t;
  t.nv = 3; t.nf = 1; t.ne = 3;
  t.points = points;
  t.fv = {0, 1, 2};
  t.fe = {0, 1, 2};
  t.ev = {0, 1, 1, 2, 2, 0};
  SI::finalize_mesh_tables(t);
  return t;
}
} // namespace

TEST(CotanWeights, ValuesClampAndScaleInvariance)
{
  const double h = std::sqrt(3.) / 2;
  SI::Mesh_tables t = one_triangle({0, 0, 0, 1, 0, 0, 0.5, h, 0});
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
  SI::Mesh_tables t = one_triangle({0, 0, 0, 1, 0, 0, 2, 0, 0});   // collinear
  EXPECT_THROW(SI::check_geometry(t), SWN::Invalid_input);
  t.points = {0, 0, 0, 1, 0, 0, 0, NaN, 0};
  EXPECT_THROW(SI::check_geometry(t), SWN::Invalid_input);
}

TEST(CotanWeights, HodgeStarSumsTheWeightsOfAnEdgesSides)
{
  // two equilateral triangles glued along edge 0 (a rhombus) and an edge 5 that no face uses: the
  // shared edge gets 2 x cot 60 / 2, the border edges cot 60 / 2, the bare edge the lower clamp
  const double h = std::sqrt(3.) / 2;
  SI::Mesh_tables t;
  t.nv = 4; t.nf = 2; t.ne = 6;
  t.points = {0, 0, 0, 1, 0, 0, 0.5, h, 0, 0.5, -h, 0};
  t.fv = {0, 1, 2, 1, 0, 3};
  t.fe = {0, 1, 2, 0, 3, 4};
  t.ev = {0, 1, 1, 2, 2, 0, 0, 3, 3, 1, 2, 3};
  SI::finalize_mesh_tables(t);
  ASSERT_EQ(t.arcs.size(), 1u);
  std::vector<double> w;
  EXPECT_EQ(SI::cotan_weights(t, w), 0u);
  const std::vector<double> star = SI::edge_hodge_star(t, w);
  ASSERT_EQ(star.size(), 6u);
  EXPECT_NEAR(star[0], 1 / std::sqrt(3.), 1e-14);
  for(int e = 1; e <= 4; ++e) EXPECT_NEAR(star[e], 0.5 / std::sqrt(3.), 1e-14) << "edge " << e;
  EXPECT_EQ(star[5], SI::min_cotan_weight);
}

TEST(CotanWeights, CotanLaplacianVanishesOnLinearFunctions)
{
  // on a planar mesh: per face, the cotangents sum to (l0^2 + l1^2 + l2^2) / (4 A); at every interior
  // vertex, sum_j w_ij (p_j - p_i) = 0 (the cotan Laplacian reproduces linear functions), wherever no
  // weight was clamped. A jittered triangular lattice: angles 60 degrees give or take 15, no clamping.
  Mesh m;
  const int n = 10;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Vertex> vs;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) vs.push_back(m.add_vertex(K::Point_3(i + 0.5 * j + jitter(rng), (j + jitter(rng)) * std::sqrt(3.) / 2, 0)));
  const auto V = grid_vertex(vs, n);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) { m.add_face(V(i, j), V(i + 1, j), V(i, j + 1)); m.add_face(V(i + 1, j), V(i + 1, j + 1), V(i, j + 1)); }
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  std::vector<double> w;
  SI::cotan_weights(t, w);
  auto clamped = [](double x) { return x == SI::min_cotan_weight || x == SI::max_cotan_weight; };
  std::vector<char> touches_clamped(t.nv, 0);
  std::vector<std::array<double, 2>> laplacian(t.nv, {0., 0.});
  std::size_t faces_checked = 0;
  for(std::size_t f = 0; f < t.nf; ++f)
  {
    double sum_w = 0, sum_l2 = 0;
    bool any_clamped = false;
    for(std::size_t s_ = 3 * f; s_ < 3 * f + 3; ++s_)
    {
      const double *p = t.point(t.tail(s_)), *q = t.point(t.head(s_));
      sum_w += w[s_];
      sum_l2 += (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
      any_clamped = any_clamped || clamped(w[s_]);
      if(clamped(w[s_])) touches_clamped[t.tail(s_)] = touches_clamped[t.head(s_)] = 1;
      for(int d = 0; d < 2; ++d)
      {
        laplacian[t.tail(s_)][d] += w[s_] * (q[d] - p[d]);
        laplacian[t.head(s_)][d] += w[s_] * (p[d] - q[d]);
      }
    }
    if(any_clamped) continue;
    ++faces_checked;
    EXPECT_NEAR(2 * sum_w, sum_l2 / (4 * t.face_area(f)), 1e-10) << "face " << f;
  }
  std::size_t vertices_checked = 0;
  for(std::size_t v = 0; v < t.nv; ++v)
  {
    if(t.vertex_on_border[v] || touches_clamped[v]) continue;
    ++vertices_checked;
    EXPECT_NEAR(laplacian[v][0], 0., 1e-12) << "vertex " << v;
    EXPECT_NEAR(laplacian[v][1], 0., 1e-12) << "vertex " << v;
  }
  EXPECT_EQ(faces_checked, t.nf);
  EXPECT_EQ(vertices_checked, std::size_t((n - 1) * (n - 1)));
}

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

// ASSERTs that order is a permutation of 0 .. n-1
void expect_permutation(std::vector<std::size_t> order, std::size_t n)
{
  std::sort(order.begin(), order.end());
  ASSERT_EQ(order.size(), n);
  for(std::size_t k = 0; k < n; ++k) ASSERT_EQ(order[k], k);
}
} // namespace

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

// =============================================================================================
// Derivatives (derivatives.h): Darboux derivative D, jump derivative J
// =============================================================================================

TEST(Derivatives, DarbouxDerivativeOfAVertexFunctionIsItsDifferential)
{
  // a torus and a disk in one mesh. f = phi(vertex) * s(face), with s = 1 or 3 per face: D f is
  // d phi times the mean of s over the edge's faces; with s = 1 and any per-face constant added, d phi
  // exactly (D does not see jumps); 0 for a constant, and 0 on the edges of excluded vertices
  Mesh m;
  torus_mesh(m, 10, 6);
  grid_disk(m, 5, 2);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  const std::vector<double> phi = random_values(t.nv, 1), offset = random_values(t.nf, 2, -5, 5);
  const std::vector<double> dphi = differential(t, phi);
  const std::vector<char> none(t.nv, 0);
  std::vector<double> f(3 * t.nf), scaled(3 * t.nf);
  for(std::size_t c = 0; c < f.size(); ++c)
  {
    f[c] = phi[t.fv[c]] + offset[c / 3];
    scaled[c] = phi[t.fv[c]] * (c / 3 % 3 == 0 ? 3. : 1.);
  }
  const std::vector<double> omega = SI::darboux_derivative(t, f, none);
  for(std::size_t e = 0; e < t.ne; ++e) EXPECT_NEAR(omega[e], dphi[e], 1e-12) << "edge " << e;
  EXPECT_EQ(max_abs(SI::darboux_derivative(t, std::vector<double>(3 * t.nf, 2.5), none)), 0.);

  const std::vector<double> omega_scaled = SI::darboux_derivative(t, scaled, none);
  for(std::size_t e = 0; e < t.ne; ++e)
  {
    double mean = 0;
    const std::size_t n_sides = t.edge_side_begin[e + 1] - t.edge_side_begin[e];
    for(std::size_t i = t.edge_side_begin[e]; i < t.edge_side_begin[e + 1]; ++i) mean += (t.edge_sides[i] / 3 % 3 == 0 ? 3. : 1.) / double(n_sides);
    EXPECT_NEAR(omega_scaled[e], mean * dphi[e], 1e-12) << "edge " << e;
  }

  std::vector<char> excluded(t.nv, 0);
  excluded[t.ev[0]] = excluded[t.ev[2 * (t.ne - 1)]] = 1;
  const std::vector<double> omega_excluded = SI::darboux_derivative(t, f, excluded);
  std::size_t zeroed = 0;
  for(std::size_t e = 0; e < t.ne; ++e)
  {
    if(excluded[t.ev[2 * e]] || excluded[t.ev[2 * e + 1]]) { EXPECT_EQ(omega_excluded[e], 0.); ++zeroed; }
    else { EXPECT_EQ(omega_excluded[e], omega[e]); }
  }
  EXPECT_GE(zeroed, 6u);
}

TEST(Derivatives, JumpDerivativeOfARegionIndicatorIsItsBoundary)
{
  // f = 1 inside a counter-clockwise loop, 0 outside: J f (left minus right) is the loop's chain, 0 on
  // border edges; a vertex function has no jump; the jump at either end of an arc is left minus right
  const int n = 8;
  const Grid_tables g(n, 4);
  const SI::Mesh_tables& t = g.tables();
  const std::vector<double> loop = g.chain({square_loop(g.vs, n, 2, 1, 6, 5)});
  std::vector<double> inside(t.nf);
  const std::vector<char> in = faces_in_rect(t, 2. / n, 1. / n, 6. / n, 5. / n);
  for(std::size_t f = 0; f < t.nf; ++f) inside[f] = in[f];
  EXPECT_EQ(std::count(in.begin(), in.end(), 1), 2 * 4 * 4);
  EXPECT_EQ(SI::jump_derivative(t, per_corner(inside)), loop);
  EXPECT_EQ(SI::jump_derivative(t, negated(per_corner(inside))), negated(loop));

  const std::vector<double> phi = random_values(t.nv, 3);
  std::vector<double> single_valued(3 * t.nf), f = random_values(3 * t.nf, 4);
  for(std::size_t c = 0; c < single_valued.size(); ++c) single_valued[c] = phi[t.fv[c]];
  EXPECT_EQ(max_abs(SI::jump_derivative(t, single_valued)), 0.);
  const std::vector<double> Jf = SI::jump_derivative(t, f);
  for(std::size_t a = 0; a < t.arcs.size(); ++a)
  {
    const SI::Arc& arc = t.arcs[a];
    double J[2];
    for(int k = 0; k < 2; ++k)
    {
      const std::size_t v = t.ev[2 * arc.edge + k];
      J[k] = f[corner_of(t, arc.left_side / 3, v)] - f[corner_of(t, arc.right_side / 3, v)];
      EXPECT_EQ(SI::corner_jump_at(t, f, a, k), J[k]);
    }
    EXPECT_DOUBLE_EQ(Jf[arc.edge], 0.5 * (J[0] + J[1]));
  }
  for(std::size_t e = 0; e < t.ne; ++e)
    if(t.edge_on_border[e]) EXPECT_EQ(Jf[e], 0.);
}

// =============================================================================================
// HarmonicPart (harmonic_part.h)
// =============================================================================================

namespace {
// the period of a 1-form (per table edge) along a closed vertex loop
double period(const Mesh& m, const Solver& s, const std::vector<Vertex>& loop, const std::vector<double>& form)
{
  double sum = 0;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const auto h = halfedge(loop[i], loop[(i + 1) % loop.size()], m);
    if(!h.second)
    {
      ADD_FAILURE() << "consecutive loop vertices are not joined by an edge";
      return NaN;   // fails every comparison that follows
    }
    const std::size_t e = s.edge_index(edge(h.first, m));
    sum += (s.tables().ev[2 * e] == s.vertex_index(loop[i]) ? 1. : -1.) * form[e];
  }
  return sum;
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

// both Hodge projections of a mesh: the harmonic basis (with the 0-form Laplacian it needs) and
// the 2-form Laplacian; `star` and the cotan weights `w` of the tables
struct Hodge_projections
{
  std::vector<double> w, star;
  SI::Cohomology_generators gen;
  SI::Jump_laplace_system<LA> L0;   // nothing excluded: the 0-form Laplacian
  SI::Harmonic_basis<LA> basis;
  SI::Two_form_laplacian<LA> B;
  explicit Hodge_projections(const SI::Mesh_tables& t)
  {
    SI::cotan_weights(t, w);
    star = SI::edge_hodge_star(t, w);
    gen = SI::cohomology_generators(t);
    L0.jump_laplacian(t, w, std::vector<char>(t.nv, 0));
    basis.assemble(t, star, gen, L0);   // throws if the Gram matrix of the h_k is singular
    B.assemble(t, star);
  }
};
} // namespace

TEST(HarmonicPart, GammaIsClosedToRoundOffAndKeepsThePeriod)
{
  const int nu = 24, nv = 12;
  const Torus_tables torus(nu, nv);
  const SI::Mesh_tables& t = torus.tables();
  const std::vector<Vertex>& vs = torus.vs;
  // a meridian with a 2-edge gap
  const std::vector<double> chain = torus.chain({meridian_piece(vs, nv, 3, 0, 4), meridian_piece(vs, nv, 3, 6, nv)});
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
  const double p = period(torus.mesh, *torus.solver, longitude, gamma);
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
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 2u);
  const Hodge_projections hodge(t);
  const SI::Cohomology_generators& gen = hodge.gen;
  EXPECT_TRUE(gen.complete);
  ASSERT_EQ(gen.size(), 5u);
  std::vector<std::size_t> classes(2, 0);
  for(std::size_t e : gen.edges) ++classes[t.face_component[t.edge_sides[t.edge_side_begin[e]] / 3]];
  EXPECT_EQ(classes[t.face_component[0]], 2u);
  EXPECT_EQ(classes[1 - t.face_component[0]], 3u);
  ASSERT_TRUE(hodge.basis.assembled());
  const std::vector<Vertex> meridian = meridian_piece(vs, nv, 3, 0, nv - 1);
  std::vector<Vertex> longitude;
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
    const std::vector<double> h = hodge.basis.harmonic_part(zeta);
    EXPECT_LT(max_abs(SI::face_curl(t, h)), 1e-12);
    EXPECT_LT(max_abs(codifferential(t, hodge.star, h)), 1e-10);
    const std::vector<double> hh = hodge.basis.harmonic_part(h);
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

TEST(HarmonicPart, ExactAndCoexactFormsHaveNoHarmonicPart)
{
  // the Hodge decomposition on a torus: an exact form d phi, a coexact form S1^-1 d1^T beta and a
  // harmonic form h. The projection on the harmonic basis keeps h only; the 2-form Laplacian removes
  // the coexact part only (the exact part of a Darboux derivative is zero, App. A)
  const Torus_tables torus(16, 9);
  const SI::Mesh_tables& t = torus.tables();
  const Hodge_projections hodge(t);
  const std::vector<double> exact = differential(t, random_values(t.nv, 6));
  const std::vector<double> beta = random_values(t.nf, 7);
  std::vector<double> coexact(t.ne, 0.), zeta(t.ne, 0.);
  for(std::size_t side = 0; side < 3 * t.nf; ++side) coexact[t.fe[side]] += t.fs[side] * beta[side / 3] / hodge.star[t.fe[side]];
  for(const auto& z : hodge.gen.closed_form(t, 0)) zeta[z.first] = z.second;
  const std::vector<double> h = hodge.basis.harmonic_part(zeta);
  EXPECT_GT(max_abs(h), 0.01);
  EXPECT_GT(max_abs(SI::face_curl(t, coexact)), 0.1);

  EXPECT_LT(max_abs(hodge.basis.harmonic_part(exact)), 1e-9);
  EXPECT_LT(max_abs(hodge.basis.harmonic_part(coexact)), 1e-9);
  const std::vector<double> exact_by_B = hodge.B.harmonic_part(exact);   // closed: nothing to remove
  for(std::size_t e = 0; e < t.ne; ++e) EXPECT_NEAR(exact_by_B[e], exact[e], 1e-12) << "edge " << e;
  EXPECT_LT(max_abs(hodge.B.harmonic_part(coexact)), 1e-9);
  std::vector<double> sum(t.ne);
  for(std::size_t e = 0; e < t.ne; ++e) sum[e] = exact[e] + coexact[e] + h[e];
  const std::vector<double> by_basis = hodge.basis.harmonic_part(sum), by_B = hodge.B.harmonic_part(sum);
  for(std::size_t e = 0; e < t.ne; ++e)
  {
    EXPECT_NEAR(by_basis[e], h[e], 1e-9) << "edge " << e;
    EXPECT_NEAR(by_B[e], exact[e] + h[e], 1e-9) << "edge " << e;
  }
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
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  std::vector<Vertex> a = meridian_piece(vs, nv, 2, 0, 6), loop;
  for(int i = 5; i <= 9; ++i) loop.push_back(vs[std::size_t(i * nv + 1)]);
  for(int j = 2; j <= 4; ++j) loop.push_back(vs[std::size_t(9 * nv + j)]);
  const std::vector<double> chain = table_chain(m, s, {a, loop});
  const Hodge_projections hodge(t);
  std::vector<double> w;
  const std::vector<double> omega = omega_of_chain(t, chain, w);
  ASSERT_TRUE(hodge.gen.complete);
  EXPECT_EQ(hodge.gen.size(), 2u);
  const std::vector<double> g1 = hodge.B.harmonic_part(omega), g2 = hodge.basis.harmonic_part(omega);
  EXPECT_GT(max_abs(g1), 0.01);
  for(std::size_t e = 0; e < t.ne; ++e) EXPECT_NEAR(g1[e], g2[e], 1e-9);
  EXPECT_LT(max_abs(SI::face_curl(t, g2)), 1e-12);
}

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
// WindingNumber (winding_number.h): shift tau, rounding, normalization, bounding chain, second-solve jumps
// =============================================================================================

TEST(WindingNumber, ShiftTauMakesTheHigherSideOfTheCurveIntegral)
{
  // w = x on the faces inside a counter-clockwise loop (its left, higher side), another fractional
  // part outside: x + tau is the nearest integer to x. Reversed, the loop's higher side is the outside.
  const int n = 8;
  const Grid_tables g(n, 1, 0.);
  const SI::Mesh_tables& t = g.tables();
  const std::vector<double> loop = g.chain({square_loop(g.vs, n, 2, 2, 6, 5)}), reversed = negated(loop);
  const std::vector<char> inside = faces_in_rect(t, 2. / n, 2. / n, 6. / n, 5. / n);
  auto w = [&](double in, double out) {
    std::vector<double> per_face(t.nf);
    for(std::size_t f = 0; f < t.nf; ++f) per_face[f] = inside[f] ? in : out;
    return per_corner(per_face);
  };
  for(double x : {0.3, 0.7, -0.2, 2.45, -1.49})
  {
    const double other = x - 1 + 0.37;
    const std::vector<double> tau = SI::shift_tau(t, loop, w(x, other));
    ASSERT_EQ(tau.size(), 1u);
    EXPECT_NEAR(tau[0], std::round(x) - x, 1e-12) << "x = " << x;
    EXPECT_NEAR(SI::shift_tau(t, reversed, w(other, x))[0], std::round(x) - x, 1e-12) << "x = " << x;
    EXPECT_NEAR(SI::shift_tau(t, reversed, w(x, other))[0], std::round(other) - other, 1e-12) << "x = " << x;
  }
  // no curve: no shift
  EXPECT_EQ(SI::shift_tau(t, std::vector<double>(t.ne, 0.), w(0.3, 0.3)), std::vector<double>(1, 0.));
}

TEST(WindingNumber, ShiftTauIsACircularMeanPerComponent)
{
  // three grids in one mesh, a chord upwards across the first two. Per curve edge, w+ (on the left,
  // higher side) is 0.45 and 1.55 in turn on the first grid: fractional parts straddling 1/2, which
  // the paper's mean of round(w+) - w+ cancels (tau = 0, every w+ 0.45 from an integer) and whose
  // circular mean is 1/2 (every w+ + tau within 0.05 of an integer). On the second grid w+ = 0.8 + k
  // (undefined on one edge): tau = 0.2. The third grid has no curve: tau = 0.
  Mesh m;
  const int n = 8;
  std::vector<std::vector<Vertex>> grids;
  for(unsigned k = 0; k < 3; ++k) grids.push_back(grid_disk(m, n, k + 1, 0.));
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 3u);
  const std::vector<double> chain = table_chain(m, s, {grid_column(grids[0], n, 4, 0, n), grid_column(grids[1], n, 4, 0, n)});
  std::vector<std::size_t> component(3);
  for(std::size_t k = 0; k < 3; ++k) component[k] = t.face_component[s.face_index(Mesh::Face_index(2 * n * n * k))];
  std::vector<double> w(3 * t.nf, NaN);
  std::vector<std::vector<double>> w_plus(3);
  for(const SI::Arc& arc : t.arcs)
  {
    const double G = chain[arc.edge];
    if(G == 0) continue;
    const std::size_t side = G > 0 ? arc.left_side : arc.right_side;
    ASSERT_TRUE(std::isnan(w[side]) && std::isnan(w[SI::Mesh_tables::next_in_face(side)])) << "a face with two curve sides";
    const std::size_t grid = t.face_component[side / 3] == component[0] ? 0 : 1;
    const std::size_t k = w_plus[grid].size();
    const double value = grid == 0 ? (k % 2 ? 1.55 : 0.45) : (k == 0 ? NaN : 0.8 + double(k));
    w_plus[grid].push_back(value);
    w[side] = w[SI::Mesh_tables::next_in_face(side)] = value;
  }
  ASSERT_EQ(w_plus[0].size(), std::size_t(n));
  ASSERT_EQ(w_plus[1].size(), std::size_t(n));
  const std::vector<double> tau = SI::shift_tau(t, chain, w);
  ASSERT_EQ(tau.size(), 3u);
  EXPECT_NEAR(std::abs(tau[component[0]]), 0.5, 1e-12);
  double paper_tau = 0;
  for(double x : w_plus[0]) paper_tau += (std::round(x) - x) / double(n);
  EXPECT_NEAR(paper_tau, 0., 1e-12);
  for(double x : w_plus[0])
  {
    EXPECT_LE(std::abs(x + tau[component[0]] - std::round(x + tau[component[0]])), 0.05 + 1e-9) << x;
    EXPECT_GE(std::abs(x + paper_tau - std::round(x + paper_tau)), 0.45 - 1e-9) << x;
  }
  EXPECT_NEAR(tau[component[1]], 0.2, 1e-12);
  EXPECT_EQ(tau[component[2]], 0.);
}

TEST(WindingNumber, RoundLabelsAverageTheDefinedCornersPlusTau)
{
  // a 4 x 4 grid (tau = 0.25) and a lone triangle (tau = 0). Labels: the mean of the defined corners
  // plus tau, rounded half away from zero; a face without a defined corner takes its neighbours'
  // label (two such faces side by side: both), the lone triangle without one stays 0
  EXPECT_EQ(SI::round_half_away(0.5), 1);
  EXPECT_EQ(SI::round_half_away(-0.5), -1);
  EXPECT_EQ(SI::round_half_away(2.5), 3);
  EXPECT_EQ(SI::round_half_away(-2.5), -3);
  EXPECT_EQ(SI::round_half_away(0.49999999999999994), 0);
  Mesh m;
  grid_disk(m, 4, 1, 0.);
  m.add_face(m.add_vertex(K::Point_3(5, 5, 0)), m.add_vertex(K::Point_3(6, 5, 0)), m.add_vertex(K::Point_3(5, 6, 0)));
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 2u);
  ASSERT_TRUE(t.input_face.empty());
  const std::size_t lone = t.nf - 1, undefined[2] = {18, 19};   // faces 18 and 19: the two halves of cell (1, 2)
  std::vector<double> tau(2, 0.);
  tau[t.face_component[0]] = 0.25;
  std::vector<double> w(3 * t.nf, 0.);   // label 0 unless set below
  std::vector<int> expected(t.nf, 0);
  for(std::size_t f : undefined)
    for(std::size_t c = 3 * f; c < 3 * f + 3; ++c) w[c] = NaN;
  auto is_undefined = [&](std::size_t f) { return f == undefined[0] || f == undefined[1]; };
  for(const SI::Arc& arc : t.arcs)   // the neighbours of faces 18 and 19: label 4
  {
    const std::size_t L = arc.left_side / 3, R = arc.right_side / 3;
    for(const auto& fo : {std::make_pair(L, R), std::make_pair(R, L)})
      if(!is_undefined(fo.first) && is_undefined(fo.second))
      {
        for(std::size_t c = 3 * fo.first; c < 3 * fo.first + 3; ++c) w[c] = 4.;
        expected[fo.first] = 4;
      }
  }
  expected[undefined[0]] = expected[undefined[1]] = 4;
  const std::vector<std::pair<std::array<double, 3>, int>> faces = {
    {{0.1, 0.2, 0.45}, 1},     // 0.25 + 0.25 = 0.5 -> 1
    {{-0.75, -0.75, -0.75}, -1},   // -0.5 -> -1
    {{NaN, 1.4, 1.8}, 2},      // 1.6 + 0.25 (the undefined corner is not a 0)
    {{2.1, NaN, NaN}, 2}};     // 2.35
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    ASSERT_NE(expected[f], 4) << "test bug: face " << f << " is next to the undefined faces";
    for(int k = 0; k < 3; ++k) w[3 * f + k] = faces[f].first[k];
    expected[f] = faces[f].second;
  }
  for(std::size_t c = 3 * lone; c < 3 * lone + 3; ++c) w[c] = NaN;
  EXPECT_EQ(SI::round_labels(t, w, tau), expected);
}

TEST(WindingNumber, NormalizationZeroesTheLabelOfLargestAreaInEveryComponent)
{
  // four 4 x 4 grids (faces of area 1/32 each, exact). Grid 0: labels 3 (8 faces) and 5 (24): 5
  // becomes 0. Grid 1: -2 and 1 on 16 faces each, a tie: the smaller magnitude 1 becomes 0. Grid 2:
  // -1 and 1 tied: the smaller, -1. Grid 3 stretched by x -> x^3: 7 on its right column (8 faces, 37/64
  // of the area) beats 4 on the other 24 faces.
  Mesh m;
  const int n = 4;
  std::vector<std::vector<Vertex>> grids;
  for(int k = 0; k < 4; ++k) grids.push_back(grid_disk(m, n, unsigned(k + 1), 0.));
  for(Vertex v : grids[3]) m.point(v) = K::Point_3(std::pow(m.point(v).x(), 3), m.point(v).y(), 0);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_EQ(t.n_components, 4u);
  ASSERT_TRUE(t.input_face.empty());
  std::vector<int> W(t.nf);
  for(std::size_t f = 0; f < t.nf; ++f)
  {
    const std::size_t grid = f / (2 * n * n), row = f % (2 * n * n) / (2 * n), column = f % (2 * n) / 2;
    ASSERT_EQ(t.face_component[f], grid);
    const int labels[4][2] = {{3, 5}, {-2, 1}, {-1, 1}, {7, 4}};
    const bool first = grid == 0 ? row == 0 : grid == 3 ? column == 3 : row < 2;
    W[f] = labels[grid][first ? 0 : 1];
  }
  const std::vector<int> offset = {5, 1, -1, 7};
  std::vector<int> normalized = W;
  EXPECT_EQ(SI::normalize_labels(t, normalized), offset);
  for(std::size_t f = 0; f < t.nf; ++f) EXPECT_EQ(normalized[f], W[f] - offset[t.face_component[f]]);
  // normalized labels are normalized
  std::vector<int> again = normalized;
  EXPECT_EQ(SI::normalize_labels(t, again), std::vector<int>(4, 0));
  EXPECT_EQ(again, normalized);
}

TEST(WindingNumber, BoundingChainIsTheClosedJumpOfTheLabels)
{
  // on a disk, labels 1 inside a counter-clockwise loop (-1 inside its reverse): the bounding chain is
  // the loop. On a torus, labels -1 on the band between an upward meridian and a downward one: the two
  // meridians. Any labels: a chain closed relative to the border, zero on border edges.
  Mesh m;
  const int n = 8;
  const auto vs = grid_disk(m, n, 6);
  const int nu = 12, nv = 6;
  const auto tv = torus_mesh(m, nu, nv);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  ASSERT_TRUE(t.input_face.empty());
  const std::vector<double> loop = table_chain(m, s, {square_loop(vs, n, 1, 2, 5, 7)});
  const std::vector<char> inside = faces_in_rect(t, 1. / n, 2. / n, 5. / n, 7. / n);
  std::vector<int> W(t.nf, 0);
  for(std::size_t f = 0; f < 2 * n * n; ++f) W[f] = inside[f];   // the grid's faces come first
  std::vector<int> loop_chain(loop.begin(), loop.end());
  EXPECT_EQ(SI::bounding_chain(t, W), loop_chain);
  for(int& l : W) l = -l;
  for(int& x : loop_chain) x = -x;
  EXPECT_EQ(SI::bounding_chain(t, W), loop_chain);

  std::vector<Vertex> down = meridian_piece(tv, nv, 7, 0, nv);
  std::reverse(down.begin(), down.end());
  const std::vector<double> band = table_chain(m, s, {meridian_piece(tv, nv, 3, 0, nv), down});
  std::fill(W.begin(), W.end(), 0);
  for(std::size_t f = 2 * n * n; f < t.nf; ++f)
  {
    const std::size_t i = (f - 2 * n * n) / 2 / nv;   // the torus's cell (i, j)
    W[f] = i >= 3 && i < 7 ? -1 : 0;
  }
  EXPECT_EQ(SI::bounding_chain(t, W), std::vector<int>(band.begin(), band.end()));

  std::mt19937 rng(14);
  std::uniform_int_distribution<int> label(-3, 3);
  for(int& l : W) l = label(rng);
  const std::vector<int> B = SI::bounding_chain(t, W);
  EXPECT_TRUE(SI::is_relatively_closed(t, B));
  for(std::size_t e = 0; e < t.ne; ++e)
    if(t.edge_on_border[e]) EXPECT_EQ(B[e], 0) << "edge " << e;
  for(const SI::Arc& arc : t.arcs) EXPECT_EQ(B[arc.edge], W[arc.left_side / 3] - W[arc.right_side / 3]);
}

TEST(WindingNumber, SecondSolveJumpsAreGammaLessJvAndCloseAroundEveryVertex)
{
  // an open path and a loop crossing it, any residual v: at the curve's vertices the jumps are
  // Gamma - J v (measured there), elsewhere 0; they sum to zero around every vertex where the chain
  // is closed, so reduced coordinates realise them on every arc off the interior endpoints
  const Grid_tables g(12, 3);
  const SI::Mesh_tables& t = g.tables();
  const std::vector<double> chain = g.chain({grid_column(g.vs, g.n, 5, 1, 10), square_loop(g.vs, g.n, 2, 2, 8, 7)});
  const std::vector<char> endpoint = SI::interior_endpoints(t, chain);
  EXPECT_EQ(std::count(endpoint.begin(), endpoint.end(), 1), 2);
  const std::vector<double> v = random_values(3 * t.nf, 15);
  const std::vector<double> jump = SI::second_solve_jumps(t, chain, v);
  ASSERT_EQ(jump.size(), 2 * t.arcs.size());
  std::vector<char> on_curve(t.nv, 0);
  for(std::size_t e = 0; e < t.ne; ++e)
    if(chain[e] != 0) on_curve[t.ev[2 * e]] = on_curve[t.ev[2 * e + 1]] = 1;
  const std::vector<double> c = SI::reduced_coordinates(t, jump, endpoint);
  std::size_t checked = 0;
  for(std::size_t a = 0; a < t.arcs.size(); ++a)
    for(int k = 0; k < 2; ++k)
    {
      const std::size_t x = t.ev[2 * t.arcs[a].edge + k];
      if(on_curve[x]) EXPECT_NEAR(jump[2 * a + k] + SI::corner_jump_at(t, v, a, k), chain[t.arcs[a].edge], 1e-14);
      else EXPECT_EQ(jump[2 * a + k], 0.);
      if(endpoint[x]) continue;
      ++checked;
      EXPECT_NEAR(SI::corner_jump_at(t, c, a, k), jump[2 * a + k], 1e-12) << "arc " << a << ", end " << k;
    }
  EXPECT_GT(checked, t.arcs.size());
}

// =============================================================================================
// NonboundingChain (nonbounding_chain.h)
// =============================================================================================

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

#ifdef CGAL_USE_GLPK
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
#endif

// a torus_mesh(9, 7) and a grid_disk(6) in one mesh, with a meridian of the torus (the input
// curve of the nonbounding chain tests)
struct Meridian_on_torus_and_disk
{
  Mesh m;
  std::vector<Vertex> tv, dv;
  std::unique_ptr<Solver> s;
  std::vector<double> meridian;
  Meridian_on_torus_and_disk()
  {
    tv = torus_mesh(m, 9, 7);
    dv = grid_disk(m, 6, 3);
    s.reset(new Solver(m));
    EXPECT_TRUE(s->is_valid()) << s->report().error;
    EXPECT_EQ(s->tables().n_components, 2u);
    meridian = table_chain(m, *s, {meridian_piece(tv, 7, 3, 0, 7)});
  }
  const SI::Mesh_tables& tables() const { return s->tables(); }
};
} // namespace

TEST(NonboundingChain, RoundingKeepsClosedChainsAndClosesBrokenOnes)
{
  // G = round(g) half away from zero when that is closed: the meridian for g = the meridian or 0.7
  // times it, nothing for 0.3 times it. A meridian edge at 0.4 rounds to an open chain: the cheapest
  // closing puts the edge back. A chord across the disk whose first edge, at the border, is at 0.3:
  // closed relative to the border once that edge is back, not before.
  EXPECT_EQ(SI::rounded_chain({0.5, -0.5, 1.49, -1.5, 0.49, 0.}), (std::vector<int>{1, -1, 1, -2, 0, 0}));
  const Meridian_on_torus_and_disk mesh;
  const SI::Mesh_tables& t = mesh.tables();
  const std::vector<int> meridian(mesh.meridian.begin(), mesh.meridian.end());
  for(double scale : {1., 0.7, 0.3})
  {
    std::vector<double> g = mesh.meridian;
    for(double& x : g) x *= scale;
    std::size_t units = 99;
    EXPECT_EQ(SI::nonbounding_chain(t, g, mesh.meridian, &units), scale > 0.5 ? meridian : std::vector<int>(t.ne, 0)) << scale;
    EXPECT_EQ(units, 0u);
  }
  std::vector<double> g = mesh.meridian;
  const std::size_t broken = std::size_t(std::find_if(g.begin(), g.end(), [](double x) { return x != 0; }) - g.begin());
  g[broken] *= 0.4;
  EXPECT_FALSE(SI::is_relatively_closed(t, SI::rounded_chain(g)));
  std::size_t units = 0;
  EXPECT_EQ(SI::nonbounding_chain(t, g, mesh.meridian, &units), meridian);
  EXPECT_EQ(units, 1u);

  const std::vector<double> chord = table_chain(mesh.m, *mesh.s, {grid_column(mesh.dv, 6, 2, 0, 6)});
  const std::vector<int> chord_chain(chord.begin(), chord.end());
  EXPECT_TRUE(SI::is_relatively_closed(t, chord_chain));
  std::vector<double> g_chord = chord;
  const Vertex bottom = grid_vertex(mesh.dv, 6)(2, 0), above = grid_vertex(mesh.dv, 6)(2, 1);
  const std::size_t first_edge = mesh.s->edge_index(edge(halfedge(bottom, above, mesh.m).first, mesh.m));
  ASSERT_NE(chord[first_edge], 0.);
  g_chord[first_edge] *= 0.3;
  EXPECT_FALSE(SI::is_relatively_closed(t, SI::rounded_chain(g_chord)));
  EXPECT_EQ(SI::nonbounding_chain(t, g_chord, chord, &units), chord_chain);
  EXPECT_EQ(units, 1u);
}

#ifdef CGAL_USE_GLPK
// G (paper Sec. 3.6): round(g) where that is closed, otherwise the closed integer chain nearest to
// g, checked against a network linear program on a torus and a disk (border) in one mesh.
TEST(NonboundingChain, ClosesRoundingAtTheLeastCost)
{
  const Meridian_on_torus_and_disk mesh;
  const SI::Mesh_tables& t = mesh.tables();
  // a meridian of the torus: the input curve, and the integer closed chain g is a perturbation of
  const std::vector<double>& C = mesh.meridian;

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
#endif

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

namespace {
// labels and G of one solve, by the solver class or by the free function, to compare
struct Labels_and_G
{
  std::map<Mesh::Face_index, int> labels;
  std::map<Mesh::Edge_index, int> G;
  template <class Chain, class NP = decltype(CGAL::parameters::default_values())>
  bool solve(Solver& solver, const Chain& chain, const NP& np = CGAL::parameters::default_values())
  {
    return solver.solve(chain, boost::make_assoc_property_map(labels),
                        SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G), np));
  }
  template <class Chain>
  bool solve(const Mesh& m, const Chain& chain)
  {
    return CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(labels),
                                         SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G)));
  }
  void expect_equal(const Labels_and_G& other) const
  {
    EXPECT_EQ(labels, other.labels);
    EXPECT_EQ(G, other.G);
  }
};
} // namespace

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
