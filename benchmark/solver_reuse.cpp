// Many closed curves on one mesh with the solver class: what the kept factorization saves.
//
//   solver_reuse MESH N [broken]
//   solver_reuse sketch NU NV N
//
// Solves N small closed loops (the links of N vertices spread over the mesh; with `broken`, each with one
// edge left out, so that it has two interior endpoints) one after the other with
// one Surface_winding_numbers_solver and prints, per solve, whether the jump Laplacian's factorization
// was kept from an earlier solve (Solve_report::jump_laplacian_reused; for broken loops, with a low-rank
// update for their endpoints, jump_laplacian_update_rank) and the report's timings. Not a
// test: see RESULTS.md ("Speed") for the numbers. Build (from the repository root):
//   g++ -std=gnu++17 -O2 -DNDEBUG -frounding-math -DCGAL_EIGEN3_ENABLED -DCGAL_SWN_USE_CHOLMOD \
//     -DCGAL_SWN_USE_LEMON -Iinclude -isystem /usr/include/eigen3 -isystem /usr/include/suitesparse \
//     benchmark/solver_reuse.cpp -o solver_reuse -lgmp -lmpfr -llemon -lcholmod -pthread

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;

// The paper's sketching use (Sec. 5.3) on a torus of nu x nv quads (2 nu nv faces): a meridian with a
// gap, kept, and a square stroke with a gap, moved by one step along the torus before each solve. Prints
// each solve, then checks every stroke's labels and G against a fresh surface_winding_numbers() call.
int sketch(int nu, int nv, int n)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v(std::size_t(nu) * std::size_t(nv));
  const double R = 3, r = 1, pi = 3.14159265358979323846;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
      v[std::size_t(i * nv + j)] = m.add_vertex(K::Point_3((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)));
    }
  const auto at = [&](int i, int j) { return v[std::size_t(((i % nu + nu) % nu) * nv + (j % nv + nv) % nv)]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  const int side = nv / 4;
  // the curves of stroke k
  const auto chain_of = [&](int k) {
    std::vector<int> chain(num_edges(m), 0);
    const auto chain_map = CGAL::make_property_map(chain);
    std::vector<Mesh::Vertex_index> meridian, stroke;
    for(int j = 1; j <= nv - 2; ++j) meridian.push_back(at(nu / 8, j));   // a gap of 3 edges
    const int i0 = nu / 2 + k, j0 = nv / 4;
    for(int t = 0; t < side; ++t) stroke.push_back(at(i0 + t, j0));
    for(int t = 0; t < side; ++t) stroke.push_back(at(i0 + side, j0 + t));
    for(int t = 0; t < side; ++t) stroke.push_back(at(i0 + side - t, j0 + side));
    for(int t = 0; t < side - 1; ++t) stroke.push_back(at(i0, j0 + side - t));   // a gap of 1 edge
    SWN::add_vertex_polyline_to_chain(m, meridian, chain_map);
    SWN::add_vertex_polyline_to_chain(m, stroke, chain_map);
    return chain;
  };
  // the strokes one after the other on one solver, as a sketching session runs them (the fresh solves
  // that check them come afterwards: between re-solves they would leave the allocator's heap grown)
  std::vector<std::vector<int>> labels{std::size_t(n)}, G{std::size_t(n)};
  for(int k = 0; k < n; ++k)
  {
    std::vector<int> chain = chain_of(k);
    labels[std::size_t(k)].assign(num_faces(m), 0);
    G[std::size_t(k)].assign(num_edges(m), 0);
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = solver.solve(CGAL::make_property_map(chain), CGAL::make_property_map(labels[std::size_t(k)]),
                                 SWN::parameters::nonbounding_chain_map(CGAL::make_property_map(G[std::size_t(k)])));
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const SWN::Solve_report& r = solver.report();
    std::cout << "stroke " << k << (ok ? " ok" : " failed") << ": jump Laplace " << r.time_jump_laplace << " s (update rank "
              << r.jump_laplacian_update_rank << "), Hodge " << r.time_hodge << " s, residual " << r.time_residual
              << " s, second solve " << r.time_second_solve << " s (warm " << r.residual_warm_started << "), labels "
              << r.time_labels << " s, whole " << t << " s\n";
    if(!ok) return 1;
  }
  for(int k = 0; k < n; ++k)
  {
    std::vector<int> chain = chain_of(k);
    std::vector<int> fresh_labels(num_faces(m), 0), fresh_G(num_edges(m), 0);
    const auto t1 = std::chrono::steady_clock::now();
    const bool fresh_ok = CGAL::surface_winding_numbers(m, CGAL::make_property_map(chain), CGAL::make_property_map(fresh_labels),
                                                        SWN::parameters::nonbounding_chain_map(CGAL::make_property_map(fresh_G)));
    const double t_fresh = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    const bool same = fresh_ok && fresh_labels == labels[std::size_t(k)] && fresh_G == G[std::size_t(k)];
    std::cout << "stroke " << k << ": fresh solve " << t_fresh << " s, " << (same ? "same" : "DIFFERENT") << " labels and G\n";
    if(!same) return 1;
  }
  return 0;
}

int main(int argc, char** argv)
{
  if(argc == 5 && std::string(argv[1]) == "sketch") return sketch(std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4]));
  Mesh m;
  if(argc < 3 || !CGAL::IO::read_polygon_mesh(argv[1], m) || is_empty(m))
  {
    std::cerr << "usage: solver_reuse MESH N [broken] (MESH: a triangle mesh CGAL can read)\n";
    return 1;
  }
  const int n = std::atoi(argv[2]);
  const bool broken = argc > 3 && std::string(argv[3]) == "broken";
  SWN::Surface_winding_numbers_solver<Mesh> solver(m);
  auto labels = get(CGAL::dynamic_face_property_t<int>(), m);
  for(int k = 0; k < n; ++k)
  {
    // the link of a vertex: a small closed loop
    const auto v = *std::next(vertices(m).begin(), std::ptrdiff_t((std::size_t(k) * 7919u) % num_vertices(m)));
    auto chain = get(CGAL::dynamic_edge_property_t<int>(), m);
    for(auto e : edges(m)) put(chain, e, 0);
    std::vector<Mesh::Vertex_index> link;
    for(auto h : halfedges_around_target(halfedge(v, m), m)) link.push_back(source(h, m));
    if(!broken) link.push_back(link.front());
    SWN::add_vertex_polyline_to_chain(m, link, chain);
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = solver.solve(chain, labels);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const SWN::Solve_report& r = solver.report();
    std::cout << "solve " << k << (ok ? " ok" : " failed") << ", interior endpoints " << r.interior_endpoints
              << ", jump Laplacian kept " << r.jump_laplacian_reused << ", residual warm " << r.residual_warm_started << " (update rank " << r.jump_laplacian_update_rank
              << "): jump Laplace " << r.time_jump_laplace
              << " s, residual " << r.time_residual << " s, second solve " << r.time_second_solve << " s, whole " << t
              << " s\n";
  }
}
