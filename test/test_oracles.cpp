// End-to-end analytic oracle tests for CGAL::surface_winding_numbers (algorithm notes, section 10).
//
// Every oracle runs on CGAL::Surface_mesh and on CGAL::Polyhedron_3 (typed tests), mostly on
// jittered meshes with random diagonals. Results are converted to "soup terms" (labels per
// soup triangle, chains keyed by soup vertex pairs) so that expectations are written once,
// independently of the data structure and of its edge orientation.
//
// Conventions (section 1 of the notes): a chain value counts traversals along a -> b; W increases
// by chain(e) when crossing e from its right to its left (the inside of a CCW loop is one higher);
// per connected component, the label covering the largest area is 0.
//
// Every successful solve goes through check_common(): all outputs written; G == R(g) on every
// edge unless the report says R(g) had to be closed; G closed at interior vertices; no G or B on
// border edges; B == JW (left minus right label) on interior edges, hence B closed at interior
// vertices; w NaN exactly at the corners of interior endpoints; report.interior_endpoints;
// largest-area label 0 in every component. Closed curves also go through
// check_closed_decomposition(): B = chain - G on curve edges, 0 elsewhere.
//
// Suites (typed on both data structures unless noted): OraclesGenerators, OraclesDisk (D*),
// OraclesTorus (T*), OraclesAnnulus (A*), OraclesSphere, OraclesTwoComponents, OraclesMetamorphic
// (reversal, multiplicity, similarity x1e3 / x1e-3, far loop, renumbering, data structures),
// OraclesApi (solver class, chain helpers), OraclesSurfaceMesh (not typed: native maps, garbage),
// OraclesBadInput, OraclesHarness (not typed: the checks themselves can fail). The checks of each
// kind of curve are written once: expect_closed_bounding(), expect_closed_nonbounding(),
// expect_completed_nonbounding(), expect_open_curve().
//
// Environment: SWN_ORACLE_SEED_OFFSET=k runs everything on other random meshes;
// SWN_ORACLE_DIAG=1 prints one line of diagnostics per solve.

//
// The suites are spread over test_oracles*.cpp, all built into the binary test_oracles; the shared code
// is in test_oracles_support.h and test_oracles_cases.h.
#include "test_oracles_cases.h"

// ------------------------------------------------------------------------------------------
// Generators sanity (the oracles are only as good as the meshes)
// ------------------------------------------------------------------------------------------

TYPED_TEST(OraclesGenerators, ProduceValidOrientedMeshes)
{
  const Soup disk = make_disk(kDiskN, seed(3)), ann = make_annulus(kNr, kNt, seed(3)), tor = make_torus(kNu, kNv, seed(3)),
             sph = make_uv_sphere(kLat, kLon, seed(3));
  EXPECT_GT(min_signed_xy_area(disk), 0.);
  EXPECT_GT(min_signed_xy_area(ann), 0.);
  EXPECT_GT(min_outward_ratio_sphere(sph), 0.5);
  struct Case { const Soup* s; long chi; bool closed; std::size_t F; };
  for(const Case& c : {Case{&disk, 1, false, 800}, Case{&ann, 0, false, 768}, Case{&tor, 0, true, 576},
                       Case{&sph, 2, true, 528}})
  {
    auto m = make_mesh<TypeParam>(*c.s);
    EXPECT_TRUE(m->vertex_order_preserved);
    EXPECT_TRUE(m->face_order_preserved);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m->tm));
    EXPECT_TRUE(CGAL::is_triangle_mesh(m->tm));
    EXPECT_EQ(CGAL::is_closed(m->tm), c.closed);
    EXPECT_EQ(num_faces(m->tm), c.F);
    EXPECT_EQ(long(num_vertices(m->tm)) - long(num_edges(m->tm)) + long(num_faces(m->tm)), c.chi);
    for(Index v = 0; v < c.s->num_vertices(); ++v)
      EXPECT_EQ(get(CGAL::vertex_point, m->tm, m->vertex[v]), c.s->points[v]);
  }
}

