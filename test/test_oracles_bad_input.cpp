// test_oracles: bad input, polygon meshes, and the self-tests of the harness.
#include "test_oracles_cases.h"

// ==========================================================================================
// Bad input: false, report.error set, outputs untouched
// ==========================================================================================


// Faces of more than three sides are triangulated internally (issue 32): a loop around the inner 2 x 2
// cells of a 4 x 4 disk of quads (some cells cut into two triangles) gives exactly those cells label 1.
TYPED_TEST(OraclesApi, QuadAndMixedMeshesLabelWholeFaces)
{
  typedef boost::graph_traits<TypeParam> GT;
  const int n = 4;
  std::vector<Point_3> pts;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) pts.emplace_back(double(i) / n, double(j) / n, 0.);
  for(bool mixed : {false, true})
  {
    std::vector<std::vector<Index>> polygons;
    std::vector<bool> inside;
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        const Index a = disk_vid(n, i, j), b = disk_vid(n, i + 1, j), c = disk_vid(n, i + 1, j + 1), d = disk_vid(n, i, j + 1);
        const bool in = i >= 1 && i < 3 && j >= 1 && j < 3;
        if(mixed && (i + j) % 2 == 0) { polygons.push_back({a, b, c}); polygons.push_back({a, c, d}); inside.push_back(in); }
        else polygons.push_back({a, b, c, d});
        inside.push_back(in);
      }
    TypeParam tm;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polygons, tm);
    ASSERT_EQ(num_faces(tm), polygons.size());
    const std::vector<typename GT::vertex_descriptor> vd(vertices(tm).begin(), vertices(tm).end());   // soup order
    std::map<typename GT::edge_descriptor, int> chain_storage;
    for(auto e : edges(tm)) chain_storage[e] = 0;
    std::vector<typename GT::vertex_descriptor> polyline;
    const std::vector<Index> loop = disk_rect_loop(n, 1, 1, 3, 3);
    for(std::size_t k = 0; k <= loop.size(); ++k) polyline.push_back(vd[loop[k % loop.size()]]);
    auto chain = boost::make_assoc_property_map(chain_storage);
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(tm, polyline, chain));
    std::map<typename GT::face_descriptor, int> label_storage;
    SWN::Solve_report report;
    ASSERT_TRUE(CGAL::surface_winding_numbers(tm, chain, boost::make_assoc_property_map(label_storage),
                                              SWN::parameters::report(std::ref(report)))) << report.error;
    EXPECT_EQ(report.faces, polygons.size());
    std::size_t k = 0;
    for(auto f : faces(tm)) EXPECT_EQ(label_storage[f], inside[k++] ? 1 : 0) << (mixed ? "mixed" : "quads") << ", face " << k - 1;
  }
}

TYPED_TEST(OraclesBadInput, EmptyMesh)
{
  TypeParam tm;
  Raw_maps<TypeParam> r(tm);
  expect_rejected(r, tm, "empty mesh");
}

TYPED_TEST(OraclesBadInput, ChainOnBorderEdge)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(111)));
  Soup_chain c = loop_chain(d_loop());
  add_segment(c, disk_vid(kDiskN, 3, 0), disk_vid(kDiskN, 4, 0));   // bottom border edge
  expect_chain_rejected(*m, c, "chain on a border edge");
}

TYPED_TEST(OraclesBadInput, NaNCoordinate)
{
  disk_with_a_moved_vertex_case<TypeParam>(seed(112), 0.2, 7, 7, Point_3(std::numeric_limits<double>::quiet_NaN(), 0.35, 0),
                                           loop_chain(d_loop()), "NaN coordinate");
}

TYPED_TEST(OraclesBadInput, InfiniteCoordinate)
{
  auto m = make_mesh<TypeParam>(make_torus(kNu, kNv, seed(113)));
  put(get(CGAL::vertex_point, m->tm), m->vertex[torus_vid(kNu, kNv, 3, 3)], Point_3(0, std::numeric_limits<double>::infinity(), 0));
  expect_chain_rejected(*m, meridian(6), "infinite coordinate");
}

