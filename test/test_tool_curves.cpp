// End-to-end tests of the tool's curves off the mesh: --polylines (3D OBJ polylines) and --stamp (an SVG
// drawing stamped along --direction) on a sphere, against the analytic areas; bad files.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/generators.h>

#include "test_tool_support.h"

#include <cmath>
#include <regex>



namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
const double kPi = std::acos(-1.);

// a unit sphere (icosahedron subdivided 4 times, 5120 faces) written to `path`; returns its area
double write_sphere(const fs::path& path)
{
  CGAL::Surface_mesh<K::Point_3> m;
  CGAL::make_icosahedron(m, K::Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(4));
  double area = 0;
  for(auto v : vertices(m)) m.point(v) = CGAL::ORIGIN + (m.point(v) - CGAL::ORIGIN) / std::sqrt((m.point(v) - CGAL::ORIGIN).squared_length());
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    area += std::sqrt(CGAL::squared_area(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m))));
  }
  EXPECT_TRUE(CGAL::IO::write_OFF(path.string(), m, CGAL::parameters::stream_precision(17)));
  return area;
}

// label -> area, from summary.json
std::map<int, double> label_areas(const std::string& summary)
{
  std::map<int, double> r;
  const std::regex entry("\"label\":\\s*(-?[0-9.]+),\\s*\"faces\":\\s*[0-9]+,\\s*\"area\":\\s*([-0-9.eE+]+)");
  for(std::sregex_iterator it(summary.begin(), summary.end(), entry), end; it != end; ++it)
    r[int(std::lround(std::stod((*it)[1])))] = std::stod((*it)[2]);
  return r;
}

std::map<int, double> run_and_read_areas(const std::string& args, const fs::path& out)
{
  const Tool_run r = run(args + " --quiet --output-dir '" + out.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  return label_areas(slurp((out / "summary.json").string()));
}

TEST(ToolCurves, PolylinesAboveASphereLabelTheCap)
{
  const fs::path dir = fresh_dir("polylines");
  fs::create_directories(dir);
  const double area = write_sphere(dir / "sphere.off");
  // a circle of polar angle 0.7 at radius 1.02, counter-clockwise seen from +z, closed
  std::ofstream obj(dir / "circle.obj");
  const double angle = 0.7;
  for(int i = 0; i < 120; ++i)
    obj << "v " << 1.02 * std::sin(angle) * std::cos(2 * kPi * i / 120) << " " << 1.02 * std::sin(angle) * std::sin(2 * kPi * i / 120)
        << " " << 1.02 * std::cos(angle) << "\n";
  obj << "l";
  for(int i = 1; i <= 120; ++i) obj << " " << i;
  obj << " 1\n";
  obj.close();
  const auto areas = run_and_read_areas("'" + (dir / "sphere.off").string() + "' --polylines '" + (dir / "circle.obj").string() + "'", dir / "out");
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_NEAR(areas.at(1) / area, (1 - std::cos(angle)) / 2, 0.01);
  fs::remove_all(dir);
}

TEST(ToolCurves, StampedDiamondLabelsItsShadowOnTheSphere)
{
  const fs::path dir = fresh_dir("stamp");
  fs::create_directories(dir);
  const double area = write_sphere(dir / "sphere.off");
  std::ofstream svg(dir / "diamond.svg");
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path d=\"M 10 0 L 20 10 L 10 20 L 0 10 Z\"/>\n</svg>\n";
  svg.close();
  // fitted to 80 % of the sphere's extent: the diamond |x| + |y| < 0.8, seen from +z
  const auto areas = run_and_read_areas("'" + (dir / "sphere.off").string() + "' --stamp '" + (dir / "diamond.svg").string() +
                                        "' --direction 0,0,-1", dir / "out");
  ASSERT_EQ(areas.size(), 2u);
  double expected = 0;   // the area of the sphere above the diamond, by the midpoint rule
  const int n = 800;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const double x = -0.8 + 1.6 * (i + 0.5) / n, y = -0.8 + 1.6 * (j + 0.5) / n;
      if(std::abs(x) + std::abs(y) < 0.8) expected += (1.6 / n) * (1.6 / n) / std::sqrt(1 - x * x - y * y);
    }
  const double labelled = std::min(areas.begin()->second, std::prev(areas.end())->second);
  EXPECT_NEAR(labelled / area, expected / (4 * kPi), 0.01);
  fs::remove_all(dir);
}

TEST(ToolCurves, NoNonboundingFilterContoursU)
{
  // torus with the letter Phi: filtered, the broken meridian is G (tested with the demo data); unfiltered,
  // u's contours split the torus along the completed meridian and the opposite contour: one more label
  std::string summary;
  const std::map<int, int> filtered = solve_demo("'" + demo + "torus.obj' --curve '" + demo + "torus-phi.txt'", "phi", &summary);
  EXPECT_EQ(summary.find("\"nonbounding_edges\": 0,"), std::string::npos);
  const std::map<int, int> unfiltered =
    solve_demo("'" + demo + "torus.obj' --curve '" + demo + "torus-phi.txt' --no-nonbounding-filter", "phi_u", &summary);
  EXPECT_EQ(unfiltered.size(), filtered.size() + 1);
  EXPECT_NE(summary.find("\"nonbounding_edges\": 0,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"lp_ran\": false"), std::string::npos) << summary;
}

TEST(ToolCurves, BadFilesGiveFileLineOrAWarning)
{
  const fs::path dir = fresh_dir("bad_curves");
  fs::create_directories(dir);
  write_sphere(dir / "sphere.off");
  const std::string mesh = "'" + (dir / "sphere.off").string() + "'";
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return "'" + (dir / name).string() + "'";
  };
  Tool_run r = run(mesh + " --polylines " + write("nan.obj", "v 0 0 1\nv nan 0 1\nl 1 2\n"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("nan.obj:2: vertex coordinate is not finite"), std::string::npos) << r.err;
  r = run(mesh + " --polylines " + write("far.obj", "v 0 0 3\nv 0 1 3\nv 1 1 3\nl 1 2 3\n"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("far.obj: no curve on the surface"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: " + (dir / "far.obj").string() + ": polyline 0: no point within"), std::string::npos) << r.err;
  r = run(mesh + " --stamp " + write("curve.svg", "<svg>\n<path d=\"M0 0 Q 1 1 2 0\"/>\n</svg>\n"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("curve.svg:2: path command 'Q' is not supported"), std::string::npos) << r.err;
  r = run(mesh + " --quiet --stamp " + write("circle.svg", "<svg>\n<circle r=\"3\"/>\n<polygon points=\"0 0 1 0 1 1\"/>\n</svg>\n"));
  EXPECT_EQ(r.status, 0) << r.err;
  r = run(mesh + " --stamp " + write("circle2.svg", "<svg>\n<circle r=\"3\"/>\n<polygon points=\"0 0 1 0 1 1\"/>\n</svg>\n"));
  EXPECT_NE(r.err.find("warning: " + (dir / "circle2.svg").string() + ":2: <circle> is not supported"), std::string::npos) << r.err;
  r = run(mesh + " --stamp " + (dir / "circle.svg").string() + " --direction 0,0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--direction needs three numbers"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

} // namespace
