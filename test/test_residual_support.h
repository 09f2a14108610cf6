// Helpers of the residual solver tests (test_residual*.cpp): random residual problems on dual graphs
// of grids, GLPK's optimum, torus meshes and the pipeline's residual problems.
#ifndef SWN_TEST_RESIDUAL_SUPPORT_H
#define SWN_TEST_RESIDUAL_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#include <CGAL/Surface_winding_numbers/LEMON_residual_solver.h>
#include <CGAL/Surface_winding_numbers/internal/pipeline.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/boykov_kolmogorov_flow.h>
#include <CGAL/Surface_winding_numbers/internal/residual_flow/warm_push_relabel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace residual_test {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SI = CGAL::Surface_winding_numbers::internal;
typedef SI::Default_sparse_solver LA;
typedef SWN::LEMON_residual_solver Lemon;
typedef Lemon::Options Options;

inline Options with_algorithm(Lemon::Algorithm a)
{
  Options o;
  o.algorithm = a;
  return o;
}

constexpr double inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// Random residual problems on the dual graph of an nu x nv grid of quads cut into two triangles
// (T0 below the diagonal, T1 above). Periodic in both directions (torus) or not (disk, whose
// border edges are no arcs). Every arc is oriented with its left face "above" (horizontal edges),
// "left" (vertical edges) or T1 (diagonals), so a cochain that is constant on a row of
// horizontal edges is closed.
struct Grid
{
  int nu, nv;
  bool periodic;
  std::size_t face0;   // index of the first face in the problem
  std::size_t T(int k, int i, int j) const { return face0 + 2 * (std::size_t(j) * nu + std::size_t(i)) + std::size_t(k); }
  std::size_t faces() const { return 2 * std::size_t(nu) * std::size_t(nv); }
};

enum Edge_kind { HORIZONTAL, VERTICAL, DIAGONAL };

struct Grid_arc
{
  Edge_kind kind;
  int i, j;   // horizontal: edge (i,j)-(i+1,j); vertical: (i,j)-(i,j+1); diagonal: cell (i,j)
};

// appends the arcs of grid g to P (s, cost, bounds left free/zero) and returns their grid positions
inline std::vector<Grid_arc> add_grid_arcs(const Grid& g, SWN::Residual_problem& P)
{
  std::vector<Grid_arc> pos;
  auto add = [&](std::size_t L, std::size_t R, Grid_arc a) {
    P.left.push_back(L); P.right.push_back(R); P.s.push_back(0.); P.cost.push_back(1.);
    P.lower.push_back(-inf); P.upper.push_back(inf);
    pos.push_back(a);
  };
  for(int j = 0; j < g.nv; ++j)
    for(int i = 0; i < g.nu; ++i)
    {
      add(g.T(1, i, j), g.T(0, i, j), {DIAGONAL, i, j});
      // horizontal edge at the bottom of cell (i,j): above T0(i,j), below T1(i,j-1)
      if(j > 0 || g.periodic) add(g.T(0, i, j), g.T(1, i, (j + g.nv - 1) % g.nv), {HORIZONTAL, i, j});
      // vertical edge at the left of cell (i,j): right of it T1(i,j), left T0(i-1,j)
      if(i > 0 || g.periodic) add(g.T(0, (i + g.nu - 1) % g.nu, j), g.T(1, i, j), {VERTICAL, i, j});
    }
  return pos;
}

struct Random_problem
{
  SWN::Residual_problem P;
  std::vector<std::size_t> bounded;   // arcs with finite bounds
};