// ==========================================================================================
// Disk (simply connected: one solve, no LP)
// ==========================================================================================


TYPED_TEST(OraclesDisk, D1_ClosedCCWLoop)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(11)));
  const Soup_chain c = loop_chain(d_loop());
  const Outcome o = expect_closed_bounding(*m, c, d_inside(m->soup), d_outside(m->soup), +1, 1, 0);
  EXPECT_TRUE(o.B == c) << to_string(o.B);
  EXPECT_LT(max_abs_g(o), 1e-12);
  EXPECT_FALSE(o.rep.lp_ran);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
}

TYPED_TEST(OraclesDisk, D1_RegularMeshNoJitter)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(11), 0.0, false));
  expect_closed_bounding(*m, loop_chain(d_loop()), d_inside(m->soup), d_outside(m->soup), +1, 1, 0);
}

TYPED_TEST(OraclesDisk, D2_ReversedLoop)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(12)));
  const Outcome o = expect_closed_bounding(*m, loop_chain(reversed(d_loop())), d_inside(m->soup), d_outside(m->soup), -1, -1, 0);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesDisk, D3_LoopEnclosingMostOfTheDisk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(13)));
  // 256 of 400 cells; normalization: the inside covers the largest area, so it is 0 and the outside is -1
  const Outcome o = expect_closed_bounding(*m, loop_chain(disk_rect_loop(kDiskN, 2, 2, 18, 18)), inside_rect(m->soup, 2, 2, 18, 18),
                                           outside_rect(m->soup, 2, 2, 18, 18), +1, 0, -1);
  EXPECT_FALSE(o.rep.lp_ran);
}


TYPED_TEST(OraclesDisk, D4_LoopWithOneEdgeGap) { disk_gap_case<TypeParam>(1, 14); }
TYPED_TEST(OraclesDisk, D5_LoopWithThreeEdgeGap) { disk_gap_case<TypeParam>(3, 15); }

TYPED_TEST(OraclesDisk, D6_ChordBoundaryToBoundary)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(16)));
  const Soup_chain c = path_chain(disk_vertical_path(kDiskN, 10, 0, kDiskN));   // going up at x = 1/2
  // ends on the border: counts as closed
  const Outcome o = expect_closed_bounding(*m, c, left_of(m->soup, 10), right_of(m->soup, 10), +1);
  EXPECT_TRUE(o.B == c) << to_string(o.B);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesDisk, D6_ChordDownwardsAndOffCentre)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(17)));
  // going down at x = 0.3: left is x > 0.3, which covers 70% of the area
  expect_closed_bounding(*m, path_chain(disk_vertical_path(kDiskN, 6, kDiskN, 0)), right_of(m->soup, 6), left_of(m->soup, 6), +1, 0, -1);
}

TYPED_TEST(OraclesDisk, D7_ChordWithTwoEdgeGap)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(18)));
  const Soup_chain c = pieces_chain(path_with_gap(disk_vertical_path(kDiskN, 10, 0, kDiskN), 9, 2));   // gap (10,9)-(10,11)
  const auto away = far_from({{10, 10}}, 3.0);
  const Outcome o = expect_open_curve(*m, c, left_of(m->soup, 10, away), right_of(m->soup, 10, away), +1, std::nullopt,
                                      std::nullopt, {}, 2);
  EXPECT_EQ(count_labels(o), 2u);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesDisk, NestedLoops)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(19)));
  const Soup_chain c = sum(loop_chain(disk_rect_loop(kDiskN, 3, 3, 13, 13)), loop_chain(disk_rect_loop(kDiskN, 6, 6, 10, 10)));
  const Outcome o = closed_run(*m, c);
  const auto ring = inside_rect(m->soup, 3, 3, 13, 13, [](double x, double y, int) { return !in_rect(x, y, 6, 6, 10, 10); });
  expect_regions(o, inside_rect(m->soup, 6, 6, 10, 10), ring, +1, 2, 1);
  expect_regions(o, ring, outside_rect(m->soup, 3, 3, 13, 13), +1, 1, 0);
  EXPECT_EQ(count_labels(o), 3u);
  expect_G(o, {});
  EXPECT_TRUE(o.B == c);
}

