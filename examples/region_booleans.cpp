// Booleans of regions drawn with broken curves, and extraction of a region as a mesh.
//
// Two overlapping loops with gaps are drawn on a sphere. One solver (per-mesh work done once) gives
// the labels of each; union, intersection and difference of the two regions are then label
// arithmetic, and the intersection is extracted with CGAL::Face_filtered_graph, ready for any CGAL
// segmentation or remeshing workflow.
//
// Usage: region_booleans [intersection.off]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/surface_winding_numbers.h>

#include <cmath>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SWN = CGAL::Surface_winding_numbers;

// a loop of mesh edges around the direction `axis`: the boundary of the faces whose centroid is
// within `angle` of it, with a few edges removed to make gaps
std::vector<Mesh::Halfedge_index> broken_cap_boundary(const Mesh& m, const K::Vector_3& axis, double angle, int gaps)
{
  auto in_cap = [&](Mesh::Face_index f) {
    K::Vector_3 c(0, 0, 0);
    for(Vertex v : vertices_around_face(halfedge(f, m), m)) c = c + (m.point(v) - CGAL::ORIGIN);
    return c * axis / std::sqrt(c.squared_length() * axis.squared_length()) > std::cos(angle);
  };
  std::vector<Mesh::Halfedge_index> loop;
  for(Mesh::Halfedge_index h : halfedges(m))
    if(in_cap(face(h, m)) && !in_cap(face(opposite(h, m), m))) loop.push_back(h);   // the cap is on the left
  std::vector<Mesh::Halfedge_index> broken;
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(int(i % (loop.size() / gaps)) != 0) broken.push_back(loop[i]);
  return broken;
}

int main(int argc, char** argv)
{
  Mesh mesh;
  CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(4));

  auto chain_a = mesh.add_property_map<Mesh::Edge_index, int>("e:a", 0).first;
  auto chain_b = mesh.add_property_map<Mesh::Edge_index, int>("e:b", 0).first;
  SWN::add_halfedges_to_chain(mesh, broken_cap_boundary(mesh, K::Vector_3(0.3, 0, 1), 0.8, 5), chain_a);
  SWN::add_halfedges_to_chain(mesh, broken_cap_boundary(mesh, K::Vector_3(-0.3, 0.2, 1), 0.7, 4), chain_b);

  SWN::Surface_winding_numbers_solver<Mesh> solver(mesh);
  if(!solver.is_valid()) { std::cerr << "invalid mesh: " << solver.report().error << "\n"; return 1; }
  auto label_a = mesh.add_property_map<Mesh::Face_index, int>("f:a", 0).first;
  auto label_b = mesh.add_property_map<Mesh::Face_index, int>("f:b", 0).first;
  if(!solver.solve(chain_a, label_a) || !solver.solve(chain_b, label_b))
  {
    std::cerr << "error: " << solver.report().error << "\n";
    return 1;
  }

  // On a sphere each loop bounds its cap; the normalization makes the larger side 0, so the cap is
  // the face set where the label is not 0.
  std::size_t a = 0, b = 0, both = 0, either = 0, a_minus_b = 0;
  std::vector<Mesh::Face_index> intersection;
  for(Mesh::Face_index f : faces(mesh))
  {
    const bool in_a = label_a[f] != 0, in_b = label_b[f] != 0;
    a += in_a; b += in_b; either += in_a || in_b; a_minus_b += in_a && !in_b;
    if(in_a && in_b) { ++both; intersection.push_back(f); }
  }
  std::cout << num_faces(mesh) << " faces; region A: " << a << ", region B: " << b << "\n"
            << "A union B: " << either << ", A intersection B: " << both << ", A minus B: " << a_minus_b << "\n";

  // The intersection as a mesh of its own.
  CGAL::Face_filtered_graph<Mesh> selection(mesh, intersection);
  Mesh piece;
  CGAL::copy_face_graph(selection, piece);
  std::cout << "extracted intersection: " << num_vertices(piece) << " vertices, " << num_faces(piece) << " faces\n";
  if(argc > 1)
  {
    if(!CGAL::IO::write_polygon_mesh(argv[1], piece, CGAL::parameters::stream_precision(17))) return 1;
    std::cout << "wrote " << argv[1] << "\n";
  }
  return (a > 0 && b > 0 && both > 0 && either == a + b - both) ? 0 : 1;
}
