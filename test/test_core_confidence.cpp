// The library's per-region confidence (internal/confidence.h, named parameters label_confidence,
// confidence_map, region_map, second_best_label_map) on analytic cases: flipping a region bounded by
// complete input loops costs epsilon times their length in Eq. 11, in the one direction that keeps G
// within the input's bounds; a region between two loops that bound it from both sides cannot flip. And
// the benchmark's simulated hints (benchmark/bench_confidence.h) on top of the regions.
#include "test_core_support.h"

#include <CGAL/Polygon_mesh_processing/measure.h>

#include "../benchmark/bench_confidence.h"

namespace {

namespace SB = swn_bench;

// a solve of `polylines` with every confidence output, and the input
struct Confidence_case
{
  std::map<Mesh::Face_index, int> W, second;
  std::map<Mesh::Face_index, double> cost;
  std::map<Mesh::Face_index, std::size_t> region;
  std::map<Mesh::Edge_index, int> chain, G;
  SWN::Label_confidence conf;
};

Confidence_case solve_case(Mesh& m, const std::vector<std::vector<Vertex>>& polylines, double epsilon = 0.01)
{
  Confidence_case c;
  for(auto e : edges(m)) c.chain[e] = 0;
  auto chain = boost::make_assoc_property_map(c.chain);
  for(const auto& p : polylines) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, chain));
  namespace P = SWN::parameters;
  EXPECT_TRUE(CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(c.W),
    P::nonbounding_chain_map(boost::make_assoc_property_map(c.G), P::label_confidence(std::ref(c.conf),
    P::confidence_map(boost::make_assoc_property_map(c.cost), P::region_map(boost::make_assoc_property_map(c.region),
    P::second_best_label_map(boost::make_assoc_property_map(c.second), P::epsilon(epsilon))))))));
  return c;
}

// epsilon times the length of the edges of `polylines`, in mean interior edge lengths (measured on the mesh)
double input_cost(const Mesh& m, const std::vector<std::vector<Vertex>>& polylines, double epsilon)
{
  double mean = 0, len = 0;
  std::size_t interior = 0;
  for(auto e : edges(m))
    if(!is_border(e, m)) { mean += CGAL::Polygon_mesh_processing::edge_length(e, m); ++interior; }
  mean /= double(interior);
  for(const auto& p : polylines)
    for(std::size_t k = 0; k + 1 < p.size(); ++k) len += std::sqrt(CGAL::squared_distance(m.point(p[k]), m.point(p[k + 1])));
  return epsilon * len / mean;
}

// the region outputs agree with each other and with the labels; returns the faces of every region
std::vector<std::vector<Mesh::Face_index>> check_regions(const Mesh& m, const Confidence_case& c)
{
  std::vector<std::vector<Mesh::Face_index>> faces_of(c.conf.regions.size());
  for(auto f : faces(m))
  {
    const std::size_t r = c.region.at(f);
    EXPECT_LT(r, c.conf.regions.size());
    if(r >= faces_of.size()) continue;
    faces_of[r].push_back(f);
    EXPECT_EQ(c.conf.regions[r].label, c.W.at(f));
    EXPECT_EQ(c.cost.at(f), c.conf.regions[r].flip_cost);
    const bool flipped = r == c.conf.second_best_region;
    EXPECT_EQ(c.second.at(f), c.W.at(f) + (flipped ? c.conf.regions[r].flip_delta : 0));
  }
  for(std::size_t r = 0; r < faces_of.size(); ++r)
  {
    EXPECT_EQ(c.conf.regions[r].faces, faces_of[r].size());
    double area = 0;
    for(auto f : faces_of[r]) area += CGAL::Polygon_mesh_processing::face_area(f, m);
    EXPECT_NEAR(c.conf.regions[r].area, area, 1e-9 * area);
  }
  // the input is J W + G on every edge (the decomposition the flips keep)
  for(auto e : edges(m))
    if(!is_border(e, m))
    {
      const auto h = halfedge(e, m);
      EXPECT_EQ(c.chain.at(e), c.W.at(face(h, m)) - c.W.at(face(opposite(h, m), m)) + c.G.at(e));
    }
  return faces_of;
}

} // namespace