TYPED_TEST(OraclesBadInput, ZeroAreaFace)
{
  // regular disk, every cell split along (i,j)-(i+1,j+1): moving (7,7) onto the line x = 8/n
  // makes the triangle (7,7),(8,7),(8,8) exactly degenerate.
  const double h = 1.0 / kDiskN;
  disk_with_a_moved_vertex_case<TypeParam>(seed(114), 0.0, 7, 7, Point_3(8 * h, 7.5 * h, 0),
                                           loop_chain(disk_rect_loop(kDiskN, 12, 12, 16, 16)), "zero-area face");
}

TYPED_TEST(OraclesBadInput, CoincidentVertices)
{
  const Soup disk = make_disk(kDiskN, seed(115));
  disk_with_a_moved_vertex_case<TypeParam>(seed(115), 0.2, 7, 7, disk.points[disk_vid(kDiskN, 8, 7)],
                                           loop_chain(disk_rect_loop(kDiskN, 12, 12, 16, 16)), "coincident vertices (zero-area faces)");
}

TYPED_TEST(OraclesBadInput, SolverClassReportsError)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(116)));
  Raw_maps<TypeParam> r(m->tm);
  Soup_chain c;
  add_segment(c, disk_vid(kDiskN, 0, 3), disk_vid(kDiskN, 0, 4));   // left border edge
  set_chain(*m, c, r.chain);
  SWN::Surface_winding_numbers_solver<TypeParam> solver(m->tm);
  const bool ok = r.call_solver(solver);
  EXPECT_FALSE(ok);
  EXPECT_FALSE(r.rep.error.empty());
  EXPECT_TRUE(r.outputs_untouched());
}

// ==========================================================================================
// API misuse (issue 33): what can be checked cheaply is, instead of a crash or a silent read out of
// bounds; extreme units solve like unit-size meshes.
// ==========================================================================================

TEST(OraclesApiMisuse, ChainHelpersRefuseDescriptorsOfNoMesh)
{
  auto m = make_mesh<SM>(make_torus(kNu, kNv, seed(120)));
  SM& tm = m->tm;
  auto ch = tm.add_property_map<SM::Edge_index, int>("e:test_chain", 0).first;
  const SM::Halfedge_index good = *halfedges(tm).begin();
  const SM::Halfedge_index far(static_cast<SM::size_type>(tm.num_halfedges() + 7));
  for(const std::vector<SM::Halfedge_index>& hs : {std::vector<SM::Halfedge_index>{good, far},
                                                     std::vector<SM::Halfedge_index>{good, SM::null_halfedge()}})
  {
    EXPECT_FALSE(SWN::add_halfedges_to_chain(tm, hs, ch));
    for(auto e : edges(tm)) ASSERT_EQ(ch[e], 0);   // unchanged
  }
  const std::vector<SM::Vertex_index> polyline = {m->vertex[torus_vid(kNu, kNv, 0, 0)], m->vertex[torus_vid(kNu, kNv, 1, 0)],
                                                  SM::Vertex_index(static_cast<SM::size_type>(tm.num_vertices() + 3))};
  EXPECT_FALSE(SWN::add_vertex_polyline_to_chain(tm, polyline, ch));
  EXPECT_FALSE(SWN::add_vertex_polyline_to_chain(tm, std::vector<SM::Vertex_index>{SM::null_vertex(), polyline[0]}, ch));
  for(auto e : edges(tm)) ASSERT_EQ(ch[e], 0);
  // a chain map of a smaller mesh
  SM small;
  CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1), small);
  auto small_chain = small.add_property_map<SM::Edge_index, int>("e:c", 0).first;
  EXPECT_FALSE(SWN::add_vertex_polyline_to_chain(tm, std::vector<SM::Vertex_index>(polyline.begin(), polyline.begin() + 2), small_chain));
  // the same calls on valid input succeed
  EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(tm, std::vector<SM::Vertex_index>(polyline.begin(), polyline.begin() + 2), ch));
  // Polyhedron_3: null handles are refused
  auto p = make_mesh<PH>(make_torus(kNu, kNv, seed(120)));
  std::map<boost::graph_traits<PH>::edge_descriptor, int> storage;
  auto pch = boost::make_assoc_property_map(storage);
  EXPECT_FALSE(SWN::add_halfedges_to_chain(p->tm, std::vector<boost::graph_traits<PH>::halfedge_descriptor>{
                                                     boost::graph_traits<PH>::null_halfedge()}, pch));
  EXPECT_TRUE(storage.empty());
}