// closed_s: s = differences of a random potential + periods on the rows j = 0 and columns i = 0
// (like real data); otherwise s is chosen so that a random sigma* with |sigma*| <= s_scale / 2 is
// feasible (s up to about s_scale, not closed).
// Curve arcs: a horizontal and a vertical loop with gaps, and a contractible rectangle, with
// multiplicities up to 3 and random orientations: bounds [0, G] or [G, 0].
inline void randomize(Random_problem& rp, const Grid& g, const std::vector<Grid_arc>& pos, std::size_t first_arc,
               std::mt19937& rng, bool closed_s, double s_scale)
{
  SWN::Residual_problem& P = rp.P;
  std::uniform_real_distribution<double> U01(0., 1.);
  std::uniform_int_distribution<int> mult(1, 3), coin(0, 1);
  const double eps = 0.01;
  std::vector<double> phi(g.faces());
  for(double& x : phi) x = s_scale * (U01(rng) - 0.5);
  const double alpha = (U01(rng) - 0.5) * 3, beta = (U01(rng) - 0.5) * 3;
  const int row = int(rng() % unsigned(g.nv)), col = int(rng() % unsigned(g.nu));
  const int G_row = (coin(rng) ? 1 : -1) * mult(rng), G_col = (coin(rng) ? 1 : -1) * mult(rng);
  const int i0 = int(rng() % unsigned(g.nu)), j0 = int(rng() % unsigned(g.nv));
  const int w = 2 + int(rng() % 3u), h = 2 + int(rng() % 3u);
  const int G_rect = (coin(rng) ? 1 : -1) * mult(rng);
  for(std::size_t k = 0; k < pos.size(); ++k)
  {
    const std::size_t a = first_arc + k;
    const Grid_arc& e = pos[k];
    const double len = 0.5 + U01(rng);
    P.cost[a] = len;
    // curve membership
    int G = 0;
    const bool gap = U01(rng) < 0.2;
    if(!gap)
    {
      if(e.kind == HORIZONTAL && e.j == row && g.periodic) G += G_row;   // edges along row `row` are crossed vertically
      if(e.kind == VERTICAL && e.i == col && g.periodic) G += G_col;
      // rectangle [i0, i0+w] x [j0, j0+h] (no wrap): its horizontal sides and vertical sides
      if(e.kind == HORIZONTAL && (e.j == j0 || e.j == j0 + h) && e.i >= i0 && e.i < i0 + w && j0 + h < g.nv && i0 + w < g.nu)
        G += e.j == j0 ? G_rect : -G_rect;
      if(e.kind == VERTICAL && (e.i == i0 || e.i == i0 + w) && e.j >= j0 && e.j < j0 + h && j0 + h < g.nv && i0 + w < g.nu)
        G += e.i == i0 ? -G_rect : G_rect;
    }
    const std::size_t L = P.left[a] - g.face0, R = P.right[a] - g.face0;
    if(G != 0)
    {
      P.cost[a] = eps * len;
      P.lower[a] = std::min(0, G);
      P.upper[a] = std::max(0, G);
      rp.bounded.push_back(a);
    }
    if(closed_s)
    {
      double period = 0;
      if(g.periodic && e.kind == HORIZONTAL && e.j == 0) period += alpha;
      if(g.periodic && e.kind == VERTICAL && e.i == 0) period += beta;
      P.s[a] = phi[R] - phi[L] + period;
    }
    else
    {
      // J* within the bounds (or anywhere near 0 on free arcs) for sigma = phi
      const double Jstar = G != 0 ? G * U01(rng) : (U01(rng) - 0.5);
      P.s[a] = Jstar - phi[L] + phi[R];
    }
  }
}

inline Random_problem random_problem(unsigned seed, bool closed_s, double s_scale, bool several_components)
{
  std::mt19937 rng(seed);
  Random_problem rp;
  std::vector<Grid> grids;
  grids.push_back(Grid{8 + int(rng() % 8u), 6 + int(rng() % 8u), true, 0});
  if(several_components)
  {
    grids.push_back(Grid{6 + int(rng() % 6u), 5 + int(rng() % 6u), false, 0});
    grids.push_back(Grid{7, 5, true, 0});
  }
  std::size_t nf = 0;
  for(Grid& g : grids) { g.face0 = nf; nf += g.faces(); }
  rp.P.number_of_faces = nf + (several_components ? 1 : 0);   // plus an isolated face
  for(const Grid& g : grids)
  {
    const std::size_t first = rp.P.number_of_arcs();
    const std::vector<Grid_arc> pos = add_grid_arcs(g, rp.P);
    randomize(rp, g, pos, first, rng, closed_s, s_scale);
    rp.P.gauge_faces.push_back(g.face0 + rng() % g.faces());
  }
  if(several_components) rp.P.gauge_faces.push_back(nf);
  return rp;
}

// GLPK's optimum (through the package's LP formulation) and its objective
inline double glpk_optimum(const SWN::Residual_problem& P, std::vector<double>& sigma)
{
  SWN::GLPK_linear_program_traits lp;
  double objective = 0;
  std::size_t nv = 0, nr = 0;
  sigma = SI::solve_residual_with_lp(P, lp, nv, nr);
  objective = P.objective(sigma);
  return objective;
}

// LEMON's sigma is feasible and optimal: its objective equals GLPK's optimum to 1e-7 relative and
// is never larger; gauge faces get 0
inline void expect_solver_matches_glpk(Lemon& lemon, const SWN::Residual_problem& P, const std::string& what,
                                double* lemon_objective = nullptr)
{
  std::vector<double> sigma;
  ASSERT_TRUE(lemon.solve_residual(P, sigma)) << what << ": " << lemon.error();
  ASSERT_EQ(sigma.size(), P.number_of_faces);
  EXPECT_TRUE(lemon.error().empty());
  EXPECT_TRUE(lemon.statistics().certified) << what;
  EXPECT_LE(P.max_violation(sigma), 1e-9) << what;
  std::vector<double> sigma_glpk;
  const double og = glpk_optimum(P, sigma_glpk);
  const double ol = P.objective(sigma);
  EXPECT_NEAR(ol, lemon.statistics().objective, 1e-12 * (1 + ol));
  EXPECT_NEAR(ol, og, 1e-7 * (1 + og)) << what << " (lemon " << ol << ", glpk " << og << ")";
  EXPECT_LE(ol, og + 1e-7 * (1 + og)) << what;
  for(std::size_t f : P.gauge_faces)
    if(f < sigma.size()) EXPECT_EQ(sigma[f], 0.) << what;
  if(lemon_objective) *lemon_objective = ol;
}

