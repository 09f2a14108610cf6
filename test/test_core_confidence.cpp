// The benchmark's per-region confidence (benchmark/bench_confidence.h) on analytic cases: flipping a
// region bounded by complete input loops costs epsilon times their length in Eq. 11, in the one
// direction that keeps G within the input's bounds.
#include "test_core_support.h"

#include <CGAL/Polygon_mesh_processing/measure.h>

#include "../benchmark/bench_confidence.h"

namespace {

namespace SB = swn_bench;

struct Confidence_case
{
  std::vector<double> chain;
  std::vector<long> G;
  std::vector<int> W;
  std::vector<double> area;
};

// solves `polylines` on the mesh of `s` and returns everything per table index
Confidence_case solve_case(Mesh& m, Solver& s, const std::vector<std::vector<Vertex>>& polylines)
{
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:c", 0).first;
  auto W = m.add_property_map<Mesh::Face_index, int>("f:W", 0).first;
  auto G = m.add_property_map<Mesh::Edge_index, int>("e:G", 0).first;
  for(const auto& p : polylines) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
  EXPECT_TRUE(s.solve(chain, W, SWN::parameters::nonbounding_chain_map(G)));
  const SI::Mesh_tables& t = s.tables();
  Confidence_case c;
  c.chain.assign(t.ne, 0.);
  c.G.assign(t.ne, 0);
  c.W.assign(t.nf, 0);
  c.area.assign(t.nf, 0.);
  for(auto e : edges(m)) { c.chain[s.edge_index(e)] = chain[e]; c.G[s.edge_index(e)] = G[e]; }
  for(auto f : faces(m))
  {
    c.W[s.face_index(f)] = W[f];
    c.area[s.face_index(f)] = CGAL::Polygon_mesh_processing::face_area(f, m);
  }
  m.remove_property_map(chain);
  m.remove_property_map(W);
  m.remove_property_map(G);
  return c;
}

// epsilon times the length of the edges where x is nonzero, in mean interior edge lengths
double input_cost(const SI::Mesh_tables& t, const std::vector<double>& x, double epsilon)
{
  double len = 0;
  for(std::size_t e = 0; e < t.ne; ++e)
    if(x[e] != 0) len += t.edge_length(e);
  return epsilon * len / SB::mean_interior_edge_length(t);
}

// the input is J W + G on every interior edge (the decomposition the flips keep)
void expect_decomposition(const SI::Mesh_tables& t, const Confidence_case& c)
{
  for(const SI::Arc& a : t.arcs)
    EXPECT_EQ(std::lround(c.chain[a.edge]), long(c.W[a.left_side / 3]) - long(c.W[a.right_side / 3]) + c.G[a.edge])
        << "edge " << a.edge;
}

} // namespace

TEST(Confidence, RegionInsideACompleteLoopOnATorusCostsEpsilonTimesItsLength)
{
  Mesh m;
  const int nu = 24, nv = 12;
  const auto vs = torus_mesh(m, nu, nv);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  const std::vector<Vertex> meridian = meridian_piece(vs, nv, 3, 0, nv);
  const std::vector<Vertex> rect = rect_loop(torus_vertex(vs, nv), 10, 2, 14, 6);
  const Confidence_case c = solve_case(m, s, {meridian, rect});
  expect_decomposition(t, c);
  const std::vector<double> weight = SB::eq11_weights(t, c.chain, 0.01);
  const SB::Cells cells = SB::label_cells(t, c.chain, c.G, c.W, c.area);
  ASSERT_EQ(cells.area.size(), 2u);   // the 4 x 4 cells inside the rectangle, and the rest
  const std::size_t inside = cells.area[0] < cells.area[1] ? 0 : 1;
  std::size_t n_inside = 0;
  for(std::size_t f = 0; f < t.nf; ++f) n_inside += cells.of_face[f] == inside;
  EXPECT_EQ(n_inside, 32u);

  const std::vector<SB::Flip> flips = SB::flip_costs(t, cells, c.chain, c.G, weight);
  const double expected = input_cost(t, table_chain(m, s, {rect}), 0.01);
  EXPECT_NEAR(flips[inside].cost, expected, 1e-9 * expected);
  EXPECT_NEAR(flips[1 - inside].cost, expected, 1e-9 * expected);   // the complement: the same move
  // only the flip that empties the rectangle keeps G along the input's direction
  std::size_t f_in = 0;
  while(cells.of_face[f_in] != inside) ++f_in;
  std::size_t f_out = 0;
  while(cells.of_face[f_out] == inside) ++f_out;
  EXPECT_EQ(c.W[f_in] + flips[inside].delta, c.W[f_out]);
  // the boundary: the rectangle's length in mean interior edge lengths
  EXPECT_NEAR(flips[inside].boundary, expected / 0.01, 1e-9 * expected / 0.01);
}