TEST(Confidence, RegionInsideACompleteLoopOnATorusCostsEpsilonTimesItsLength)
{
  Mesh m;
  const int nu = 24, nv = 12;
  const auto vs = torus_mesh(m, nu, nv);
  const std::vector<Vertex> meridian = meridian_piece(vs, nv, 3, 0, nv);
  const std::vector<Vertex> rect = rect_loop(torus_vertex(vs, nv), 10, 2, 14, 6);
  const Confidence_case c = solve_case(m, {meridian, rect});
  const auto faces_of = check_regions(m, c);
  ASSERT_EQ(c.conf.regions.size(), 2u);   // the 4 x 4 cells inside the rectangle, and the rest
  const std::size_t inside = faces_of[0].size() < faces_of[1].size() ? 0 : 1;
  EXPECT_EQ(faces_of[inside].size(), 32u);
  EXPECT_TRUE(c.conf.regions[1 - inside].largest_in_component);
  EXPECT_FALSE(c.conf.regions[inside].largest_in_component);

  const double expected = input_cost(m, {rect}, 0.01);
  EXPECT_NEAR(c.conf.regions[inside].flip_cost, expected, 1e-9 * expected);
  EXPECT_NEAR(c.conf.regions[1 - inside].flip_cost, expected, 1e-9 * expected);   // the complement: the same move
  // the boundary: the rectangle's length in mean interior edge lengths
  EXPECT_NEAR(c.conf.regions[inside].boundary_length, expected / 0.01, 1e-9 * expected / 0.01);
  // only the flip that empties the rectangle keeps G along the input's direction: the second-best
  // labeling is constant
  EXPECT_EQ(c.W.at(faces_of[inside][0]) + c.conf.regions[inside].flip_delta, c.W.at(faces_of[1 - inside][0]));
  EXPECT_EQ(c.conf.second_best_region, inside);
  EXPECT_EQ(c.conf.second_best_cost, c.conf.regions[inside].flip_cost);
  for(auto f : faces(m)) EXPECT_EQ(c.second.at(f), c.W.at(faces_of[1 - inside][0]));
  // the cost scales with epsilon
  const Confidence_case c2 = solve_case(m, {meridian, rect}, 0.02);
  EXPECT_NEAR(c2.conf.second_best_cost, 2 * expected, 2e-9 * expected);
}

