// Curves that are not on the mesh: a 3D stroke sketched above a sphere, and a 2D drawing stamped onto it.
//
// The stroke is a wobbly circle drawn slightly above the surface, with a stretch lifted far off it (a
// gap); polylines_to_chain() projects it onto the surface, walks between its points through the faces and
// cuts the mesh so that it runs along edges. The drawing, a five-pointed star, is stamped onto the sphere
// along a direction by stamp_polylines(). One solver then labels both: the cap inside the stroke (its area
// is known) and the star's shadow.
//
// Usage: curves_off_the_mesh [labels.ply]   (the sphere with the labels of the stroke as face colours)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/IO/Color.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/polylines_to_chain.h>
#include <CGAL/Surface_winding_numbers/stamp_polylines.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;

int main(int argc, char** argv)
{
  const double pi = std::acos(-1.);
  Mesh mesh;
  CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(4));
  for(auto v : vertices(mesh))
    mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) / std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length());

  // 1. A stroke around the north pole, at polar angle 0.6 (wobbling by 0.02), 1 % above the surface, with
  //    points 20..29 lifted far off it: they are dropped and leave a gap.
  std::vector<std::vector<K::Point_3> > stroke(1);
  const double angle = 0.6;
  for(int i = 0; i <= 100; ++i)
  {
    const double phi = 2 * pi * (i % 100) / 100, theta = angle + 0.02 * std::sin(7 * phi);
    const double r = (i % 100 >= 20 && i % 100 < 30) ? 1.5 : 1.01;
    stroke[0].emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
  }
  auto stroke_chain = mesh.add_property_map<Mesh::Edge_index, int>("e:stroke", 0).first;
  const auto put = SWN::polylines_to_chain(mesh, stroke, stroke_chain);
  if(!put) { std::cerr << "error: " << put.error << "\n"; return 1; }
  std::cout << "stroke: " << put.points << " points, " << put.points_off_surface << " off the surface, "
            << put.curves << " curve(s) on the mesh; the cut added " << put.cut.cut_vertices << " vertices\n";

  // 2. A star stamped along -z (seen from above, its points up), on the same mesh: it is cut again.
  std::vector<std::vector<std::array<double, 2> > > star(1);
  for(int k = 0; k <= 10; ++k)
  {
    const double a = pi / 2 + 2 * pi * (k % 10) / 10, r = (k % 2 == 0) ? 1.0 : 0.4;
    star[0].push_back({r * std::cos(a), -r * std::sin(a)});   // SVG-like: y downwards
  }
  const K::Vector_3 down(0, 0, -1);
  const auto stamped = SWN::stamp_polylines(mesh, star, SWN::fit_stamp_frame(mesh, star, down, 0.7));
  auto star_chain = mesh.add_property_map<Mesh::Edge_index, int>("e:star", 0).first;
  const auto star_put = SWN::polylines_to_chain(mesh, stamped, star_chain);
  if(!star_put) { std::cerr << "error: " << star_put.error << "\n"; return 1; }
  // the stroke's chain lives on edges that the star's cut may have split: both halves keep its value

  // 3. One solver for both curves.
  SWN::Surface_winding_numbers_solver<Mesh> solver(mesh);
  auto stroke_labels = mesh.add_property_map<Mesh::Face_index, int>("f:stroke", 0).first;
  auto star_labels = mesh.add_property_map<Mesh::Face_index, int>("f:star", 0).first;
  if(!solver.is_valid() || !solver.solve(stroke_chain, stroke_labels) || !solver.solve(star_chain, star_labels))
  {
    std::cerr << "error: " << solver.report().error << "\n";
    return 1;
  }
  double total = 0, cap = 0, shadow = 0;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const double a = std::sqrt(CGAL::squared_area(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                                  mesh.point(target(next(h, mesh), mesh))));
    total += a;
    cap += stroke_labels[f] != 0 ? a : 0;
    shadow += star_labels[f] != 0 ? a : 0;
  }
  const double expected = (1 - std::cos(angle)) / 2;
  std::cout << "cap inside the stroke: " << cap / total << " of the sphere (a circle at polar angle " << angle
            << ": " << expected << ")\nstar: " << shadow / total << " of the sphere\n";

  if(argc > 1)
  {
    auto colour = mesh.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
    for(auto f : faces(mesh))
      colour[f] = stroke_labels[f] != 0 ? CGAL::IO::Color(230, 120, 40)
                : star_labels[f] != 0  ? CGAL::IO::Color(60, 110, 190) : CGAL::IO::Color(215, 215, 205);
    std::ofstream out(argv[1], std::ios::binary);
    CGAL::IO::set_binary_mode(out);
    if(!CGAL::IO::write_PLY(out, mesh)) return 1;
    std::cout << "wrote " << argv[1] << "\n";
  }
  return std::abs(cap / total - expected) < 0.01 && shadow > 0 && shadow < cap ? 0 : 1;
}