TEST(OraclesApiMisuse, PropertyMapsOfAnotherMeshAreRefused)
{
  auto m = make_mesh<SM>(make_torus(kNu, kNv, seed(121)));
  SM& tm = m->tm;
  SM small;
  CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1), small);
  auto chain = tm.add_property_map<SM::Edge_index, int>("e:c", 0).first;
  auto labels = tm.add_property_map<SM::Face_index, int>("f:W", kIntSentinel).first;
  auto G = tm.add_property_map<SM::Edge_index, int>("e:G", kIntSentinel).first;
  set_chain(*m, meridian(6), chain);
  auto small_chain = small.add_property_map<SM::Edge_index, int>("e:c", 1).first;
  auto small_labels = small.add_property_map<SM::Face_index, int>("f:W", kIntSentinel).first;
  auto small_G = small.add_property_map<SM::Edge_index, int>("e:G", kIntSentinel).first;
  auto small_w = small.add_property_map<SM::Halfedge_index, double>("h:w", 0.).first;
  auto untouched = [&] {
    for(auto f : faces(tm)) if(labels[f] != kIntSentinel) return false;
    for(auto e : edges(tm)) if(G[e] != kIntSentinel) return false;
    return true;
  };
  struct Case { std::function<bool(SWN::Solve_report&)> call; std::string message; };
  const std::vector<Case> cases = {
    {[&](SWN::Solve_report& r) { return CGAL::surface_winding_numbers(tm, small_chain, labels, SWN::parameters::report(std::ref(r))); },
     "the chain map has 6 entries but the mesh has"},
    {[&](SWN::Solve_report& r) { return CGAL::surface_winding_numbers(tm, chain, small_labels, SWN::parameters::report(std::ref(r))); },
     "the label map has 4 entries but the mesh has"},
    {[&](SWN::Solve_report& r) {
       return CGAL::surface_winding_numbers(tm, chain, labels, SWN::parameters::nonbounding_chain_map(small_G, SWN::parameters::report(std::ref(r))));
     }, "nonbounding_chain_map has 6 entries"},
    {[&](SWN::Solve_report& r) {
       return CGAL::surface_winding_numbers(tm, chain, labels, SWN::parameters::nonbounding_chain_map(G,
                                            SWN::parameters::winding_number_map(small_w, SWN::parameters::report(std::ref(r)))));
     }, "winding_number_map has 12 entries"}};
  for(const Case& c : cases)
  {
    SWN::Solve_report r;
    EXPECT_FALSE(c.call(r)) << c.message;
    EXPECT_TRUE(r.invalid_input);
    EXPECT_NE(r.error.find(c.message), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("another mesh"), std::string::npos) << r.error;
    EXPECT_TRUE(untouched());
  }
  SWN::Solve_report r;   // the mesh's own maps: solved, the meridian is G
  ASSERT_TRUE(CGAL::surface_winding_numbers(tm, chain, labels, SWN::parameters::nonbounding_chain_map(G, SWN::parameters::report(std::ref(r))))) << r.error;
  for(auto e : edges(tm)) EXPECT_EQ(G[e], chain[e]);
}

// Scaling is exact and the method scale invariant: 1e160 (areas would overflow) and 1e-160 (they would
// underflow) give the labels, G and w of the unit-size torus.
TEST(OraclesScale, ExtremeUnitsSolveLikeTheUnitMesh)
{
  const Soup unit = make_torus(kNu, kNv, seed(122));
  Soup_chain c = torus_square(2, 2, 7, 6);
  for(const auto& kv : meridian(9)) c[kv.first] += kv.second;
  auto mu = make_mesh<SM>(unit);
  const Outcome ref = run(*mu, c);
  ASSERT_TRUE(ref.ok) << ref.rep.error;
  for(double scale : {1e160, 1e-160})
  {
    Soup s = unit;
    for(Point_3& p : s.points) p = Point_3(p.x() * scale, p.y() * scale, p.z() * scale);
    auto ms = make_mesh<SM>(s);
    const Outcome o = run(*ms, c);
    ASSERT_TRUE(o.ok) << scale << ": " << o.rep.error;
    EXPECT_EQ(o.W, ref.W) << scale;
    EXPECT_EQ(o.G, ref.G) << scale;
    for(std::size_t f = 0; f < ref.w.size(); ++f)
      for(int k = 0; k < 3; ++k) EXPECT_NEAR(o.w[f][k], ref.w[f][k], 1e-9) << scale << " face " << f;
  }
}

