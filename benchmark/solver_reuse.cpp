// Many closed curves on one mesh with the solver class: what the kept factorization saves.
//
//   solver_reuse MESH N [broken]
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
// and run with OPENBLAS_NUM_THREADS=1 OMP_THREAD_LIMIT=1 GLIBC_TUNABLES=glibc.malloc.hugetlb=1, as the swn
// tool runs itself.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;

int main(int argc, char** argv)
{
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
              << ", jump Laplacian kept " << r.jump_laplacian_reused << " (update rank " << r.jump_laplacian_update_rank
              << "): jump Laplace " << r.time_jump_laplace
              << " s, residual " << r.time_residual << " s, second solve " << r.time_second_solve << " s, whole " << t
              << " s\n";
  }
}
