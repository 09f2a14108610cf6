// test_core: the flat tables and what is built on them (MeshTables, UnionFind, LocalityOrder, CotanWeights).
#include "test_core_support.h"

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
    EXPECT_EQ(t.point(i)[0], t.point_scale * shuffled.point(v).x());   // scaling by a power of two is exact
    EXPECT_EQ(t.point(i)[2], t.point_scale * shuffled.point(v).z());
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

