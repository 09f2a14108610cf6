// Polygon soups and polygon meshes (issue 32, part 1 and 4): the soup entry point
// CGAL::polygon_soup_winding_numbers() and FaceGraphs with faces of more than three sides, on quad and
// mixed quad/triangle tori with analytic answers, and their errors. Nonmanifold and nonorientable soups
// are in test_oracles_nonmanifold.cpp.
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include "mesh_generators.h"
#include "test_oracles_soup.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace {

// every cell with i0 <= i < i1 and j0 <= j < j1 is one higher than every other cell, and the bounding
// chain is the loop around them
void expect_rectangle(const Polygon_torus& t, const Soup_answer& a, int i0, int j0, int i1, int j1)
{
  ASSERT_TRUE(a.ok) << a.report.error;
  std::set<int> inside, outside;
  for(std::size_t p = 0; p < t.polygons.size(); ++p)
  {
    const bool in = t.cell[p].first >= i0 && t.cell[p].first < i1 && t.cell[p].second >= j0 && t.cell[p].second < j1;
    (in ? inside : outside).insert(a.W[p]);
  }
  ASSERT_EQ(inside.size(), 1u);
  ASSERT_EQ(outside.size(), 1u);
  EXPECT_EQ(*inside.begin() - *outside.begin(), 1);
  EXPECT_EQ(*outside.begin(), 0);   // normalization: the largest area is 0
  const std::vector<Pair> loop = loop_edges(torus_rect_loop(t.nu, t.nv, i0, j0, i1, j1));
  int on_loop = 0, elsewhere = 0;
  for(const auto& kv : a.bounding) elsewhere += std::abs(kv.second);
  for(const Pair& e : loop) on_loop += along(a.bounding, e.first, e.second);
  EXPECT_EQ(on_loop, int(loop.size()));
  EXPECT_EQ(elsewhere, int(loop.size()));
  for(const auto& kv : a.G) EXPECT_EQ(kv.second, 0);
}

} // namespace

TEST(PolygonSoup, TriangulationOfANonConvexPolygonCoversItWithPositiveTriangles)
{
  // an L-shaped hexagon in the plane z = 1, and a pentagon with a flat corner
  const std::vector<double> xyz = {0, 0, 1, 2, 0, 1, 2, 1, 1, 1, 1, 1, 1, 2, 1, 0, 2, 1,   // L: area 3
                                   5, 0, 1, 6, 0, 1, 7, 0, 1, 7, 1, 1, 5, 1, 1};          // pentagon: area 2
  const double n[3] = {0, 0, 1};
  for(const std::vector<std::size_t>& polygon : {std::vector<std::size_t>{0, 1, 2, 3, 4, 5}, std::vector<std::size_t>{6, 7, 8, 9, 10}})
  {
    const auto tris = SI::triangulate_polygon(xyz, polygon);
    ASSERT_EQ(tris.size(), polygon.size() - 2);
    double area = 0;
    for(const auto& t : tris)
    {
      const double a = SI::projected_area(&xyz[3 * polygon[t[0]]], &xyz[3 * polygon[t[1]]], &xyz[3 * polygon[t[2]]], n);
      EXPECT_GT(a, 1e-12);   // no flat or flipped triangle
      area += a / 2;
    }
    EXPECT_NEAR(area, polygon.size() == 6 ? 3. : 2., 1e-12);
  }
}

