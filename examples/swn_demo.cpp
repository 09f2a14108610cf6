// Surface winding numbers of a broken curve on a torus: a contractible loop with a gap (it bounds
// a region) and a meridian with a gap (it goes around the handle and bounds nothing).
//
// Usage: swn_demo [output.off]   (writes the mesh with per-face labels as colours if a path is given)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SWN = CGAL::Surface_winding_numbers;

int main(int argc, char** argv)
{
  // A torus of revolution (R = 1, r = 0.4), nu x nv quads split into triangles.
  const int nu = 48, nv = 24;
  const double R = 1., r = 0.4, pi = 3.14159265358979323846;
  Mesh mesh;
  std::vector<Vertex> grid;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
      grid.push_back(mesh.add_vertex(K::Point_3((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
                                                r * std::sin(b))));
    }
  auto V = [&](int i, int j) { return grid[((i % nu + nu) % nu) * nv + (j % nv + nv) % nv]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      mesh.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1));
      mesh.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1));
    }

  // The curve: an integer chain on the edges, built from vertex polylines.
  auto chain = mesh.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  std::vector<Vertex> meridian, loop;
  for(int j = 0; j <= nv; ++j)
    if(j < 10 || j > 11) meridian.push_back(V(0, j));               // gap of 2 edges at j = 10..11
  for(int i = 16; i <= 28; ++i) loop.push_back(V(i, 4));            // a counter-clockwise loop on the outer side
  for(int j = 5; j <= 12; ++j) loop.push_back(V(28, j));
  for(int i = 27; i >= 16; --i) loop.push_back(V(i, 12));
  for(int j = 11; j >= 6; --j) loop.push_back(V(16, j));             // gap of 2 edges at the end
  std::vector<Vertex> meridian_a(meridian.begin(), meridian.begin() + 10), meridian_b(meridian.begin() + 10, meridian.end());
  if(!SWN::add_vertex_polyline_to_chain(mesh, meridian_a, chain) || !SWN::add_vertex_polyline_to_chain(mesh, meridian_b, chain) ||
     !SWN::add_vertex_polyline_to_chain(mesh, loop, chain))
  {
    std::cerr << "error: a polyline does not follow mesh edges\n";
    return 1;
  }

  auto labels = mesh.add_property_map<Mesh::Face_index, int>("f:label", 0).first;
  auto G = mesh.add_property_map<Mesh::Edge_index, int>("e:G", 0).first;
  auto bounding = mesh.add_property_map<Mesh::Edge_index, int>("e:bounding", 0).first;
  SWN::Solve_report report;
  const bool ok = CGAL::surface_winding_numbers(
    mesh, chain, labels,
    SWN::parameters::nonbounding_chain_map(G, SWN::parameters::bounding_chain_map(bounding, SWN::parameters::report(std::ref(report)))));
  if(!ok)
  {
    std::cerr << "error: " << report.error << "\n";
    return 1;
  }

  std::map<int, int> faces_per_label;
  for(auto f : faces(mesh)) ++faces_per_label[labels[f]];
  std::size_t curve_edges = 0, G_edges = 0, G_on_meridian = 0, bounding_edges = 0;
  for(auto e : edges(mesh))
  {
    curve_edges += chain[e] != 0;
    G_edges += G[e] != 0;
    bounding_edges += bounding[e] != 0;
    const Vertex s = source(halfedge(e, mesh), mesh), t = target(halfedge(e, mesh), mesh);
    G_on_meridian += (G[e] != 0 && (std::size_t(s) / nv == 0) && (std::size_t(t) / nv == 0));
  }
  std::cout << "torus: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces, genus " << report.genus << "\n"
            << "curve: " << curve_edges << " edges, " << report.interior_endpoints << " interior endpoints\n"
            << "labels (W) per region:\n";
  for(const auto& fl : faces_per_label) std::cout << "  W = " << fl.first << ": " << fl.second << " faces\n";
  std::cout << "nonbounding loops G: " << G_edges << " edges (" << G_on_meridian << " on the meridian, of " << nv << ")\n"
            << "bounding chain: " << bounding_edges << " edges (the completed loop)\n"
            << "residual LP: " << (report.lp_ran ? "ran" : "skipped") << ", " << report.lp_variables << " variables, "
            << report.time_total << " s in total\n";

  if(argc > 1)
  {
    std::ofstream out(argv[1]);
    out << "COFF\n" << num_vertices(mesh) << ' ' << num_faces(mesh) << " 0\n";
    for(auto v : vertices(mesh)) out << mesh.point(v) << '\n';
    for(auto f : faces(mesh))
    {
      out << 3;
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) out << ' ' << std::size_t(v);
      out << (labels[f] == 0 ? " 200 200 200\n" : labels[f] > 0 ? " 220 60 40\n" : " 40 80 220\n");
    }
    std::cout << "wrote " << argv[1] << "\n";
  }
  // the inside of the loop is 12 x 8 quads, and G is the whole meridian
  return (faces_per_label.size() == 2 && faces_per_label[1] == 2 * 12 * 8 && G_on_meridian == std::size_t(nv)) ? 0 : 1;
}
