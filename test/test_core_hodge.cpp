// test_core: the Hodge step (Derivatives: the Darboux and jump derivatives; HarmonicPart).
#include "test_core_support.h"

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

