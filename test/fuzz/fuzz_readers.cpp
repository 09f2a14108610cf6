// The input the fuzzers feed to the swn tool's readers and the library (see fuzz_readers.h), compiled
// once for all the fuzzers.

#include "fuzz_readers.h"

#include "swn_io/conforming_cut.h"
#include "swn_io/curves_off_mesh.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include "swn_io/soup_curves.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_winding_numbers/polygon_soup_winding_numbers.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <functional>
#include <sstream>

namespace swn_fuzz {

namespace SIO = CGAL::Surface_winding_numbers::IO;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

// the unit square in z = 0, n x n squares split along their (i, j)-(i+1, j+1) diagonals, normals +z
Mesh unit_grid(std::size_t n)
{
  Mesh m;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i) m.add_vertex(Point(double(i) / double(n), double(j) / double(n), 0));
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      auto v = [&](std::size_t x, std::size_t y) { return Mesh::Vertex_index(Mesh::size_type(y * (n + 1) + x)); };
      m.add_face(v(i, j), v(i + 1, j), v(i + 1, j + 1));
      m.add_face(v(i, j), v(i + 1, j + 1), v(i, j + 1));
    }
  return m;
}

} // namespace

struct Fixed_meshes
{
  Mesh grid;
  Mesh unit_grid = swn_fuzz::unit_grid(10);   // the reproducers' grid10.obj
};

namespace {

// curves off the mesh onto `mesh`: polylines, a drawing, both, as the tool puts them
void put_off_mesh(const Mesh& mesh, const SIO::Off_mesh_curves& curves)
{
  SIO::Cut_result<Point> cut = SIO::conforming_cut(mesh, std::vector<SIO::Curve_set>());
  SIO::add_off_mesh_curves(cut, curves, "fuzz mesh", [](const std::string&) {});
}

// the soup route of the tool: an OBJ file read as a soup when it is not an oriented 2-manifold triangle
// mesh (or has dual chains), its `l`/`c` records checked against the soup, then solved
void soup_route(std::istream& is)
{
  Mesh mesh;
  SIO::Triangle_soup soup;
  SIO::Mesh_read_info info;
  const std::string file = "fuzz.soup.obj";
  std::string problem = SIO::read_mesh_or_soup(is, "obj", file, mesh, soup, info);
  if(problem.empty() && info.obj_dual_chains.empty()) return;   // a mesh: the other formats' route
  const SIO::Curve_set cs = SIO::curve_set_from_obj(info, soup);
  if(cs.segments.empty() && cs.dual_pairs.empty()) throw SIO::Input_error(file, 0, "no curve");
  const SIO::Soup_curve curve = SIO::soup_curve(std::vector<SIO::Curve_set>{cs}, soup);
  std::vector<Point> points;
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  std::vector<int> labels(SIO::number_of_faces(soup), 0);
  CGAL::Surface_winding_numbers::Solve_report report;
  auto solve = [&](const auto& polygons) {
    namespace P = CGAL::Surface_winding_numbers::parameters;
    return CGAL::polygon_soup_winding_numbers(points, polygons, curve.edges, CGAL::make_property_map(labels),
                                              P::dual_chain(curve.dual_pairs, P::concurrency(false, P::report(std::ref(report)))));
  };
  const bool ok = soup.polygons.empty() ? solve(soup.triangles) : solve(soup.polygons);
  if(!ok) throw SIO::Input_error(file, 0, report.error);   // refused, with a reason: not a defect
}

} // namespace

Outcome read_input(const std::string& data, const std::string& format, const Fixed_meshes& meshes)
{
  try
  {
    std::istringstream is(data, std::ios::in | std::ios::binary);
    std::vector<SIO::Curve_set> curves;
    if(format == "curve")
    {
      curves.push_back(SIO::read_curves(is, "fuzz.txt", meshes.grid));
      SIO::conforming_cut(meshes.grid, curves);
      return Outcome::READ;
    }
    if(format == "polylines" || format == "svg")
    {
      SIO::Off_mesh_curves c;
      if(format == "polylines") c.polylines = SIO::read_obj_polylines(is, c.polylines_file = "fuzz.polylines.obj");
      else c.drawing = SIO::read_svg_polylines(is, c.stamp_file = "fuzz.svg");
      put_off_mesh(meshes.unit_grid, c);
      return Outcome::READ;
    }
    if(format == "soup")
    {
      soup_route(is);
      return Outcome::READ;
    }
    Mesh mesh;
    const SIO::Mesh_read_info info = SIO::read_mesh(is, format == "offmesh" ? "obj" : format, "fuzz." + format, mesh);
    if(format == "offmesh")
    {
      // a closed stroke through three of the mesh's vertices, and a drawing of two shapes stamped along -z
      SIO::Off_mesh_curves c;
      c.polylines_file = "stroke.obj";
      const std::size_t n = mesh.number_of_vertices();
      std::vector<std::array<double, 3> > stroke;
      for(std::size_t k : {std::size_t(0), n / 3, 2 * n / 3, std::size_t(0)})
      {
        const Point& p = mesh.point(Mesh::Vertex_index(Mesh::size_type(k)));
        stroke.push_back({p.x(), p.y(), p.z()});
      }
      c.polylines.polylines.push_back(stroke);
      c.polylines.lines.push_back(1);
      c.stamp_file = "shapes.svg";
      c.drawing.polylines = {{{10, 10}, {50, 50}, {90, 10}}, {{20, 60}, {40, 60}, {30, 80}, {20, 60}}};
      c.drawing.lines = {1, 2};
      put_off_mesh(mesh, c);
      return Outcome::READ;
    }
    if(SIO::has_curve_records(info))
    {
      curves.push_back(SIO::curve_set_from_obj(info, mesh));
      SIO::conforming_cut(mesh, curves);
    }
    return Outcome::READ;
  }
  catch(const SIO::Input_error&)
  {
    return Outcome::INPUT_ERROR;
  }
}

std::shared_ptr<const Fixed_meshes> fixed_meshes(const std::string& grid_path)
{
  auto m = std::make_shared<Fixed_meshes>();
  SIO::read_mesh(grid_path, m->grid);
  return m;
}

} // namespace swn_fuzz
