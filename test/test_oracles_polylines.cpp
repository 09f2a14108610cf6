// polylines_to_chain(): 3D polylines off the mesh projected onto it, against the analytic cap of a circle
// of latitude on the unit sphere.
#include <CGAL/Surface_winding_numbers/polylines_to_chain.h>

#include "test_oracles_curves_support.h"

#include <limits>

using namespace swn_curves_test;

namespace {

const K::Vector_3 kZ(0, 0, 1);

TEST(Polylines, CircleAboveSphereLabelsItsCap)
{
  Mesh m = unit_sphere(4);
  const double h = mean_edge_length(m), angle = 0.7;
  Chain chain = new_chain(m);
  const std::vector<std::vector<P3> > polylines{latitude_circle(angle, 1 + 0.3 * h, 150)};
  const auto r = SWN::polylines_to_chain(m, polylines, chain);
  ASSERT_TRUE(r) << r.error;
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.points_off_surface, 0u);
  EXPECT_EQ(r.failed_walks, 0u);
  EXPECT_EQ(r.curves, 1u);
  EXPECT_EQ(chain_endpoints(m, chain), 0u) << "a closed polyline gives a closed chain";
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m));
  // every chain edge lies near the circle
  for(auto e : edges(m))
    if(chain[e] != 0)
      for(auto v : {source(e, m), target(e, m)})
        EXPECT_NEAR(polar_angle(m.point(v), kZ), angle, h);
  const auto labels = solve(m, chain);
  const double fraction = expect_cap(m, labels, kZ, angle, 1.5 * h, 1);
  EXPECT_NEAR(fraction, cap_fraction(angle), 0.01);
}

TEST(Polylines, CircleCrossingFacesAtAnAngleAndOnVertices)
{
  // a tilted circle through the surface's vertices' latitudes: walks through vertices and along edges
  Mesh m = unit_sphere(3);
  const double h = mean_edge_length(m), angle = 1.1;
  const K::Vector_3 axis(0.3, -0.2, 1);
  const double c = std::sqrt(axis.squared_length());
  // an orthonormal frame around the axis
  const K::Vector_3 n = axis / c, u0 = CGAL::cross_product(n, K::Vector_3(1, 0, 0));
  const K::Vector_3 u = u0 / std::sqrt(u0.squared_length()), v = CGAL::cross_product(n, u);
  std::vector<P3> circle;
  for(int i = 0; i <= 40; ++i)
  {
    const double phi = 2 * kPi * (i % 40) / 40;
    circle.push_back(CGAL::ORIGIN + std::cos(angle) * n + std::sin(angle) * (std::cos(phi) * u + std::sin(phi) * v));
  }
  Chain chain = new_chain(m);
  const auto r = SWN::polylines_to_chain(m, std::vector<std::vector<P3> >{circle}, chain);
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(chain_endpoints(m, chain), 0u);
  const auto labels = solve(m, chain);
  // the polyline's chords cut inside the sphere by up to 1 - cos(pi/40) of the radius
  const double fraction = expect_cap(m, labels, axis, angle, 1.5 * h, 1);
  EXPECT_NEAR(fraction, cap_fraction(angle), 0.02);
}

TEST(Polylines, PointsFarFromTheSurfaceMakeAGapThatIsClosed)
{
  Mesh m = unit_sphere(4);
  const double h = mean_edge_length(m), angle = 0.7;
  std::vector<P3> circle = latitude_circle(angle, 1, 150);
  for(int i = 20; i < 32; ++i) circle[i] = CGAL::ORIGIN + 1.5 * (circle[i] - CGAL::ORIGIN);   // lifted off
  Chain chain = new_chain(m);
  const auto r = SWN::polylines_to_chain(m, std::vector<std::vector<P3> >{circle}, chain);
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.points_off_surface, 12u);
  EXPECT_EQ(r.curves, 1u) << "the closed polyline with one gap is one open curve";
  ASSERT_EQ(r.pieces.size(), 1u);
  ASSERT_EQ(r.pieces[0].size(), 1u);
  EXPECT_EQ(r.pieces[0][0].front(), 32u);
  EXPECT_EQ(r.pieces[0][0].back(), 19u);
  EXPECT_EQ(chain_endpoints(m, chain), 2u);
  const auto labels = solve(m, chain);
  EXPECT_NEAR(expect_cap(m, labels, kZ, angle, 1.5 * h, 1), cap_fraction(angle), 0.01);
}

