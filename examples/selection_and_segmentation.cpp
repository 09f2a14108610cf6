// Cleaning a noisy face selection; cleaning a noisy edge selection, then splitting the mesh into one
// sub-mesh per region.
//
// First, a cap of a sphere selected with a brush, with 11 % of all faces picked or missed at random:
// clean_face_selection() takes the boundary of the selection as a chain without the sides of the faces
// whose state most of their surroundings do not share, and the surface winding numbers close the gaps
// this leaves and drop the rest: the faces labelled against the cap go from about 140 to about 10.
//
// Then a user selected, with a screen-space tool, the borders of two disks on a sphere: the edges come without
// orientation, with gaps, and with a few spurious edges on the far side. orient_edge_selection() orients
// them; the surface winding numbers complete the loops and drop the spurious pieces (the bounding chain is
// the cleaned selection). Both disks get the label 1: one label can cover several regions, so the
// segmentation goes by connected region (PMP::connected_components with the label jumps as constrained
// edges), each region extracted with Face_filtered_graph and written out.
//
// Usage: selection_and_segmentation [output_prefix]   (writes output_prefix_noisy.ply and
//        output_prefix_cleaned.ply, the face selection before and after, output_prefix_region_K.off and
//        output_prefix_labels.ply, the regions as face colours)

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
#include <CGAL/Surface_winding_numbers/clean_selection.h>
#include <CGAL/Surface_winding_numbers/orient_edge_selection.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef Mesh::Property_map<Mesh::Face_index, bool> Face_selection;

// writes the mesh with the selected faces in orange, the others in grey
bool write_selection(const std::string& file, Mesh mesh, const Face_selection& selected)
{
  auto colour = mesh.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(auto f : faces(mesh)) colour[f] = selected[f] ? CGAL::IO::Color(230, 120, 40) : CGAL::IO::Color(215, 215, 205);
  std::ofstream out(file, std::ios::binary);
  CGAL::IO::set_binary_mode(out);
  return CGAL::IO::write_PLY(out, mesh);
}

// A cap of 294 faces on a sphere of 1,280, each face flipped with probability 0.11: returns the number of
// faces labelled against the cap after cleaning (and prints it with the number before)
std::size_t clean_noisy_face_selection(const char* prefix)
{
  Mesh mesh;
  CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(3));
  for(auto v : vertices(mesh))   // onto the unit sphere
    mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) / std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length());
  const K::Vector_3 axis(0.2, 0.1, 1);
  auto in_cap = [&](Mesh::Face_index f) {
    const auto h = halfedge(f, mesh);
    const K::Vector_3 c = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                         mesh.point(target(next(h, mesh), mesh))) - CGAL::ORIGIN;
    return c * axis / std::sqrt(c.squared_length() * axis.squared_length()) > std::cos(1.0);
  };
  Face_selection selection = mesh.add_property_map<Mesh::Face_index, bool>("f:selection", false).first;
  Face_selection cleaned = mesh.add_property_map<Mesh::Face_index, bool>("f:cleaned", false).first;
  std::mt19937 noise(2);
  for(auto f : faces(mesh)) selection[f] = in_cap(f) != (noise() % 1000 < 110);

  SWN::Solve_report report;
  if(!SWN::clean_face_selection(mesh, selection, cleaned, SWN::parameters::report(std::ref(report))))
  {
    std::cerr << "error: " << report.error << "\n";
    return num_faces(mesh);
  }
  std::size_t cap = 0, before = 0, after = 0;
  for(auto f : faces(mesh))
  {
    cap += in_cap(f);
    before += selection[f] != in_cap(f);
    after += cleaned[f] != in_cap(f);
  }
  std::cout << "face selection: a cap of " << cap << " of " << num_faces(mesh) << " faces, " << before
            << " faces flipped at random; after clean_face_selection(): " << after << " faces differ from the cap\n";
  if(prefix != nullptr && !(write_selection(std::string(prefix) + "_noisy.ply", mesh, selection) &&
                            write_selection(std::string(prefix) + "_cleaned.ply", mesh, cleaned)))
    return num_faces(mesh);
  return after;
}

int main(int argc, char** argv)
{
  const std::size_t face_selection_wrong = clean_noisy_face_selection(argc > 1 ? argv[1] : nullptr);

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
  return face_selection_wrong <= 20 && wrong <= 4 && regions == 3 && dropped >= spurious && dropped <= spurious + 4 ? 0 : 1;
}
