// Cleaning a noisy edge selection, then splitting the mesh into one sub-mesh per region.
//
// A user selected, with a screen-space tool, the borders of two disks on a sphere: the edges come without
// orientation, with gaps, and with a few spurious edges on the far side. orient_edge_selection() orients
// them; the surface winding numbers complete the loops and drop the spurious pieces (the bounding chain is
// the cleaned selection). Both disks get the label 1: one label can cover several regions, so the
// segmentation goes by connected region (PMP::connected_components with the label jumps as constrained
// edges), each region extracted with Face_filtered_graph and written out.
//
// Usage: selection_and_segmentation [output_prefix]   (writes output_prefix_region_K.off and
//                                                      output_prefix_labels.ply, the regions as face colours)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/orient_edge_selection.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  Mesh mesh;
  CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(4));

  // the two disks the user meant: faces within 0.5 rad of two directions
  const std::vector<K::Vector_3> centres = {K::Vector_3(1, 0.2, 0.5), K::Vector_3(-1, 0.3, 0.6)};
  auto disk = [&](Mesh::Face_index f) {
    const auto h = halfedge(f, mesh);
    const K::Vector_3 c = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                         mesh.point(target(next(h, mesh), mesh))) - CGAL::ORIGIN;
    for(std::size_t k = 0; k < centres.size(); ++k)
      if(c * centres[k] / std::sqrt(c.squared_length() * centres[k].squared_length()) > std::cos(0.5)) return int(k) + 1;
    return 0;
  };
  // the selection: their borders with every 7th edge missed, and five edges picked through the model, on
  // the far side (none touching another)
  std::vector<Mesh::Edge_index> selection;
  std::vector<Mesh::Vertex_index> used;
  std::size_t n = 0, spurious = 0;
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    const auto u = source(h, mesh), v = target(h, mesh);
    if(disk(face(h, mesh)) != disk(face(opposite(h, mesh), mesh)))
    {
      if(++n % 7 != 0) selection.push_back(e);
    }
    else if(mesh.point(u).z() < -0.8 * std::sqrt((mesh.point(u) - CGAL::ORIGIN).squared_length()) && spurious < 5 && std::find(used.begin(), used.end(), u) == used.end() &&
            std::find(used.begin(), used.end(), v) == used.end())
    {
      for(auto w : vertices_around_target(h, mesh)) used.push_back(w);
      for(auto w : vertices_around_target(opposite(h, mesh), mesh)) used.push_back(w);
      selection.push_back(e);
      ++spurious;
    }
  }

  auto chain = mesh.add_property_map<Mesh::Edge_index, int>("e:selection", 0).first;
  const std::size_t pieces = SWN::orient_edge_selection(mesh, selection, chain);
  auto labels = mesh.add_property_map<Mesh::Face_index, int>("f:label", 0).first;
  auto cleaned = mesh.add_property_map<Mesh::Edge_index, int>("e:cleaned", 0).first;
  SWN::Solve_report report;
  if(!CGAL::surface_winding_numbers(mesh, chain, labels,
       SWN::parameters::bounding_chain_map(cleaned, SWN::parameters::report(std::ref(report)))))
  {
    std::cerr << "error: " << report.error << "\n";
    return 1;
  }
  std::size_t selected = 0, kept = 0, dropped = 0, wrong = 0;
  for(auto e : selection) (cleaned[e] != 0 ? kept : dropped) += 1;
  for(auto e : edges(mesh)) selected += cleaned[e] != 0;
  for(auto f : faces(mesh)) wrong += (labels[f] != 0) != (disk(f) != 0);
  std::cout << selection.size() << " edges selected in " << pieces << " pieces; cleaned selection: " << selected
            << " edges (" << kept << " of the selected ones kept, " << dropped << " dropped, " << spurious
            << " of them picked on the far side); faces labelled against the disks: " << wrong << " differ\n";

  // Segmentation: one part per connected region of equal labels.
  auto jump = mesh.add_property_map<Mesh::Edge_index, bool>("e:jump", false).first;
  for(auto e : edges(mesh))
    jump[e] = !is_border(e, mesh) && labels[face(halfedge(e, mesh), mesh)] != labels[face(opposite(halfedge(e, mesh), mesh), mesh)];
  auto region = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:region", 0).first;
  const std::size_t regions = PMP::connected_components(mesh, region, CGAL::parameters::edge_is_constrained_map(jump));
  std::cout << regions << " regions:";
  for(std::size_t r = 0; r < regions; ++r)
  {
    CGAL::Face_filtered_graph<Mesh> part(mesh, r, region);
    Mesh piece;
    CGAL::copy_face_graph(part, piece);
    std::cout << "  " << num_faces(piece) << " faces (label " << labels[*faces(part).begin()] << ")";
    if(argc > 1 && !CGAL::IO::write_OFF(std::string(argv[1]) + "_region_" + std::to_string(r) + ".off", piece,
                                        CGAL::parameters::stream_precision(17)))
      return 1;
  }
  std::cout << "\n";
  if(argc > 1)
  {
    auto colour = mesh.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
    const CGAL::IO::Color palette[] = {CGAL::IO::Color(215, 215, 205), CGAL::IO::Color(230, 120, 40),
                                       CGAL::IO::Color(60, 110, 190), CGAL::IO::Color(90, 170, 90)};
    for(auto f : faces(mesh)) colour[f] = palette[region[f] % 4];
    std::ofstream out(std::string(argv[1]) + "_labels.ply", std::ios::binary);
    CGAL::IO::set_binary_mode(out);
    if(!CGAL::IO::write_PLY(out, mesh)) return 1;
  }
  // the two disks (where the gaps are closed, a completion may differ from the disks' border by a face or
  // two), as two regions of label 1, and none of the spurious edges
  return wrong <= 4 && regions == 3 && dropped >= spurious && dropped <= spurious + 4 ? 0 : 1;
}
