// test_oracles: the sphere and two components, the metamorphic checks, the API, Surface_mesh specifics.
#include "test_oracles_cases.h"

// ==========================================================================================
// Sphere (closed, genus 0: one solve) and two components
// ==========================================================================================

TYPED_TEST(OraclesSphere, LatitudeLoop)
{
  auto m = make_mesh<TypeParam>(make_uv_sphere(kLat, kLon, seed(51)));
  // polar angle 60 deg: the cap is 25% of the area
  const Outcome o = expect_closed_bounding(*m, loop_chain(sphere_ring(kLat, kLon, 4)), select(m->soup, [](double, double p, int) { return p < 4; }),
                                           select(m->soup, [](double, double p, int) { return p > 4; }), +1, 1, 0);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesSphere, BrokenLatitudeLoop)
{
  auto m = make_mesh<TypeParam>(make_uv_sphere(kLat, kLon, seed(52)));
  const auto away = far_from({{6, 6}}, 3.0, kLon);
  const auto north = select(m->soup, [&](double q, double p, int k) { return p < 6 && away(q, p, k); });
  const auto south = select(m->soup, [&](double q, double p, int k) { return p > 6 && away(q, p, k); });
  // equator, gap q = 5..7
  const Outcome o = expect_open_curve(*m, path_chain(loop_with_gap(sphere_ring(kLat, kLon, 6), 5, 2)), north, south, +1,
                                      std::nullopt, std::nullopt, {}, 2);
  EXPECT_FALSE(o.rep.lp_ran);
}


TYPED_TEST(OraclesTwoComponents, EachNormalizedIndependently)
{
  const int n = 12;
  auto m = make_mesh<TypeParam>(combine(make_disk(n, seed(61)), make_disk(n, seed(62)), 2.0, 0, 0));
  // component 0: small CCW loop; component 1: CCW loop enclosing 69%
  const Outcome o = closed_run(*m, sum(loop_chain(disk_rect_loop(n, 3, 3, 7, 7)),
                                       shifted(loop_chain(disk_rect_loop(n, 1, 1, 11, 11)), Index(n + 1) * Index(n + 1))));
  expect_regions(o, inside_rect(m->soup, 3, 3, 7, 7, component(0)), outside_rect(m->soup, 3, 3, 7, 7, component(0)), +1, 1, 0);
  expect_regions(o, inside_rect(m->soup, 1, 1, 11, 11, component(1)), outside_rect(m->soup, 1, 1, 11, 11, component(1)), +1, 0, -1);
  expect_G(o, {});
  EXPECT_EQ(o.rep.components, 2u);
}

TYPED_TEST(OraclesTwoComponents, TorusAndDisk)
{
  auto m = make_mesh<TypeParam>(combine(make_torus(kNu, kNv, seed(63)), make_disk(10, seed(64)), 3.0, 0, 0));
  // a meridian, and a CW loop on the disk
  const Outcome o = closed_run(*m, sum(meridian(6), shifted(loop_chain(reversed(disk_rect_loop(10, 2, 2, 5, 5))), Index(kNu) * Index(kNv))));
  int lt = 0;
  EXPECT_TRUE(region_label(o, select(m->soup, component(0)), lt));
  EXPECT_EQ(lt, 0);
  expect_regions(o, inside_rect(m->soup, 2, 2, 5, 5, component(1)), outside_rect(m->soup, 2, 2, 5, 5, component(1)), -1, -1, 0);
  expect_G(o, meridian(6));
}

TYPED_TEST(OraclesTwoComponents, BrokenLoopsOnTwoTori)
{
  // two tori, each with a broken meridian and a contractible loop: endpoints, Hodge step and LP
  // on a disconnected mesh. On the second torus the curve is reversed, so its inside is -1.
  auto m = make_mesh<TypeParam>(combine(make_torus(kNu, kNv, seed(65)), make_torus(kNu, kNv, seed(66)), 4.0, 0, 0));
  const Index off = Index(kNu) * Index(kNv);
  const Outcome o = checked_run(*m, sum(t12_chain(), shifted(scaled(t12_chain(), -1), off)));
  expect_regions(o, t12_inside(m->soup, 0), t12_outside(m->soup, 0), +1, 1, 0);
  expect_regions(o, t12_inside(m->soup, 1), t12_outside(m->soup, 1), -1, -1, 0);
  expect_G(o, sum(meridian(0), shifted(scaled(meridian(0), -1), off)));
  EXPECT_EQ(o.rep.interior_endpoints, 4u);
  EXPECT_TRUE(o.rep.lp_ran);
}

// ==========================================================================================
// Metamorphic checks
// ==========================================================================================