TYPED_TEST(OraclesDisk, OverlappingOppositeLoopsCrossingAtVertices)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(20)));
  // CCW and CW; they cross at (11,7) and (7,11)
  const Soup_chain c = sum(loop_chain(disk_rect_loop(kDiskN, 3, 3, 11, 11)), loop_chain(reversed(disk_rect_loop(kDiskN, 7, 7, 15, 15))));
  const Outcome o = closed_run(*m, c);
  const Face_filter inA = [](double x, double y, int) { return in_rect(x, y, 3, 3, 11, 11); };
  const Face_filter inB = [](double x, double y, int) { return in_rect(x, y, 7, 7, 15, 15); };
  const auto none = outside_rect(m->soup, 3, 3, 11, 11, [&](double x, double y, int k) { return !inB(x, y, k); });
  expect_regions(o, outside_rect(m->soup, 7, 7, 15, 15, inA), none, +1, 1, 0);   // only in A
  expect_regions(o, outside_rect(m->soup, 3, 3, 11, 11, inB), none, -1, -1, 0);   // only in B
  expect_regions(o, inside_rect(m->soup, 3, 3, 11, 11, inB), none, 0, 0, 0);      // in both
  EXPECT_EQ(count_labels(o), 3u);
  expect_G(o, {});
}

TYPED_TEST(OraclesDisk, LoopTouchingTheBorderAtAVertex)
{
  // diagonals (i,j)-(i+1,j+1) everywhere (jittered positions): the loop dips to the border
  // vertex (9,0) through the edges (9,1)-(9,0) and (9,0)-(10,1).
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(21), 0.2, false));
  std::vector<Index> l;
  for(int i = 6; i < 9; ++i) l.push_back(disk_vid(kDiskN, i, 1));
  l.push_back(disk_vid(kDiskN, 9, 1));
  l.push_back(disk_vid(kDiskN, 9, 0));
  for(int i = 10; i < 12; ++i) l.push_back(disk_vid(kDiskN, i, 1));
  for(int j = 1; j < 6; ++j) l.push_back(disk_vid(kDiskN, 12, j));
  for(int i = 12; i > 6; --i) l.push_back(disk_vid(kDiskN, i, 6));
  for(int j = 6; j > 1; --j) l.push_back(disk_vid(kDiskN, 6, j));
  const Soup_chain c = loop_chain(l);
  ASSERT_TRUE(boundary(c).empty());
  const Face_filter cell90 = [](double x, double y, int) { return x > 9 && x < 10 && y < 1; };
  const Outcome o = expect_closed_bounding(*m, c, inside_rect(m->soup, 6, 1, 12, 6),
                                           outside_rect(m->soup, 6, 1, 12, 6, [&](double x, double y, int k) { return !cell90(x, y, k); }),
                                           +1, 1, 0);
  EXPECT_TRUE(o.B == c);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
  // the triangle (9,0),(10,1),(9,1) is inside, (9,0),(10,0),(10,1) outside
  for(Index f : select(m->soup, cell90))
  {
    const Triangle& t = m->soup.triangles[f];
    const bool has_91 = std::count(t.begin(), t.end(), disk_vid(kDiskN, 9, 1)) > 0;
    EXPECT_EQ(o.W[f], has_91 ? 1 : 0);
  }
}

// ==========================================================================================
// Torus (genus 1: LP path)
// ==========================================================================================


TYPED_TEST(OraclesTorus, T1_Meridian)
{
  auto m = torus<TypeParam>(seed(21));
  expect_closed_nonbounding(*m, meridian(6));
}

TYPED_TEST(OraclesTorus, T1_MeridianRegularMesh)
{
  auto m = make_mesh<TypeParam>(make_torus(kNu, kNv, seed(22), 0.0, false));
  expect_closed_nonbounding(*m, meridian(0));
}