TEST(Confidence, BandBetweenTwoOppositeMeridiansFlipsIntoTwoNonboundingLoops)
{
  Mesh m;
  const int nu = 20, nv = 10;
  const auto vs = torus_mesh(m, nu, nv);
  const std::vector<Vertex> a = meridian_piece(vs, nv, 3, 0, nv);
  std::vector<Vertex> b = meridian_piece(vs, nv, 9, 0, nv);
  std::reverse(b.begin(), b.end());
  const Confidence_case c = solve_case(m, {a, b});
  const auto faces_of = check_regions(m, c);
  for(const auto& g : c.G) EXPECT_EQ(g.second, 0);   // the two loops bound the band
  ASSERT_EQ(c.conf.regions.size(), 2u);
  const double expected = input_cost(m, {a, b}, 0.01);   // both meridians become G
  for(std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(c.conf.regions[k].flip_cost, expected, 1e-9 * expected);
  // the band (6 of 20 columns) is the second best region; flipped, the labels are constant
  const std::size_t band = faces_of[0].size() < faces_of[1].size() ? 0 : 1;
  EXPECT_EQ(faces_of[band].size(), std::size_t(2 * 6 * nv));
  EXPECT_EQ(c.conf.second_best_region, band);
  for(auto f : faces(m)) EXPECT_EQ(c.second.at(f), c.second.at(faces_of[0][0]));
}

TEST(Confidence, RegionBetweenTwoNestedLoopsCannotFlipAlone)
{
  // nested counter-clockwise squares on a disk: labels 2 / 1 / 0 from the inside out. The ring between
  // them is bounded by input on both sides, with opposite signs of J 1_ring against the input: either
  // direction of its flip reverses G against one of the squares (infinite cost). The inner square flips
  // down at epsilon times its length; it makes the second-best labeling.
  Mesh m;
  const int n = 16;
  const auto vs = grid_disk(m, n, 5);
  const std::vector<Vertex> outer = square_loop(vs, n, 2, 2, 13, 13), inner = square_loop(vs, n, 5, 5, 9, 9);
  const Confidence_case c = solve_case(m, {outer, inner});
  const auto faces_of = check_regions(m, c);
  ASSERT_EQ(c.conf.regions.size(), 3u);
  for(std::size_t r = 0; r < 3; ++r)
  {
    const int label = c.conf.regions[r].label;
    ASSERT_TRUE(label >= 0 && label <= 2);
    if(label == 1)
    {
      EXPECT_EQ(c.conf.regions[r].flip_cost, inf);
      EXPECT_EQ(c.conf.regions[r].flip_delta, 0);
    }
    if(label == 2)
    {
      const double expected = input_cost(m, {inner}, 0.01);
      EXPECT_NEAR(c.conf.regions[r].flip_cost, expected, 1e-9 * expected);
      EXPECT_EQ(c.conf.regions[r].flip_delta, -1);
      EXPECT_EQ(c.conf.second_best_region, r);
      EXPECT_EQ(faces_of[r].size(), std::size_t(2 * 4 * 4));
    }
    if(label == 0)
    {
      const double expected = input_cost(m, {outer}, 0.01);
      EXPECT_NEAR(c.conf.regions[r].flip_cost, expected, 1e-9 * expected);
      EXPECT_EQ(c.conf.regions[r].flip_delta, +1);
      EXPECT_TRUE(c.conf.regions[r].largest_in_component);
    }
  }
}

TEST(Confidence, PolygonSoupGivesEveryPolygonTheConfidenceOfItsRegion)
{
  // A torus of quads (triangulated internally along a diagonal), as a soup and as a quad Surface_mesh,
  // with a meridian and a rectangle loop around 4 x 4 quads: the region inside the loop costs epsilon times
  // its length, in mean interior edge lengths (the quads' edges and the diagonals of the triangulation),
  // on both paths; every polygon gets its region's values, the same on both.
  const int nu = 24, nv = 12;
  Mesh triangles;   // its points: those of torus_mesh(nu, nv), vertex (i, j) at i nv + j
  std::vector<K::Point_3> points;
  for(Vertex v : torus_mesh(triangles, nu, nv)) points.push_back(triangles.point(v));
  auto V = [&](int i, int j) { return std::size_t(((i % nu + nu) % nu) * nv + (j % nv + nv) % nv); };
  std::vector<std::vector<std::size_t>> quads;
  double length_sum = 0;   // the interior edges of the triangulated quads: two edges and one diagonal per quad
  auto dist = [&](std::size_t p, std::size_t q) { return std::sqrt(CGAL::squared_distance(points[p], points[q])); };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      quads.push_back({V(i, j), V(i + 1, j), V(i + 1, j + 1), V(i, j + 1)});
      // isosceles trapezoids: both diagonals have the same length
      length_sum += dist(V(i, j), V(i + 1, j)) + dist(V(i, j), V(i, j + 1)) + dist(V(i, j), V(i + 1, j + 1));
    }
  const double mean = length_sum / double(3 * nu * nv);
  Mesh m;
  for(const auto& p : points) m.add_vertex(p);
  const std::vector<Vertex> vs(m.vertices().begin(), m.vertices().end());
  for(const auto& q : quads) ASSERT_NE(m.add_face(vs[q[0]], vs[q[1]], vs[q[2]], vs[q[3]]), Mesh::null_face());
  const std::vector<Vertex> meridian = meridian_piece(vs, nv, 3, 0, nv);
  const std::vector<Vertex> rect = rect_loop(torus_vertex(vs, nv), 10, 2, 14, 6);
  double rect_length = 0;
  std::vector<std::pair<std::size_t, std::size_t>> curve;
  for(const auto* p : {&meridian, &rect})
    for(std::size_t k = 0; k + 1 < p->size(); ++k) curve.emplace_back(std::size_t((*p)[k]), std::size_t((*p)[k + 1]));
  for(std::size_t k = 0; k + 1 < rect.size(); ++k) rect_length += dist(std::size_t(rect[k]), std::size_t(rect[k + 1]));
  const double expected = 0.01 * rect_length / mean;

  const std::size_t P = quads.size();
  std::vector<int> W(P, 7), second(P, 7);
  std::vector<double> cost(P, -1.);
  std::vector<std::size_t> region(P, 99);
  SWN::Label_confidence conf;
  namespace NP = SWN::parameters;
  ASSERT_TRUE(CGAL::polygon_soup_winding_numbers(points, quads, curve, CGAL::make_property_map(W),
    NP::label_confidence(std::ref(conf), NP::confidence_map(CGAL::make_property_map(cost),
    NP::region_map(CGAL::make_property_map(region), NP::second_best_label_map(CGAL::make_property_map(second)))))));
  ASSERT_EQ(conf.regions.size(), 2u);
  std::size_t quads_in[2] = {0, 0};
  for(std::size_t p = 0; p < P; ++p)
  {
    ASSERT_LT(region[p], 2u);
    ++quads_in[region[p]];
    const SWN::Label_region& r = conf.regions[region[p]];
    EXPECT_EQ(W[p], r.label);
    EXPECT_EQ(cost[p], r.flip_cost);
    EXPECT_EQ(second[p], W[p] + (region[p] == conf.second_best_region ? r.flip_delta : 0));
  }
  const std::size_t inside = quads_in[0] < quads_in[1] ? 0 : 1;
  EXPECT_EQ(quads_in[inside], 16u);
  EXPECT_EQ(conf.regions[inside].faces, 32u);   // the triangles of its quads
  EXPECT_EQ(conf.regions[1 - inside].faces, std::size_t(2 * P - 32));
  EXPECT_NEAR(conf.regions[inside].flip_cost, expected, 1e-9 * expected);
  EXPECT_NEAR(conf.regions[1 - inside].flip_cost, expected, 1e-9 * expected);
  EXPECT_EQ(conf.second_best_region, inside);
  for(std::size_t p = 0; p < P; ++p) EXPECT_EQ(second[p], conf.regions[1 - inside].label);   // flipped: constant

  // the mesh path on the same quads: the same values per polygon
  const Confidence_case c = solve_case(m, {meridian, rect});
  ASSERT_EQ(c.conf.regions.size(), 2u);
  for(auto f : faces(m))
  {
    const std::size_t p = std::size_t(f);
    EXPECT_EQ(c.W.at(f), W[p]);
    EXPECT_NEAR(c.cost.at(f), cost[p], 1e-12 * expected);
    EXPECT_EQ(c.second.at(f), second[p]);
    EXPECT_EQ(c.conf.regions[c.region.at(f)].faces, conf.regions[region[p]].faces);
  }
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
  const SI::Label_regions cells = SI::label_regions(t, full_d, G, W);
  std::size_t right_cell = 0;
  while(!inside_right[right_cell]) ++right_cell;
  const std::vector<int> fixed = SB::relabel_cell(t, cells, cells.of_face[right_cell], area, W, gt);
  EXPECT_EQ(fixed, gt);
}
