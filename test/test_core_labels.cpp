// test_core: from w to the outputs (WindingNumber, NonboundingChain).
#include "test_core_support.h"

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

TEST(WindingNumber, AnchorFaceGetsLabelZeroInItsComponentAndLabelDifferencesStay)
{
  // two disks, a counter-clockwise square on each: by default inside 1, outside 0. Anchored at a face
  // inside the first square, the first disk's labels drop by one (inside 0, outside -1), w with them;
  // the second disk and G do not change. The same through the polygon soup function.
  Mesh m;
  const int n = 8;
  const auto a = grid_disk(m, n, 1), b = grid_disk(m, n, 2);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:c", 0).first;
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, square_loop(a, n, 1, 1, 4, 4), chain));
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(m, square_loop(b, n, 2, 2, 5, 5), chain));
  auto W0 = m.add_property_map<Mesh::Face_index, int>("f:W0", 0).first;
  auto W1 = m.add_property_map<Mesh::Face_index, int>("f:W1", 0).first;
  auto w0 = m.add_property_map<Mesh::Halfedge_index, double>("h:w0", 0.).first;
  auto w1 = m.add_property_map<Mesh::Halfedge_index, double>("h:w1", 0.).first;
  Solver s(m);
  ASSERT_TRUE(s.solve(chain, W0, SWN::parameters::winding_number_map(w0)));
  const std::size_t first_disk = 2 * n * n;
  Mesh::Face_index inside;
  std::size_t ones = 0;
  for(auto f : faces(m))
  {
    ASSERT_TRUE(W0[f] == 0 || W0[f] == 1);
    if(std::size_t(f) < first_disk && W0[f] == 1) { inside = f; ++ones; }
  }
  ASSERT_EQ(ones, 18u);   // the 3 x 3 squares inside
  ASSERT_TRUE(s.solve(chain, W1, SWN::parameters::label_anchor_face(inside, SWN::parameters::winding_number_map(w1))));
  EXPECT_EQ(W1[inside], 0);
  for(auto f : faces(m)) EXPECT_EQ(W1[f], W0[f] - (std::size_t(f) < first_disk ? 1 : 0));
  for(auto h : halfedges(m))
    if(!is_border(h, m)) EXPECT_NEAR(w1[h], w0[h] - (std::size_t(face(h, m)) < first_disk ? 1 : 0), 1e-12);
  EXPECT_EQ(s.report().min_label, -1);
  // the free function takes it too
  auto W2 = m.add_property_map<Mesh::Face_index, int>("f:W2", 0).first;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, W2, SWN::parameters::label_anchor_face(inside)));
  for(auto f : faces(m)) EXPECT_EQ(W2[f], W1[f]);

  // a face that is not in the mesh: bad input, nothing written
  SWN::Solve_report rep;
  W2[inside] = 42;
  EXPECT_FALSE(CGAL::surface_winding_numbers(m, chain, W2, SWN::parameters::label_anchor_face(
    Mesh::Face_index(num_faces(m) + 3), SWN::parameters::report(std::ref(rep)))));
  EXPECT_TRUE(rep.invalid_input);
  EXPECT_NE(rep.error.find("label_anchor_face"), std::string::npos) << rep.error;
  EXPECT_EQ(W2[inside], 42);

  // the polygon soup of the same mesh, anchored at the same face (a polygon index)
  std::vector<K::Point_3> points;
  for(auto v : vertices(m)) points.push_back(m.point(v));
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f : faces(m))
  {
    triangles.emplace_back();
    std::size_t k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) triangles.back()[k++] = std::size_t(v);
  }
  std::vector<std::pair<std::size_t, std::size_t>> curve;
  for(auto e : edges(m))
    for(int k = 0; k < std::abs(chain[e]); ++k)
    {
      const auto h = chain[e] > 0 ? halfedge(e, m) : opposite(halfedge(e, m), m);
      curve.emplace_back(std::size_t(source(h, m)), std::size_t(target(h, m)));
    }
  std::vector<int> soup_labels(triangles.size(), 7);
  ASSERT_TRUE(CGAL::polygon_soup_winding_numbers(points, triangles, curve, CGAL::make_property_map(soup_labels),
                                                 SWN::parameters::label_anchor_face(std::size_t(inside))));
  for(auto f : faces(m)) EXPECT_EQ(soup_labels[std::size_t(f)], W1[f]);
  EXPECT_FALSE(CGAL::polygon_soup_winding_numbers(points, triangles, curve, CGAL::make_property_map(soup_labels),
                                                  SWN::parameters::label_anchor_face(triangles.size(),
                                                  SWN::parameters::report(std::ref(rep)))));
  EXPECT_TRUE(rep.invalid_input);
  EXPECT_NE(rep.error.find("out of range"), std::string::npos) << rep.error;
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

