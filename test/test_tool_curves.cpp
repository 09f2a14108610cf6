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

// the vertices (16, lines 1-16) and faces (18, lines 17-34) of grid4.off as OBJ records: the square [0,3]^2,
// vertex i at (i % 4, i / 4, 0), two triangles per cell
void write_grid4_obj(std::ostream& obj)
{
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i) obj << "v " << i << " " << j << " 0\n";
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i)
    {
      const int a = 4 * j + i + 1;
      obj << "f " << a << " " << a + 1 << " " << a + 5 << "\nf " << a << " " << a + 5 << " " << a + 4 << "\n";
    }
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
  EXPECT_NE(r.err.find("far.obj: no curve on the surface (every point is farther"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: " + (dir / "far.obj").string() + ":4: polyline 0: no point within"), std::string::npos) << r.err;
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

// grid4.off: the square [0,3]^2 in z = 0, 3 x 3 unit squares split along (i,j)-(i+1,j+1), normals +z
const std::string grid = "'" + std::string(SWN_TEST_DATA_DIR) + "/grid4.off'";

// a run of the tool on grid4 with curves off the mesh, and its summary.json
struct Grid_run
{
  fs::path dir;       // the test's directory (remove it at the end)
  std::string file;   // the curves' file in it
  Tool_run r;
  std::string summary;
  std::size_t at = std::string::npos;   // where "curves_off_mesh" is in the summary
  bool ok() const { return r.status == 0 && at != std::string::npos; }
};

// writes `text` to the file `name` (.obj: --polylines, .svg: --stamp) in a fresh directory `dir_name`, runs
// the tool on grid4 with it and an output directory, reads summary.json and finds "curves_off_mesh"
Grid_run run_on_grid(const std::string& dir_name, const std::string& name, const std::string& text)
{
  Grid_run g;
  g.dir = fresh_dir(dir_name);
  fs::create_directories(g.dir);
  g.file = (g.dir / name).string();
  std::ofstream(g.file) << text;
  const std::string option = name.size() > 4 && name.compare(name.size() - 4, 4, ".svg") == 0 ? " --stamp '" : " --polylines '";
  g.r = run(grid + option + g.file + "' --output-dir '" + (g.dir / "out").string() + "'");
  EXPECT_EQ(g.r.status, 0) << g.r.err;
  if(g.r.status != 0) return g;
  g.summary = slurp((g.dir / "out" / "summary.json").string());
  g.at = g.summary.find("\"curves_off_mesh\"");
  EXPECT_NE(g.at, std::string::npos) << g.summary;
  return g;
}

TEST(ToolCurves, PolylinesReportTheLibrarysCountsOnConsoleAndInSummary)
{
  // y = 0.25 from x = 0.5 to 2.5 crosses x = 1, the diagonal at 1.25, x = 2 and the diagonal at 2.25: four
  // vertices cut in, none near an edge's end; the third point, 5 above the grid, is off the surface
  const Grid_run g = run_on_grid("report_polylines", "stroke.obj", "# a stroke\nv 0.5 0.25 0\nv 2.5 0.25 0\nv 2.5 0.25 5\n\nl 1 2 3\n");
  ASSERT_TRUE(g.ok());
  const Tool_run& r = g.r;
  const std::string& file = g.file;
  const std::string& summary = g.summary;
  const std::size_t at = g.at;
  EXPECT_NE(r.out.find("polylines " + file + ": 1 polylines, 3 points (1 off the surface), 0 failed walks, 0 pieces along "
                       "the border dropped, 0 crossings: 1 curves; cut: 4 vertices added"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: " + file + ":6: polyline 0: 1 of its 3 points are farther than the mean edge length"),
            std::string::npos) << "a stroke that loses points warns, with its `l` line: " << r.err;
  EXPECT_EQ(json_number(summary, "points", at), 3);
  EXPECT_EQ(json_number(summary, "points_off_surface", at), 1);
  EXPECT_EQ(json_number(summary, "failed_walks", at), 0);
  EXPECT_EQ(json_number(summary, "crossing_vertices", at), 0);
  EXPECT_EQ(json_number(summary, "curves", at), 1);
  EXPECT_EQ(json_number(summary, "cut_vertices", at), 4);
  // the solved mesh is the grid with the vertices of the cut and of the refinement, counted in solved_mesh
  const double cut = json_number(summary, "cut_new_vertices"), refined = json_number(summary, "refine_new_vertices");
  EXPECT_EQ(cut, 4) << summary;
  EXPECT_EQ(refined, json_number(summary, "refinement_vertices", at));
  EXPECT_EQ(json_number(summary, "vertices", summary.find("\"solved_mesh\"")), 16 + cut + refined) << summary;
  EXPECT_EQ(json_number(summary, "interior_endpoints"), 2);

  // --verbose: the polyline's details on stderr
  const Tool_run v = run(grid + " --polylines '" + file + "' --verbose");
  EXPECT_NE(v.err.find("[swn] " + file + ":6: polyline 0: 1 of its 3 points"), std::string::npos) << v.err;
  fs::remove_all(g.dir);
}

TEST(ToolCurves, StrokesCrossingInsideAFaceAreCutInOnceAndReported)
{
  // y = 0.45 from x = 0.2 to 2.8 and x = 1.25 from y = 0.1 to 2.9 cross at (1.25, 0.45), strictly inside the
  // face of the square [1,2] x [0,1] above its diagonal, which both curves cross from edge to edge (curve
  // points are where the walks cross edges): one vertex where they cross, none refused
  const Grid_run g = run_on_grid("report_crossing", "cross.obj", "v 0.2 0.45 0\nv 2.8 0.45 0\nv 1.25 0.1 0\nv 1.25 2.9 0\nl 1 2\nl 3 4\n");
  ASSERT_TRUE(g.ok());
  EXPECT_NE(g.r.out.find("0 failed walks, 0 pieces along the border dropped, 1 crossings: 2 curves"), std::string::npos) << g.r.out;
  EXPECT_EQ(json_number(g.summary, "crossing_vertices", g.at), 1);
  EXPECT_EQ(json_number(g.summary, "interior_endpoints"), 4);
  fs::remove_all(g.dir);
}

TEST(ToolCurves, StampReportsItsPolylinesAndSaysWhenTheDirectionSeesTheBack)
{
  const Grid_run g = run_on_grid("report_stamp", "square.svg", "<svg>\n<polygon points=\"0 0 10 0 10 10 0 10\"/>\n</svg>\n");
  ASSERT_TRUE(g.ok());
  const std::string svg = "'" + g.file + "'";
  const std::string& summary = g.summary;
  const std::size_t at = g.at;
  EXPECT_NE(summary.find("\"kind\": \"stamp\"", at), std::string::npos) << summary;
  EXPECT_EQ(json_number(summary, "polylines", at), 1);
  EXPECT_EQ(json_number(summary, "stamped_polylines", at), 1);
  EXPECT_EQ(json_number(summary, "points_off_surface", at), 0);
  EXPECT_EQ(json_number(summary, "curves", at), 1);
  EXPECT_EQ(json_number(summary, "cut_new_vertices"), json_number(summary, "cut_vertices", at));
  EXPECT_GT(json_number(summary, "cut_vertices", at), 0) << "the square's sides cross the grid's edges";
  EXPECT_NE(g.r.out.find("stamp " + g.file + ": 1 polylines stamped as 1,"), std::string::npos) << g.r.out;

  // the grid's faces look up (+z): stamped along +z every ray meets their back
  Tool_run r = run(grid + " --stamp " + svg + " --direction 0,0,1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("square.svg: nothing stamped: along --direction 0,0,1 every ray misses the mesh or meets the back "
                       "of its faces"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the opposite direction meets their front"), std::string::npos) << r.err;
  r = run(grid + " --stamp " + svg + " --direction 1,0,0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("square.svg: the stamped drawing misses the mesh (along --direction 1,0,0 and the opposite"),
            std::string::npos) << r.err;
  fs::remove_all(g.dir);
}

TEST(ToolCurves, MessagesNameTheRecordThatFails)
{
  const fs::path dir = fresh_dir("messages");
  fs::create_directories(dir);
  // a stroke there and back: every point is on the surface, the curve cancels out
  std::ofstream(dir / "back.obj") << "v 0.5 1.5 0\nv 2.5 1.5 0\nl 1 2 1\n";
  Tool_run r = run(grid + " --polylines '" + (dir / "back.obj").string() + "'");
  EXPECT_TRUE(r.status == 0 || r.status == 2) << r.err;
  if(r.status == 2)
  {
    EXPECT_NE(r.err.find("back.obj:3: no curve left on the surface: what was put on it cancels out"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("too far"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("farther"), std::string::npos) << r.err;
  }
  // a closed stroke inside one face of the grid: it crosses no edge, and the error says so (not "cancels out")
  std::ofstream(dir / "one_face.obj") << "v 0.2 0.1 0\nv 0.6 0.2 0\nv 0.7 0.5 0\nl 1 2 3 1\n";
  r = run(grid + " --polylines '" + (dir / "one_face.obj").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("one_face.obj:4: no curve left on the surface: the polylines cross no edge of the mesh (each stays "
                       "inside one face)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("cancels out"), std::string::npos) << r.err;
  // an OBJ mesh whose `l` record leaves the faces (points above the grid, on no face): a hint at --polylines
  std::ofstream obj(dir / "mesh_and_stroke.obj");
  write_grid4_obj(obj);
  obj << "v 0.2 0.2 0.1\nv 2.7 0.3 0.1\nv 1.5 2.8 0.1\nl 17 18 19 17\n";
  obj.close();
  r = run("'" + (dir / "mesh_and_stroke.obj").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("mesh_and_stroke.obj:38: the segment from vertex 16 to vertex 17"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give it with --polylines FILE"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(ToolCurves, StrokesAlongTheBorderAreDroppedAndSaidSo)
{
  // along the border from (0,0) to (2,0), then inside to (2,2) and (0,2): the piece along the border is
  // counted, and the labels are those of the stroke without it
  const Grid_run g = run_on_grid("border_part", "part.obj", "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nl 1 2 3 4\n");
  ASSERT_TRUE(g.ok());
  EXPECT_NE(g.r.out.find("0 failed walks, 1 pieces along the border dropped, 0 crossings: 1 curves"), std::string::npos) << g.r.out;
  EXPECT_NE(g.r.err.find("warning: " + g.file + ": 1 piece of curve along the border of the mesh dropped"), std::string::npos) << g.r.err;
  EXPECT_EQ(json_number(g.summary, "border_pieces", g.at), 1);
  const Tool_run v = run(grid + " --polylines '" + g.file + "' --verbose");
  EXPECT_NE(v.err.find("[swn] " + g.file + ":5: polyline 0: on the surface in 1 piece; 1 piece along the border of the mesh dropped"),
            std::string::npos) << v.err;
  const Grid_run rest = run_on_grid("border_rest", "rest.obj", "v 2 0 0\nv 2 2 0\nv 0 2 0\nl 1 2 3\n");
  ASSERT_TRUE(rest.ok());
  const std::vector<int> labels = read_labels(g.dir / "out" / "labels.txt");
  EXPECT_EQ(labels, read_labels(rest.dir / "out" / "labels.txt"));
  EXPECT_EQ(histogram(labels).size(), 2u) << "the square [0,2]^2 is labelled";
  // only along the border of grid4: no curve left, and the error says why, at the stroke's `l` line
  const std::string along = (g.dir / "along.obj").string();
  std::ofstream(along) << "v 0 0 0\nv 3 0 0\nv 3 3 0\nl 1 2 3\n";
  const Tool_run a = run(grid + " --polylines '" + along + "' --output-dir '" + (g.dir / "a").string() + "'");
  EXPECT_EQ(a.status, 2);
  EXPECT_NE(a.err.find("swn: error: " + along + ":4: no curve left on the surface: it runs along the border of the mesh "
                       "(1 piece dropped)"), std::string::npos) << a.err;
  EXPECT_EQ(a.err.find("cancels out"), std::string::npos) << a.err;
  EXPECT_FALSE(fs::exists(g.dir / "a"));
  fs::remove_all(g.dir);
  fs::remove_all(rest.dir);
}

// an n x n grid of the square [0, size]^2 in z = 0 (normals +z), as an OBJ file
void write_grid(const fs::path& path, int n, double size)
{
  std::ofstream obj(path);
  obj.precision(17);
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) obj << "v " << size * i / n << " " << size * j / n << " 0\n";
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i + 1;
      obj << "f " << a << " " << a + 1 << " " << a + n + 2 << "\nf " << a << " " << a + n + 2 << " " << a + n + 1 << "\n";
    }
}

TEST(ToolCurves, StampOnATinyMeshWorksOrBlamesTheMesh)
{
  // the drawing is fine: a stamp onto a mesh of size 1e-100 either gives the labels of the unit-size copy
  // or is refused with a message about the mesh, never about the SVG
  const fs::path dir = fresh_dir("tiny_stamp");
  fs::create_directories(dir);
  write_grid(dir / "unit.obj", 12, 1);
  write_grid(dir / "tiny.obj", 12, 1e-100);
  std::ofstream(dir / "shapes.svg") << "<svg>\n<polyline points=\"10,10 50,50 90,10\"/>\n"
                                       "<polygon points=\"20 60 40 60 30 80\"/>\n</svg>\n";
  const std::string svg = " --stamp '" + (dir / "shapes.svg").string() + "' --quiet --output-dir ";
  const Tool_run unit = run("'" + (dir / "unit.obj").string() + "'" + svg + "'" + (dir / "unit").string() + "'");
  ASSERT_EQ(unit.status, 0) << unit.err;
  const Tool_run tiny = run("'" + (dir / "tiny.obj").string() + "'" + svg + "'" + (dir / "tiny").string() + "'");
  if(tiny.status == 0)
    EXPECT_EQ(histogram(read_labels(dir / "tiny" / "labels.txt")), histogram(read_labels(dir / "unit" / "labels.txt")));
  else
  {
    EXPECT_EQ(tiny.status, 2);
    EXPECT_EQ(tiny.err.rfind("swn: error: " + (dir / "tiny.obj").string() + ": ", 0), 0u) << tiny.err;
    EXPECT_NE(tiny.err.find("scale the mesh"), std::string::npos) << tiny.err;
    EXPECT_FALSE(fs::exists(dir / "tiny")) << "a failed run writes nothing";
  }
  fs::remove_all(dir);
}

} // namespace

TEST(ToolCurves, CurveAlongTheBorderOfATriangleMeshIsBlamedAtItsLine)
{
  // issue 42, item 6, the triangle-mesh route (the soup route: ToolSoup): the solver refused the chain on a
  // border edge naming the mesh and a 0-based edge; the curve's file and line are blamed, as on the soup route
  const fs::path dir = fresh_dir("border_curves");
  fs::create_directories(dir);
  // along the bottom border 0 -> 1 -> 2 of the 4 x 4 grid (line 2), and only its second segment (line 3)
  std::ofstream(dir / "along.txt") << "# swn polylines\n0 1 2\n";
  std::ofstream(dir / "second.txt") << "# swn polylines\n5 6 10 9 5\n6 7 3\n";
  // the authors' format: from a quarter to three quarters of edge 0 (0 -> 1, on the border), two vertices
  // of the cut (line 4)
  std::ofstream(dir / "half.txt") << "#offset 0\ne 0 0.25\ne 0 0.75\nl 0 1\n";
  struct Case { std::string file, where, what; };
  const Case cases[] = {
    {"along.txt", "along.txt:2: ", "the curve runs along the edge from vertex 0 to vertex 1, on the border of the mesh"},
    {"second.txt", "second.txt:3: ", "the curve runs along the edge from vertex 3 to vertex 7, on the border of the mesh"},
    {"half.txt", "half.txt:4: ", "the curve runs along the edge from vertex 0 to vertex 1, on the border of the mesh"}};
  for(const Case& c : cases)
  {
    const fs::path out = dir / "out";
    const Tool_run r = run(grid + " --curve '" + (dir / c.file).string() + "' --output-dir '" + out.string() + "'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("swn: error: " + (dir / c.where).string() + c.what), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // there and back along the border cancels: no error, the loop inside gives its area
  std::ofstream(dir / "cancel.txt") << "# swn polylines\n0 1 2 1 0\n5 6 10 9 5\n";
  const std::map<int, double> areas = run_and_read_areas(grid + " --curve '" + (dir / "cancel.txt").string() + "'", dir / "cancel");
  EXPECT_NEAR(areas.at(1), 1., 1e-12);
  // the `l` records of an OBJ mesh along its border: the mesh file and the record's line
  std::ofstream obj(dir / "mesh_with_border_curve.obj");
  write_grid4_obj(obj);
  obj << "l 6 7 11 10 6\nl 16 12\n";   // a loop inside (line 35), then along the right border (line 36)
  obj.close();
  const Tool_run r = run("'" + (dir / "mesh_with_border_curve.obj").string() + "' --output-dir '" + (dir / "obj").string() + "'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("mesh_with_border_curve.obj:36: the curve runs along the edge from vertex 11 to vertex 15"), std::string::npos) << r.err;
  fs::remove_all(dir);
}