TEST(Confidence, BandBetweenTwoOppositeMeridiansFlipsIntoTwoNonboundingLoops)
{
  Mesh m;
  const int nu = 20, nv = 10;
  const auto vs = torus_mesh(m, nu, nv);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  const std::vector<Vertex> a = meridian_piece(vs, nv, 3, 0, nv);
  std::vector<Vertex> b = meridian_piece(vs, nv, 9, 0, nv);
  std::reverse(b.begin(), b.end());
  const Confidence_case c = solve_case(m, s, {a, b});
  expect_decomposition(t, c);
  for(long g : c.G) EXPECT_EQ(g, 0);   // the two loops bound the band
  const std::vector<double> weight = SB::eq11_weights(t, c.chain, 0.01);
  const SB::Cells cells = SB::label_cells(t, c.chain, c.G, c.W, c.area);
  ASSERT_EQ(cells.area.size(), 2u);
  const std::vector<SB::Flip> flips = SB::flip_costs(t, cells, c.chain, c.G, weight);
  const double expected = input_cost(t, c.chain, 0.01);   // both meridians become G
  for(std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(flips[k].cost, expected, 1e-9 * expected);
  // applying the flip: the labels become constant and G the input itself
  std::vector<int> W2 = c.W;
  for(std::size_t f = 0; f < t.nf; ++f)
    if(cells.of_face[f] == 0) W2[f] += flips[0].delta;
  for(std::size_t f = 1; f < t.nf; ++f) EXPECT_EQ(W2[f], W2[0]);
}

TEST(Confidence, HintsRelabelARegionAndRedrawTheMissingRunNextToTheError)
{
  Mesh m;
  const int n = 12;
  const auto vs = grid_disk(m, n, 3);
  Solver s(m);
  const SI::Mesh_tables& t = s.tables();
  const auto at = grid_vertex(vs, n);
  const std::vector<Vertex> left = rect_loop(at, 1, 1, 4, 4), right = rect_loop(at, 7, 7, 10, 10);
  const std::vector<double> full_d = table_chain(m, s, {left, right});
  std::vector<long> full(t.ne);
  for(std::size_t e = 0; e < t.ne; ++e) full[e] = std::lround(full_d[e]);
  // the input misses two edges of the left square and three of the right one
  std::vector<Vertex> left_broken(left.begin() + 2, left.end()), right_broken(right.begin() + 3, right.end());
  const std::vector<double> chain = table_chain(m, s, {left_broken, right_broken});
  const std::vector<char> inside_left = faces_in_rect(t, 1. / n, 1. / n, 4. / n, 4. / n);
  const std::vector<char> inside_right = faces_in_rect(t, 7. / n, 7. / n, 10. / n, 10. / n);
  std::vector<double> area(t.nf, 1.);
  // with the faces of the right square marked wrong, the hint redraws the right square's gap
  const std::vector<std::size_t> run = SB::missing_run_hint(t, full, chain, inside_right, area);
  ASSERT_EQ(run.size(), 3u);
  for(std::size_t e : run) EXPECT_TRUE(full[e] != 0 && chain[e] == 0);
  for(std::size_t e : SB::missing_run_hint(t, full, chain, inside_left, area)) EXPECT_EQ(run.end(), std::find(run.begin(), run.end(), e));
  EXPECT_EQ(SB::missing_run_hint(t, full, full_d, inside_left, area).size(), 0u);

  // labels: the left square right, the right one missed; one cell each; the hint on the right cell
  std::vector<int> gt(t.nf, 0), W(t.nf, 0);
  for(std::size_t f = 0; f < t.nf; ++f)
  {
    gt[f] = inside_left[f] || inside_right[f] ? 1 : 0;
    W[f] = inside_left[f] ? 1 : 0;
  }
  const std::vector<long> G(t.ne, 0);
  const SB::Cells cells = SB::label_cells(t, full_d, G, W, area);
  std::size_t right_cell = 0;
  while(!inside_right[right_cell]) ++right_cell;
  const std::vector<int> fixed = SB::relabel_cell(t, cells, cells.of_face[right_cell], area, W, gt);
  EXPECT_EQ(fixed, gt);
}