TYPED_TEST(OraclesMetamorphic, ReversalNegatesWDifferencesAndG_Torus)
{
  auto m = torus<TypeParam>(seed(71));
  const Soup_chain c = t12_chain();
  const Outcome o = checked_run(*m, c), r = checked_run(*m, scaled(c, -1));
  const auto F = concat(t12_inside(m->soup), t12_outside(m->soup));
  EXPECT_EQ(differences(r, F), negated(differences(o, F)));
  expect_regions(r, t12_inside(m->soup), t12_outside(m->soup), -1, -1, 0);
  expect_G(r, scaled(o.G, -1));
  expect_g_scaled(o, r, -1, kTolG);
}

TYPED_TEST(OraclesMetamorphic, ReversalNegatesWDifferences_Disk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(72)));
  const Soup_chain c = d_loop_with_gap(2);
  const Outcome o = checked_run(*m, c), r = checked_run(*m, scaled(c, -1));
  const auto F = select(m->soup, far_from({{9, 4}}, 3.0));
  EXPECT_EQ(differences(r, F), negated(differences(o, F)));
  // w is linear in the chain (single solve): w_r + w_o is constant
  double lo = 1e300, hi = -1e300;
  for(Index f = 0; f < m->soup.num_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      if(!std::isnan(o.w[f][k])) { lo = std::min(lo, o.w[f][k] + r.w[f][k]); hi = std::max(hi, o.w[f][k] + r.w[f][k]); }
  EXPECT_LT(hi - lo, kTolW);
}

TYPED_TEST(OraclesMetamorphic, MultiplicityTwoDoubles_Disk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(73)));
  const Soup_chain c = loop_chain(d_loop(), 2);
  const Outcome o = expect_closed_bounding(*m, c, d_inside(m->soup), d_outside(m->soup), +2, 2, 0);
  EXPECT_TRUE(o.B == c);
}

TYPED_TEST(OraclesMetamorphic, MultiplicityTwoDoubles_TorusLoop)
{
  auto m = torus<TypeParam>(seed(74));
  expect_closed_bounding(*m, scaled(torus_square(4, 3, 10, 8), 2), t6_inside(m->soup), t6_outside(m->soup), +2, 2, 0);
}

TYPED_TEST(OraclesMetamorphic, MultiplicityTwoDoubles_BrokenMeridian)
{
  auto m = torus<TypeParam>(seed(75));
  const Soup_chain c1 = broken_meridian(6, 4, 2);
  const Outcome o1 = checked_run(*m, c1), o2 = checked_run(*m, scaled(c1, 2));
  expect_constant_W(o2);
  expect_G(o1, meridian(6));
  expect_G(o2, meridian(6, 2));
  expect_g_scaled(o1, o2, 2, 2 * kTolG);
}


TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_TorusScaleUp)
{
  similarity_case<TypeParam>(make_torus(kNu, kNv, seed(76)), t12_chain(), 1e3);
}
TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_TorusScaleDown)
{
  similarity_case<TypeParam>(make_torus(kNu, kNv, seed(77)), t12_chain(), 1e-3);
}
TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_DiskScaleUp)
{
  similarity_case<TypeParam>(make_disk(kDiskN, seed(78)), d_loop_with_gap(1), 1e3);
}
TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_AnnulusScaleDown)
{
  similarity_case<TypeParam>(make_annulus(kNr, kNt, seed(79)), sum(radial(0), core_circle()), 1e-3);
}


TYPED_TEST(OraclesMetamorphic, FarBoundingLoopDoesNotChangeG_Torus)
{
  auto m = torus<TypeParam>(seed(80));
  far_loop_case(*m, broken_meridian(6, 4, 2), meridian(6), torus_square(14, 3, 19, 8), {14, 3, 19, 8},
                [](double x, double, int) { return x > 9 && x < 22; });
}

TYPED_TEST(OraclesMetamorphic, FarBoundingLoopDoesNotChangeG_Annulus)
{
  auto m = annulus<TypeParam>(seed(81));
  std::vector<Index> l;   // CCW quadrilateral in (k, t): k 2..6, t 20..26
  for(int k = 2; k < 6; ++k) l.push_back(annulus_vid(kNr, kNt, k, 20));
  for(int t = 20; t < 26; ++t) l.push_back(annulus_vid(kNr, kNt, 6, t));
  for(int k = 6; k > 2; --k) l.push_back(annulus_vid(kNr, kNt, k, 26));
  for(int t = 26; t > 20; --t) l.push_back(annulus_vid(kNr, kNt, 2, t));
  far_loop_case(*m, broken_radial(), radial(0), loop_chain(l), {2, 20, 6, 26}, [](double, double t, int) { return t > 4 && t < 44; });
}


