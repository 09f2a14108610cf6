// Shared set-up of the test_core sources: meshes, their flat tables and small helpers.
#ifndef SWN_TEST_CORE_SUPPORT_H
#define SWN_TEST_CORE_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/surface_winding_numbers.h>
#ifdef CGAL_USE_GLPK
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#endif
#include <CGAL/Surface_winding_numbers/internal/locality_order.h>
#include <CGAL/Surface_winding_numbers/internal/pipeline.h>

#include <Eigen/SparseCholesky>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <map>
#include <memory>
#include <random>
#include <thread>
#include <utility>
#include <vector>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SI = CGAL::Surface_winding_numbers::internal;
typedef SI::Default_sparse_solver LA;
typedef SWN::Surface_winding_numbers_solver<Mesh> Solver;

const double inf = std::numeric_limits<double>::infinity();
const double NaN = std::numeric_limits<double>::quiet_NaN();

// n x n grid on [0,1]^2 (a disk), diagonals chosen at random; vertex (i, j) is vs[j * (n + 1) + i]
std::vector<Vertex> grid_disk(Mesh& m, int n, unsigned seed = 1, double jitter = 0.2)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-jitter / n, jitter / n);
  std::vector<Vertex> vs;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      vs.push_back(m.add_vertex(K::Point_3(double(i) / n + (border ? 0 : U(rng)), double(j) / n + (border ? 0 : U(rng)), 0)));
    }
  auto V = [&](int i, int j) { return vs[j * (n + 1) + i]; };
  std::bernoulli_distribution coin(0.5);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      if(coin(rng)) { m.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1)); m.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1)); }
      else { m.add_face(V(i, j), V(i + 1, j), V(i, j + 1)); m.add_face(V(i + 1, j), V(i + 1, j + 1), V(i, j + 1)); }
  return vs;
}

// nu x nv torus of revolution; vertex (i, j) is vs[i * nv + j], cell (i, j) the faces 2 (i nv + j) and 2 (i nv + j) + 1
std::vector<Vertex> torus_mesh(Mesh& m, int nu, int nv)
{
  const double pi = 3.14159265358979323846;
  std::vector<Vertex> vs;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
      vs.push_back(m.add_vertex(K::Point_3((1 + 0.4 * std::cos(b)) * std::cos(a), (1 + 0.4 * std::cos(b)) * std::sin(a), 0.4 * std::sin(b))));
    }
  auto V = [&](int i, int j) { return vs[((i % nu + nu) % nu) * nv + (j % nv + nv) % nv]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) { m.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1)); m.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1)); }
  return vs;
}

// the chain of vertex polylines as a vector indexed like the solver's tables
std::vector<double> table_chain(const Mesh& m, const Solver& s, const std::vector<std::vector<Vertex>>& polylines)
{
  auto map = get(CGAL::dynamic_edge_property_t<int>(), m);
  for(auto e : edges(m)) put(map, e, 0);
  for(const auto& p : polylines) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m, p, map));
  std::vector<double> c(num_edges(m), 0.);
  for(auto e : edges(m)) c[s.edge_index(e)] = get(map, e);
  return c;
}

std::vector<double> negated(std::vector<double> x)
{
  for(double& v : x) v = -v;
  return x;
}

// the rectangle of grid vertices at(i, j) with corners (i0, j0), (i1, j1), walked counter-clockwise in
// (i, j) from (i0, j0) back to it
template <class At>
std::vector<Vertex> rect_loop(const At& at, int i0, int j0, int i1, int j1)
{
  std::vector<Vertex> loop;
  for(int i = i0; i < i1; ++i) loop.push_back(at(i, j0));
  for(int j = j0; j < j1; ++j) loop.push_back(at(i1, j));
  for(int i = i1; i > i0; --i) loop.push_back(at(i, j1));
  for(int j = j1; j >= j0; --j) loop.push_back(at(i0, j));
  return loop;
}

// vertex (i, j) of grid_disk(n), of torus_mesh(nu, nv) (j modulo nv)
std::function<Vertex(int, int)> grid_vertex(const std::vector<Vertex>& vs, int n)
{
  return [&vs, n](int i, int j) { return vs[std::size_t(j * (n + 1) + i)]; };
}
std::function<Vertex(int, int)> torus_vertex(const std::vector<Vertex>& vs, int nv)
{
  return [&vs, nv](int i, int j) { return vs[std::size_t(i * nv + j % nv)]; };
}

std::vector<Vertex> square_loop(const std::vector<Vertex>& vs, int n, int i0, int j0, int i1, int j1)
{
  return rect_loop(grid_vertex(vs, n), i0, j0, i1, j1);
}

// the polyline (i, j0), (i, j0 + 1), ..., (i, j1) of a grid_disk(n): a vertical path
std::vector<Vertex> grid_column(const std::vector<Vertex>& vs, int n, int i, int j0, int j1)
{
  std::vector<Vertex> p;
  for(int j = j0; j <= j1; ++j) p.push_back(grid_vertex(vs, n)(i, j));
  return p;
}

// the polyline (i, j0), ..., (i, j1) along a meridian of torus_mesh(nu, nv) (j modulo nv)
std::vector<Vertex> meridian_piece(const std::vector<Vertex>& vs, int nv, int i, int j0, int j1)
{
  std::vector<Vertex> p;
  for(int j = j0; j <= j1; ++j) p.push_back(torus_vertex(vs, nv)(i, j));
  return p;
}

// the polyline without its last k vertices
std::vector<Vertex> without_last(std::vector<Vertex> p, std::size_t k)
{
  p.resize(p.size() - k);
  return p;
}