TEST(Polylines, CurveOverAHoleEndsOnTheBorderAndTheCapIsFound)
{
  Mesh m = unit_sphere(4);
  const double h = mean_edge_length(m), angle = 0.7;
  // a hole across the circle at phi = 0
  const P3 centre(std::sin(angle), 0, std::cos(angle));
  std::vector<Mesh::Face_index> hole;
  for(auto f : faces(m))
    if(CGAL::squared_distance(centroid(m, f), centre) < 0.2 * 0.2) hole.push_back(f);
  for(auto f : hole) CGAL::Euler::remove_face(halfedge(f, m), m);
  m.collect_garbage();
  ASSERT_FALSE(CGAL::is_closed(m));
  Chain chain = new_chain(m);
  const auto r = SWN::polylines_to_chain(m, std::vector<std::vector<P3> >{latitude_circle(angle, 1, 150)}, chain);
  ASSERT_TRUE(r) << r.error;
  EXPECT_GT(r.points_off_surface + r.failed_walks, 0u);
  EXPECT_EQ(r.curves, 1u);
  for(auto e : edges(m))
    if(chain[e] != 0) EXPECT_FALSE(CGAL::is_border(e, m)) << "no curve along the border";
  const auto labels = solve(m, chain);
  // the cap minus the hole: away from the circle the labels are those of the whole sphere
  double hole_area = 0, total = 0;
  for(auto f : faces(m)) total += face_area(m, f);
  hole_area = 4 * kPi - total;
  const double fraction = expect_cap(m, labels, kZ, angle, 1.5 * h, 1);
  EXPECT_NEAR(fraction * total, cap_fraction(angle) * 4 * kPi - hole_area / 2, 0.01 * 4 * kPi);
}

TEST(Polylines, FigureEightCrossesItselfAndLabelsTheLobesWithOppositeSigns)
{
  Mesh m = unit_sphere(4);
  std::vector<P3> eight;
  const int n = 200;
  for(int i = 0; i <= n; ++i)   // a lemniscate on the sphere around +z: lobes at x > 0 and x < 0
  {
    const double s = 2 * kPi * (i % n) / n, x = 0.5 * std::sin(s), y = 0.25 * std::sin(2 * s);
    eight.emplace_back(x, y, std::sqrt(1 - x * x - y * y));
  }
  Chain chain = new_chain(m);
  const auto r = SWN::polylines_to_chain(m, std::vector<std::vector<P3> >{eight}, chain);
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.dropped_crossings, 0u);
  EXPECT_LE(r.cut.crossing_vertices, 1u);   // none if the lobes cross on an edge
  EXPECT_EQ(chain_endpoints(m, chain), 0u);
  const auto labels = solve(m, chain);
  int lobe[2] = {0, 0};
  for(auto f : faces(m))
  {
    const P3 c = centroid(m, f);
    if(CGAL::squared_distance(c, P3(0.3, 0, std::sqrt(1 - 0.09))) < 0.01) lobe[0] = labels.at(f);
    if(CGAL::squared_distance(c, P3(-0.3, 0, std::sqrt(1 - 0.09))) < 0.01) lobe[1] = labels.at(f);
  }
  EXPECT_EQ(std::abs(lobe[0]), 1);
  EXPECT_EQ(lobe[0], -lobe[1]);
}

TEST(Polylines, BadInputIsAnErrorOrAWarning)
{
  Mesh m = unit_sphere(2);
  const std::size_t nf = num_faces(m);
  Chain chain = new_chain(m);
  std::vector<std::vector<P3> > polylines{latitude_circle(0.7, 1, 20)};
  polylines[0][3] = P3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  auto r = SWN::polylines_to_chain(m, polylines, chain);
  EXPECT_FALSE(r);
  EXPECT_NE(r.error.find("polyline 0, point 3"), std::string::npos) << r.error;
  EXPECT_EQ(num_faces(m), nf) << "nothing changed";

  // an empty polyline and one entirely off the surface: warnings, the good one is used
  polylines = {{}, latitude_circle(0.7, 3, 20), latitude_circle(0.7, 1, 20)};
  r = SWN::polylines_to_chain(m, polylines, chain);
  ASSERT_TRUE(r) << r.error;
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_NE(r.warnings[0].find("polyline 0 is empty"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[1].find("polyline 1: no point within"), std::string::npos) << r.warnings[1];
  EXPECT_EQ(r.curves, 1u);

  // only curves off the surface: nothing on the mesh
  Mesh m2 = unit_sphere(2);
  Chain chain2 = new_chain(m2);
  r = SWN::polylines_to_chain(m2, std::vector<std::vector<P3> >{latitude_circle(0.7, 3, 20)}, chain2);
  EXPECT_TRUE(r);
  EXPECT_EQ(r.curves, 0u);
  EXPECT_EQ(r.points_off_surface, 21u) << "every point, the repeated closing one too";
  for(auto e : edges(m2)) EXPECT_EQ(chain2[e], 0);
}

} // namespace