TYPED_TEST(OraclesMetamorphic, RenumberingInvariance_Torus)
{
  permutation_case<TypeParam>(make_torus(kNu, kNv, seed(83)), t12_chain(), 1);
}
TYPED_TEST(OraclesMetamorphic, RenumberingInvariance_Disk)
{
  permutation_case<TypeParam>(make_disk(kDiskN, seed(84)), d_loop_with_gap(2), 2);
}
TYPED_TEST(OraclesMetamorphic, RenumberingInvariance_Annulus)
{
  permutation_case<TypeParam>(make_annulus(kNr, kNt, seed(85)), sum(core_circle(), broken_radial()), 3);
}

TYPED_TEST(OraclesMetamorphic, MeshStructuresAgree)
{
  // Same soup through the other data structure gives identical labels and G.
  const Soup s = make_torus(kNu, kNv, seed(82));
  auto a = make_mesh<TypeParam>(s);
  auto b = make_mesh<SM>(s);
  const Outcome oa = checked_run(*a, t12_chain()), ob = checked_run(*b, t12_chain());
  EXPECT_EQ(oa.W, ob.W);
  expect_G(oa, ob.G);
}

// ==========================================================================================
// API: solver class, chain helpers
// ==========================================================================================

TYPED_TEST(OraclesApi, SolverClassReusedForManyCurves)
{
  auto m = torus<TypeParam>(seed(91));
  SWN::Surface_winding_numbers_solver<TypeParam> solver(m->tm);
  const std::vector<Soup_chain> curves = {meridian(6), torus_square(4, 3, 10, 8), t12_chain(),
                                          broken_meridian(6, 4, 2), meridian(6)};
  for(std::size_t i = 0; i < curves.size(); ++i)
  {
    SCOPED_TRACE("curve " + std::to_string(i));
    Outcome s = run_with_solver(*m, solver, curves[i]);
    check_common(s);
    const Outcome f = checked_run(*m, curves[i]);
    EXPECT_EQ(s.W, f.W);
    expect_G(s, f.G);
    EXPECT_TRUE(s.B == f.B);
  }
}

TYPED_TEST(OraclesApi, SolverClassOnDisk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(92)));
  SWN::Surface_winding_numbers_solver<TypeParam> solver(m->tm);
  const Soup_chain c1 = loop_chain(d_loop()), c2 = d_loop_with_gap(2);
  for(const Soup_chain* c : {&c1, &c2, &c1})
  {
    Outcome s = run_with_solver(*m, solver, *c);
    check_common(s);
    const auto away = far_from({{9, 4}}, 3.0);
    expect_regions(s, d_inside(m->soup, away), d_outside(m->soup, away), +1, 1, 0);
  }
}

TYPED_TEST(OraclesApi, ChainHelpersMatchSoupChains)
{
  using GT = boost::graph_traits<TypeParam>;
  auto m = torus<TypeParam>(seed(93));
  const std::vector<Index> loop = torus_rect_loop(kNu, kNv, 4, 3, 10, 8);
  const Soup_chain expected = sum(loop_chain(loop), meridian(6, 2));

  auto to_soup = [&](const std::unordered_map<typename GT::edge_descriptor, int>& mp) {
    Soup_chain r;
    for(const auto& kv : mp)
      if(kv.second != 0) { auto ks = m->key(kv.first); r[ks.first] = kv.second * ks.second; }
    return r;
  };
  auto zero_chain = [&] {
    std::unordered_map<typename GT::edge_descriptor, int> c;
    for(auto e : edges(m->tm)) c[e] = 0;
    return c;
  };

  // vertex polylines (closed by repeating the first vertex)
  std::unordered_map<typename GT::edge_descriptor, int> c1 = zero_chain();
  auto pm1 = boost::make_assoc_property_map(c1);
  auto closed_polyline = [&](const std::vector<Index>& l) {
    std::vector<typename GT::vertex_descriptor> pl;
    for(Index v : l) pl.push_back(m->vertex[v]);
    pl.push_back(pl.front());
    return pl;
  };
  // property maps are taken by value: a map made inline writes to c1 as a named one does
  EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m->tm, closed_polyline(loop), boost::make_assoc_property_map(c1)));
  for(int k = 0; k < 2; ++k) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m->tm, closed_polyline(torus_meridian(kNu, kNv, 6)), pm1));
  EXPECT_TRUE(to_soup(c1) == expected) << to_string(to_soup(c1)) << "\nvs " << to_string(expected);

  // non-adjacent consecutive vertices: false, nothing added
  const auto before = c1;
  std::vector<typename GT::vertex_descriptor> bad = {m->vertex[torus_vid(kNu, kNv, 0, 0)], m->vertex[torus_vid(kNu, kNv, 0, 1)],
                                                     m->vertex[torus_vid(kNu, kNv, 5, 5)]};
  EXPECT_FALSE(SWN::add_vertex_polyline_to_chain(m->tm, bad, pm1));
  EXPECT_TRUE(c1 == before);

  // halfedges: same chain; opposite halfedges cancel
  std::unordered_map<typename GT::edge_descriptor, int> c2 = zero_chain();
  std::vector<typename GT::halfedge_descriptor> hs;
  for(std::size_t k = 0; k < loop.size(); ++k) hs.push_back(m->halfedge_of(loop[k], loop[(k + 1) % loop.size()]));
  const std::vector<Index> mer = torus_meridian(kNu, kNv, 6);
  for(int rep = 0; rep < 2; ++rep)
    for(std::size_t k = 0; k < mer.size(); ++k) hs.push_back(m->halfedge_of(mer[k], mer[(k + 1) % mer.size()]));
  auto h0 = m->halfedge_of(torus_vid(kNu, kNv, 20, 1), torus_vid(kNu, kNv, 21, 1));
  hs.push_back(h0);
  hs.push_back(opposite(h0, m->tm));
  EXPECT_TRUE(SWN::add_halfedges_to_chain(m->tm, hs, boost::make_assoc_property_map(c2)));
  EXPECT_TRUE(to_soup(c2) == expected) << to_string(to_soup(c2));

  // and the solver gives the same result from the helper-built chain
  const Outcome o = checked_run(*m, expected);
  expect_G(o, meridian(6, 2));
  expect_regions(o, t6_inside(m->soup), t6_outside(m->soup), +1, 1, 0);
}