// ==========================================================================================
// Self-tests of the harness: the checks above must be able to fail.
// ==========================================================================================


TEST(OraclesHarness, SoupChainRoundTripThroughMeshEdges)
{
  // set_chain (soup -> mesh, relative to the reference halfedges) and Built_mesh::key (mesh ->
  // soup) are inverse, on both data structures, for both orientations of every edge.
  auto check = [](auto& m) {
    Soup_chain c;
    add_loop(c, torus_rect_loop(kNu, kNv, 4, 3, 10, 8));
    add_loop(c, reversed(torus_meridian(kNu, kNv, 6)), 3);
    std::unordered_map<typename std::decay_t<decltype(m)>::edge_descriptor, int> mp;
    for(auto e : edges(m.tm)) mp[e] = 0;
    set_chain(m, c, mp);
    Soup_chain back;
    for(auto e : edges(m.tm))
      if(mp[e] != 0) { auto ks = m.key(e); back[ks.first] = mp[e] * ks.second; }
    EXPECT_TRUE(back == c) << to_string(back) << "\nvs " << to_string(c);
    // the reference halfedge agrees with the library's helper
    std::unordered_map<typename std::decay_t<decltype(m)>::edge_descriptor, int> lib;
    for(auto e : edges(m.tm)) lib[e] = 0;
    auto pm = boost::make_assoc_property_map(lib);
    std::vector<typename std::decay_t<decltype(m)>::halfedge_descriptor> hs;
    for(const auto& kv : c)
      for(int k = 0; k < std::abs(kv.second); ++k)
        hs.push_back(kv.second > 0 ? m.halfedge_of(kv.first.first, kv.first.second)
                                   : m.halfedge_of(kv.first.second, kv.first.first));
    SWN::add_halfedges_to_chain(m.tm, hs, pm);
    for(auto e : edges(m.tm)) EXPECT_EQ(lib[e], mp[e]);
  };
  auto a = make_mesh<SM>(make_torus(kNu, kNv, 5));
  auto b = make_mesh<PH>(make_torus(kNu, kNv, 5));
  check(*a);
  check(*b);
}

TEST(OraclesHarness, ChecksDetectCorruptedOutcomes)
{
  auto m = make_mesh<SM>(make_disk(kDiskN, 7));
  Soup_chain c;
  add_loop(c, d_loop());
  const Outcome good = run(*m, c);
  check_common(good);
  const auto in = d_inside(m->soup), out = d_outside(m->soup);

  Outcome bad = good;   // a wrong label breaks B == JW
  bad.W[in.front()] += 1;
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "B != JW"));

  bad = good;   // G that is not the rounding of g
  bad.G[*good.all_edges.begin()] = 1;
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "G != R(g)"));

  bad = good;   // NaN away from endpoints
  bad.w[0][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "interior endpoint"));

  bad = good;   // a B that is not closed
  bad.B.erase(bad.B.begin());
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "interior vertex"));

  bad = good;   // normalization: shift all labels
  for(int& l : bad.W) l += 5;
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "largest-area label"));

  bad = good;   // wrong difference / wrong absolute value
  EXPECT_TRUE(fails_with([&] { expect_regions(bad, d_inside(m->soup), d_outside(m->soup), -1); }, "W(A)=1 W(B)=0"));
  EXPECT_TRUE(fails_with([&] { expect_regions(bad, d_inside(m->soup), d_outside(m->soup), 1, 2, 1); }, "absolute label"));

  bad = good;   // B = chain - G on curve edges
  bad.G = c;
  EXPECT_TRUE(fails_with([&] { check_closed_decomposition(bad); }, "chain - G"));

  bad = good;   // w not two-valued
  bad.w[in.front()][0] += 1e-3;
  EXPECT_TRUE(fails_with([&] { expect_w_two_valued(bad, d_inside(m->soup), d_outside(m->soup), 1.0, kTolW); }, "w not constant on region A"));
}