// per face of the tables: 1 if the centroid lies in the open rectangle (x0, x1) x (y0, y1)
std::vector<char> faces_in_rect(const SI::Mesh_tables& t, double x0, double y0, double x1, double y1)
{
  std::vector<char> in(t.nf, 0);
  for(std::size_t f = 0; f < t.nf; ++f)
  {
    double x = 0, y = 0;
    for(int k = 0; k < 3; ++k) { x += t.point(t.fv[3 * f + k])[0] / 3; y += t.point(t.fv[3 * f + k])[1] / 3; }
    x /= t.point_scale;   // back to the mesh's unit (the tables' points are scaled to a unit box)
    y /= t.point_scale;
    in[f] = x > x0 && x < x1 && y > y0 && y < y1;
  }
  return in;
}

// per corner: the value of its face
std::vector<double> per_corner(const std::vector<double>& per_face)
{
  std::vector<double> w(3 * per_face.size());
  for(std::size_t c = 0; c < w.size(); ++c) w[c] = per_face[c / 3];
  return w;
}

// the corner of face f at vertex v, found without Mesh_tables::corner_at
std::size_t corner_of(const SI::Mesh_tables& t, std::size_t f, std::size_t v)
{
  for(std::size_t c = 3 * f; c < 3 * f + 3; ++c)
    if(t.fv[c] == v) return c;
  ADD_FAILURE() << "vertex " << v << " is not a corner of face " << f;
  return 3 * f;
}

double max_abs(const std::vector<double>& x)
{
  double r = 0;
  for(double v : x) r = std::max(r, std::abs(v));
  return r;
}

std::vector<double> random_values(std::size_t n, unsigned seed, double lo = -1, double hi = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(lo, hi);
  std::vector<double> x(n);
  for(double& v : x) v = U(rng);
  return x;
}

// the differential of a vertex function: phi(head) - phi(tail) on every edge
std::vector<double> differential(const SI::Mesh_tables& t, const std::vector<double>& phi)
{
  std::vector<double> d(t.ne);
  for(std::size_t e = 0; e < t.ne; ++e) d[e] = phi[t.ev[2 * e + 1]] - phi[t.ev[2 * e]];
  return d;
}

// the message of the Solver_failure that f throws, "<none>" if it throws none
template <class F>
std::string failure_message(F f)
{
  try { f(); }
  catch(const SWN::Solver_failure& e) { return e.what(); }
  return "<none>";
}

// a generated mesh, its vertices in the generator's order, and its solver (built by the derived class)
struct Mesh_and_tables
{
  Mesh mesh;
  std::vector<Vertex> vs;
  std::unique_ptr<Solver> solver;
  void make_solver()
  {
    solver.reset(new Solver(mesh));
    EXPECT_TRUE(solver->is_valid()) << solver->report().error;
  }
  const SI::Mesh_tables& tables() const { return solver->tables(); }
  // vertex polylines as a chain indexed like the tables
  std::vector<double> chain(const std::vector<std::vector<Vertex>>& polylines) const { return table_chain(mesh, *solver, polylines); }
};

// grid_disk(n, seed, jitter): vertex V(i, j)
struct Grid_tables : Mesh_and_tables
{
  int n;
  Grid_tables(int n_, unsigned seed = 1, double jitter = 0.2) : n(n_)
  {
    vs = grid_disk(mesh, n, seed, jitter);
    make_solver();
  }
  Vertex V(int i, int j) const { return grid_vertex(vs, n)(i, j); }
};

// torus_mesh(nu, nv) and its cotan weights w
struct Torus_tables : Mesh_and_tables
{
  std::vector<double> w;
  Torus_tables(int nu, int nv)
  {
    vs = torus_mesh(mesh, nu, nv);
    make_solver();
    SI::cotan_weights(tables(), w);
  }
};

// labels and G of one solve, by the solver class or by the free function, to compare
struct Labels_and_G
{
  std::map<Mesh::Face_index, int> labels;
  std::map<Mesh::Edge_index, int> G;
  template <class Chain, class NP = decltype(CGAL::parameters::default_values())>
  bool solve(Solver& solver, const Chain& chain, const NP& np = CGAL::parameters::default_values())
  {
    return solver.solve(chain, boost::make_assoc_property_map(labels),
                        SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G), np));
  }
  template <class Chain>
  bool solve(const Mesh& m, const Chain& chain)
  {
    return CGAL::surface_winding_numbers(m, chain, boost::make_assoc_property_map(labels),
                                         SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G)));
  }
  void expect_equal(const Labels_and_G& other) const
  {
    EXPECT_EQ(labels, other.labels);
    EXPECT_EQ(G, other.G);
  }
};

// a torus_mesh(nu, nv) with its factorized 0-form Laplacian (the jump Laplacian with nothing excluded)
struct Torus_with_0form_laplacian : Torus_tables
{
  SI::Jump_laplace_system<LA> L0;
  Torus_with_0form_laplacian(int nu, int nv) : Torus_tables(nu, nv)
  {
    L0.jump_laplacian(tables(), w, std::vector<char>(tables().nv, 0));
  }
};

// ASSERTs that order is a permutation of 0 .. n-1
void expect_permutation(std::vector<std::size_t> order, std::size_t n)
{
  std::sort(order.begin(), order.end());
  ASSERT_EQ(order.size(), n);
  for(std::size_t k = 0; k < n; ++k) ASSERT_EQ(order[k], k);
}
} // namespace

#endif // SWN_TEST_CORE_SUPPORT_H