// ==========================================================================================
// Surface_mesh specifics: native property maps, garbage
// ==========================================================================================

TEST(OraclesSurfaceMesh, NativePropertyMaps)
{
  auto m = make_mesh<SM>(make_disk(kDiskN, seed(101)));
  SM& sm = m->tm;
  auto chain = sm.add_property_map<SM::Edge_index, int>("e:chain", 0).first;
  auto labels = sm.add_property_map<SM::Face_index, int>("f:W", kIntSentinel).first;
  auto G = sm.add_property_map<SM::Edge_index, int>("e:G", kIntSentinel).first;
  auto B = sm.add_property_map<SM::Edge_index, int>("e:B", kIntSentinel).first;
  auto g = sm.add_property_map<SM::Edge_index, double>("e:g", kRealSentinel).first;
  auto w = sm.add_property_map<SM::Halfedge_index, double>("h:w", kRealSentinel).first;
  std::vector<SM::Vertex_index> pl;
  for(Index v : d_loop()) pl.push_back(m->vertex[v]);
  pl.push_back(pl.front());
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(sm, pl, chain));
  SWN::Solve_report rep;
  const bool ok = CGAL::surface_winding_numbers(sm, chain, labels,
      SWN::parameters::nonbounding_chain_map(G,
      SWN::parameters::nonbounding_chain_real_map(g,
      SWN::parameters::bounding_chain_map(B,
      SWN::parameters::winding_number_map(w,
      SWN::parameters::report(std::ref(rep)))))));
  ASSERT_TRUE(ok) << rep.error;
  for(Index f = 0; f < m->soup.num_faces(); ++f)
  {
    const bool in = in_rect(m->soup.fparam[f][0], m->soup.fparam[f][1], 4, 4, 14, 14);
    EXPECT_EQ(labels[m->face[f]], in ? 1 : 0);
  }
  for(auto e : edges(sm))
  {
    EXPECT_EQ(G[e], 0);
    EXPECT_EQ(B[e], chain[e]);
  }
  for(auto h : halfedges(sm))
    if(!is_border(h, sm)) { EXPECT_FALSE(w[h] == kRealSentinel); }
}

TEST(OraclesSurfaceMesh, MeshWithGarbage)
{
  // A Surface_mesh with removed-but-not-collected elements (index holes) must give the same result.
  auto m = make_mesh<SM>(make_disk(kDiskN, seed(102)));
  const Soup_chain c = loop_chain(d_loop());
  const Outcome clean = checked_run(*m, c);
  SM& sm = m->tm;
  auto a = sm.add_vertex(Point_3(5, 5, 0)), b = sm.add_vertex(Point_3(6, 5, 0)), d = sm.add_vertex(Point_3(5, 6, 0));
  auto f = sm.add_face(a, b, d);
  ASSERT_NE(f, SM::null_face());
  CGAL::Euler::remove_face(halfedge(f, sm), sm);
  ASSERT_TRUE(sm.has_garbage());
  ASSERT_EQ(sm.number_of_faces(), m->soup.num_faces());
  const Outcome dirty = checked_run(*m, c);
  EXPECT_EQ(dirty.W, clean.W);
  expect_G(dirty, clean.G);
  for(Index i = 0; i < clean.w.size(); ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(dirty.w[i][k], clean.w[i][k], kTolW);
}