inline void expect_matches_glpk(const SWN::Residual_problem& P, Lemon::Algorithm algorithm, const std::string& what,
                         double* lemon_objective = nullptr)
{
  Lemon lemon(with_algorithm(algorithm));
  expect_solver_matches_glpk(lemon, P, what, lemon_objective);
}

// the options of a multilevel solver whose hierarchy goes deep even on small problems, every level's
// carried-down flow balanced inside the coarser regions
inline Options deep_options(std::size_t max_refinements = 8, std::size_t descent_steps = 30)
{
  Options o;
  o.algorithm = Options::MULTILEVEL;
  o.coarsest_nodes = 12;
  o.cluster_size = 4;
  o.band_radius = 1;
  o.max_refinements = max_refinements;
  o.finest_band_radius = 2;
  o.descent_steps = descent_steps;
  o.carried_flow_routing_nodes = 0;
  return o;
}

const Lemon::Algorithm all_algorithms[] = {Options::NETWORK_SIMPLEX, Options::MULTILEVEL};
const unsigned n_algorithms = 2;

// ---------------------------------------------------------------------------------------------
// meshes

inline std::vector<Vertex> torus_mesh(Mesh& m, int nu, int nv, double R = 1, double r = 0.4, double x0 = 0)
{
  const double pi = 3.14159265358979323846;
  std::vector<Vertex> vs;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
      vs.push_back(m.add_vertex(K::Point_3(x0 + (R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b))));
    }
  auto V = [&](int i, int j) { return vs[std::size_t(((i % nu + nu) % nu) * nv + (j % nv + nv) % nv)]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) { m.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1)); m.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1)); }
  return vs;
}

// broken meridian (two pieces) + broken contractible loop on an nu x nv torus starting at vertex vs[0]
inline std::vector<std::vector<Vertex>> broken_curves(const std::vector<Vertex>& vs, int nv, int i_meridian, int i_loop)
{
  std::vector<Vertex> a, b, loop;
  for(int j = 0; j <= 3; ++j) a.push_back(vs[std::size_t(i_meridian * nv + j)]);
  for(int j = 5; j <= nv; ++j) b.push_back(vs[std::size_t(i_meridian * nv + j % nv)]);
  for(int i = i_loop; i <= i_loop + 4; ++i) loop.push_back(vs[std::size_t(i * nv + 2)]);
  for(int j = 3; j <= 5; ++j) loop.push_back(vs[std::size_t((i_loop + 4) * nv + j)]);
  for(int i = i_loop + 3; i >= i_loop + 1; --i) loop.push_back(vs[std::size_t(i * nv + 5)]);
  return {a, b, loop};
}

// the residual problem of the pipeline for the curves `polylines` (steps as in the solver)
inline SWN::Residual_problem pipeline_problem(const Mesh& m, const std::vector<std::vector<Vertex>>& polylines, double epsilon = 0.01)
{
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  EXPECT_TRUE(solver.is_valid());
  auto map = get(CGAL::dynamic_edge_property_t<int>(), m);
  for(auto e : edges(m)) put(map, e, 0);
  for(const auto& p : polylines) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, map));
  std::vector<double> chain(num_edges(m), 0.);
  for(auto e : edges(m)) chain[solver.edge_index(e)] = get(map, e);
  return solver.core().residual_problem_of(chain, epsilon);
}

// the pipeline's residual problem on two tori (36x16 and 24x12) with a broken meridian and a broken
// loop on each: two components, fine enough for a multilevel hierarchy
inline SWN::Residual_problem two_tori_problem()
{
  Mesh m;
  auto vs = torus_mesh(m, 36, 16);
  auto vs2 = torus_mesh(m, 24, 12, 1.2, 0.5, 5.);
  auto curves = broken_curves(vs, 16, 4, 15);
  for(auto& c : broken_curves(vs2, 12, 10, 3)) curves.push_back(c);
  return pipeline_problem(m, curves);
}

// random imbalances of the nodes of a random max-flow problem that sum to zero (added to b)
inline void add_zero_sum_imbalances(std::mt19937& gen, std::vector<long long>& b)
{
  const std::size_t n = b.size();
  for(std::size_t k = 0; k < n; ++k)
  {
    const long long d = (long long)(gen() % 9);
    b[gen() % n] += d;
    b[gen() % n] -= d;
  }
}

} // namespace residual_test

using namespace residual_test;

#endif