TYPED_TEST(OraclesTorus, T2_MeridianAndLongitudeCrossing)
{
  auto m = torus<TypeParam>(seed(23));
  expect_closed_nonbounding(*m, sum(meridian(6), longitude(3)));   // cross at vertex (6,3)
}

TYPED_TEST(OraclesTorus, T3_TwoParallelMeridiansEqualSpacing)
{
  auto m = torus<TypeParam>(seed(24));
  expect_closed_nonbounding(*m, sum(meridian(0), meridian(12)));   // G: each loop x1, not one loop x2
}

TYPED_TEST(OraclesTorus, T4_TwoParallelMeridiansUnequalSpacing)
{
  auto m = torus<TypeParam>(seed(25));
  expect_closed_nonbounding(*m, sum(meridian(2), meridian(7)));
}

TYPED_TEST(OraclesTorus, T5_TwoOppositeMeridians)
{
  auto m = torus<TypeParam>(seed(26));
  // the band is to the right of both curves
  const Outcome o = expect_closed_bounding(*m, sum(meridian(3), meridian_down(10)), t_band(m->soup), t_rest(m->soup), -1, -1, 0);
  EXPECT_TRUE(o.rep.lp_ran);
}

TYPED_TEST(OraclesTorus, T6_ContractibleLoop)
{
  auto m = torus<TypeParam>(seed(27));
  const Soup_chain c = torus_square(4, 3, 10, 8);
  const Outcome o = expect_closed_bounding(*m, c, t6_inside(m->soup), t6_outside(m->soup), +1, 1, 0);
  EXPECT_TRUE(o.B == c);
  EXPECT_TRUE(o.rep.lp_ran);
  EXPECT_NEAR(o.rep.lp_objective, 0.0, 1e-6);
}

TYPED_TEST(OraclesTorus, T7_ContractibleLoopWithOneEdgeGap)
{
  auto m = torus<TypeParam>(seed(28));
  const Soup_chain c = path_chain(loop_with_gap(torus_rect_loop(kNu, kNv, 4, 3, 10, 8), 2, 1));   // gap (6,3)-(7,3)
  const auto away = far_from({{6.5, 3}}, 2.5, kNu, kNv);
  const Outcome o = expect_open_curve(*m, c, t6_inside(m->soup, away), t6_outside(m->soup, away), +1, 1, 0, {}, 2);
  EXPECT_LT(max_abs_g(o), kTolG) << "the Hodge step should remove everything";
}

TYPED_TEST(OraclesTorus, T8_MeridianWithTwoEdgeGap)
{
  auto m = torus<TypeParam>(seed(29));
  // gap (6,4)-(6,6); G: the completed loop; g ~0.91 in the notes' prototype
  const Outcome o = expect_completed_nonbounding(*m, broken_meridian(6, 4, 2), meridian(6), 0.5, 1 + kTolG, 2);
  EXPECT_TRUE(o.rep.lp_ran);
}

TYPED_TEST(OraclesTorus, T9_TwoOppositeMeridiansWithGaps)
{
  auto m = torus<TypeParam>(seed(30));
  const auto away = far_from({{3, 2.5}, {10, 8.5}}, 2.5, kNu, kNv);
  expect_open_curve(*m, sum(broken_meridian(3, 2, 1), broken_meridian(10, 8, 1, true)), t_band(m->soup, away),
                    t_rest(m->soup, away), -1, -1, 0, {}, 4);
}

TYPED_TEST(OraclesTorus, T10_TwoSameMeridiansWithGaps)
{
  auto m = torus<TypeParam>(seed(31));
  // g 0.87 .. 1 in the notes' prototype
  expect_completed_nonbounding(*m, sum(broken_meridian(0, 3, 1), broken_meridian(12, 8, 1)), sum(meridian(0), meridian(12)),
                               0.8, 1 + kTolG, 4);
}

TYPED_TEST(OraclesTorus, T11_MeridianWithMultiplicityTwo)
{
  auto m = torus<TypeParam>(seed(32));
  expect_closed_nonbounding(*m, meridian(6, 2));
}