TEST(PolygonSoup, LoopOnAQuadTorusEnclosesExactlyItsQuads)
{
  const Polygon_torus t(16, 10, [](int, int) { return false; });
  const Soup_answer a = solve_soup(t.points, t.polygons, loop_edges(torus_rect_loop(16, 10, 3, 2, 8, 6)));
  expect_rectangle(t, a, 3, 2, 8, 6);
  EXPECT_EQ(a.report.faces, t.polygons.size());
  EXPECT_EQ(a.report.edges, 2 * t.polygons.size());   // a quad torus: E = 2F, the diagonals not counted
  EXPECT_EQ(a.report.genus, 1);
  // w at the corners of an inside quad is near 1 plus the outside's level
  for(std::size_t p = 0; p < t.polygons.size(); ++p)
    if(t.cell[p] == std::make_pair(5, 4))
      for(std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(a.w.at(Pair(p, k)), 1., 0.35);
}

TEST(PolygonSoup, MixedQuadsAndTrianglesAndABrokenLoop)
{
  const Polygon_torus t(18, 12, [](int i, int j) { return (i + 2 * j) % 3 == 0; });
  ASSERT_GT(t.polygons.size(), std::size_t(18 * 12));   // some cells are two triangles
  expect_rectangle(t, solve_soup(t.points, t.polygons, loop_edges(torus_rect_loop(18, 12, 4, 3, 10, 8))), 4, 3, 10, 8);
  // the same loop with one edge missing: the gap is closed
  expect_rectangle(t, solve_soup(t.points, t.polygons, loop_edges(torus_rect_loop(18, 12, 4, 3, 10, 8), 3, 1)), 4, 3, 10, 8);
}

TEST(PolygonSoup, MeridianOfAQuadTorusBoundsNothing)
{
  const Polygon_torus t(14, 9, [](int i, int j) { return (i * j) % 4 == 1; });
  const std::vector<Index> meridian = torus_meridian(14, 9, 5);
  const Soup_answer a = solve_soup(t.points, t.polygons, loop_edges(meridian));
  ASSERT_TRUE(a.ok) << a.report.error;
  for(int W : a.W) EXPECT_EQ(W, 0);
  int on = 0, total = 0;
  for(const auto& kv : a.G) total += std::abs(kv.second);
  for(const Pair& e : loop_edges(meridian)) on += along(a.G, e.first, e.second);
  EXPECT_EQ(on, int(meridian.size()));
  EXPECT_EQ(total, int(meridian.size()));
  for(const auto& kv : a.bounding) EXPECT_EQ(kv.second, 0);
}

TEST(PolygonSoup, SurfaceMeshWithQuadsGivesTheSoupsAnswer)
{
  const Polygon_torus t(16, 10, [](int i, int) { return i % 5 == 0; });
  const std::vector<Index> loop = torus_rect_loop(16, 10, 3, 2, 8, 6);
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  Mesh m;
  for(const Point_3& p : t.points) m.add_vertex(p);
  for(const auto& p : t.polygons)
  {
    std::vector<Mesh::Vertex_index> vs;
    for(std::size_t v : p) vs.push_back(Mesh::Vertex_index(Mesh::size_type(v)));
    ASSERT_NE(m.add_face(vs), Mesh::null_face());
  }
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  std::vector<Mesh::Vertex_index> polyline;
  for(std::size_t k = 0; k <= loop.size(); ++k) polyline.push_back(Mesh::Vertex_index(Mesh::size_type(loop[k % loop.size()])));
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, polyline, chain));
  auto labels = m.add_property_map<Mesh::Face_index, int>("f:W", -99).first;
  auto w = m.add_property_map<Mesh::Halfedge_index, double>("h:w", 0.).first;
  SWN::Solve_report report;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, labels, SWN::parameters::winding_number_map(w,
                SWN::parameters::report(std::ref(report))))) << report.error;
  const Soup_answer a = solve_soup(t.points, t.polygons, loop_edges(loop));
  ASSERT_TRUE(a.ok);
  for(Mesh::Face_index f : m.faces())
  {
    EXPECT_EQ(labels[f], a.W[std::size_t(f)]);
    // w at the target of each halfedge of the face is the soup's w at that corner
    std::size_t k = 0;
    const std::size_t d = m.degree(f);
    for(Mesh::Halfedge_index h : m.halfedges_around_face(m.halfedge(f)))
      EXPECT_NEAR(w[h], a.w.at(Pair(std::size_t(f), ++k % d)), 1e-9);
  }
  EXPECT_EQ(report.faces, t.polygons.size());
}

TEST(PolygonSoup, BadPolygonsAndCurvesAreRejectedWithTheirIndex)
{
  const Polygon_torus t(8, 6, [](int, int) { return false; });
  auto expect_error = [&](std::vector<Point_3> points, Polygons polygons, std::vector<Pair> curve, const std::string& what) {
    const Soup_answer a = solve_soup(points, polygons, curve);
    EXPECT_FALSE(a.ok) << what;
    EXPECT_TRUE(a.report.invalid_input) << what;
    EXPECT_NE(a.report.error.find(what), std::string::npos) << a.report.error;
    for(int W : a.W) EXPECT_EQ(W, -99);   // nothing written
  };
  Polygons p = t.polygons;
  p[7] = {p[7][0], p[7][1]};
  expect_error(t.points, p, {}, "polygon 7 has 2 vertices");
  p = t.polygons;
  p[9][2] = p[9][0];
  expect_error(t.points, p, {}, "polygon 9 uses vertex");
  p = t.polygons;
  p[3][1] = 100000;
  expect_error(t.points, p, {}, "polygon 3: vertex index 100000 is out of range");
  std::vector<Point_3> pts = t.points;
  pts[5] = Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  expect_error(pts, t.polygons, {}, "vertex 5 has a non-finite coordinate");
  // a quad's diagonal is no edge of the soup
  expect_error(t.points, t.polygons, {Pair(t.polygons[0][0], t.polygons[0][2])}, "is not an edge of the polygons");
  // dual chain pairs must be polygons that share an edge
  const Soup_answer d = solve_soup(t.points, t.polygons, {}, {Pair(0, 47)});
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.report.error.find("dual chain pair 0 (0, 47): the two polygons share no edge"), std::string::npos)
    << d.report.error;
  EXPECT_FALSE(solve_soup(t.points, t.polygons, {}, {Pair(0, 1), Pair(1, 480)}).ok);
}