TYPED_TEST(OraclesTorus, T12_BrokenMeridianPlusContractibleLoop)
{
  auto m = torus<TypeParam>(seed(33));
  const Outcome o = expect_open_curve(*m, t12_chain(), t12_inside(m->soup), t12_outside(m->soup), +1, 1, 0, meridian(0), 2);
  EXPECT_TRUE(o.rep.lp_ran);
}

// T13: a meridian with a 5-edge gap on this mesh leaves g about 1/2 along the whole loop (0.5007 on
// the curve, 0.498 in the gap), so round(g) keeps the curve and drops the gap: an open chain. G is
// its closing (test_core: NonboundingChain): the completed meridian, the closed chain nearest to g
// with the curve's edges weighted twice (dropping the whole curve is the other closing, and the
// nearer one if every edge counted the same).
TYPED_TEST(OraclesTorus, T13_MeridianWhoseRoundingIsOpen)
{
  if(seed(2) != 2) GTEST_SKIP() << "the open rounding is a property of this one mesh";
  auto m = torus<TypeParam>(seed(2));
  const Outcome o = expect_completed_nonbounding(*m, broken_meridian(6, 2, 5), meridian(6), 0.45, 0.55, 2);
  EXPECT_EQ(o.rep.nonbounding_closing_units, 1u);
}

// ==========================================================================================
// Annulus (relative homology: LP path)
// ==========================================================================================


TYPED_TEST(OraclesAnnulus, A1_RadialArcInnerToOuter)
{
  auto m = annulus<TypeParam>(seed(41));
  expect_closed_nonbounding(*m, radial(0));
}

TYPED_TEST(OraclesAnnulus, A2_CoreCircle)
{
  auto m = annulus<TypeParam>(seed(42));
  // outer ring is larger (0.4375 pi vs 0.3125 pi)
  expect_closed_bounding(*m, core_circle(), inner_ring(m->soup), outer_ring(m->soup), +1, 1, 0);
}

TYPED_TEST(OraclesAnnulus, A3_ArcCuttingOffACap)
{
  auto m = annulus<TypeParam>(seed(43));
  Soup_chain c;
  add_path(c, annulus_radial_path(kNr, kNt, 10, kNr, 6));       // inwards from the outer border
  add_path(c, annulus_circle_path(kNr, kNt, 6, 10, 16));         // CCW along k = 6
  add_path(c, annulus_radial_path(kNr, kNt, 16, 6, kNr));        // back out
  // the cap is to the right of the curve
  expect_closed_bounding(*m, c, inside_rect(m->soup, 6, 10, kNr, 16), outside_rect(m->soup, 6, 10, kNr, 16), -1, -1, 0);
}

TYPED_TEST(OraclesAnnulus, A4_RadialArcWithTwoEdgeGap)
{
  auto m = annulus<TypeParam>(seed(44));
  expect_completed_nonbounding(*m, broken_radial(), radial(0), 0.5, 1 + kTolG, 2);   // g ~0.80 in the notes' prototype
}

TYPED_TEST(OraclesAnnulus, A5_TwoOppositeRadialArcs)
{
  auto m = annulus<TypeParam>(seed(45));
  // out at t = 0, back in at t = 12
  expect_closed_bounding(*m, sum(radial(0), radial(12, kNr, 0)), select(m->soup, [](double, double t, int) { return t < 12; }),
                         select(m->soup, [](double, double t, int) { return t > 12; }), +1, 1, 0);
}

TYPED_TEST(OraclesAnnulus, A6_RadialArcPlusCoreCircleSharingAVertex)
{
  auto m = annulus<TypeParam>(seed(46));
  const Outcome o = closed_run(*m, sum(radial(0), core_circle(kNr / 2, 0)));   // share vertex (4, 0)
  expect_regions(o, inner_ring(m->soup), outer_ring(m->soup), +1, 1, 0);
  EXPECT_EQ(count_labels(o), 2u);
  expect_G(o, radial(0));   // the arc only
}

