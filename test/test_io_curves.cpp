// Curves off the mesh made dependable (issue 42): the input face of every piece of the cut, and the
// reproducers of test/data/fuzz_curves (README there) through the library.

#include "swn_io/read_polylines.h"

#include "test_io_support.h"

#include <CGAL/Surface_winding_numbers/conforming_cut.h>
#include <CGAL/Surface_winding_numbers/orient_edge_selection.h>
#include <CGAL/Surface_winding_numbers/polylines_to_chain.h>
#include <CGAL/Surface_winding_numbers/stamp_polylines.h>
#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>
#include <CGAL/surface_winding_numbers.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

using namespace swn_test;

namespace {

namespace SWN = CGAL::Surface_winding_numbers;
namespace PMP = CGAL::Polygon_mesh_processing;

// every face maps to a face of the input, faces not cut to themselves, and the pieces of every input face
// tile it: their areas add up to its area
void expect_origins_tile_input(const Mesh& input, const Mesh& cut, const Mesh::Property_map<FI, FI>& origin)
{
  std::map<FI, double> area;
  std::size_t pieces = 0;
  for(FI f : cut.faces())
  {
    const FI g = origin[f];
    ASSERT_TRUE(std::size_t(g) < input.number_of_faces()) << "face " << f;
    if(std::size_t(f) < input.number_of_faces() && g != f)
      EXPECT_EQ(g, f) << "a face of the input keeps its descriptor and is a piece of itself";
    area[g] += PMP::face_area(f, cut);
    pieces += (g != f);
  }
  EXPECT_GT(pieces, 0u);
  for(FI g : input.faces())
    EXPECT_NEAR(area[g], PMP::face_area(g, input), 1e-12 * (1 + PMP::face_area(g, input))) << "input face " << g;
}

TEST(FaceOrigin, ConformingCutAndPolylinesToChainTileEveryInputFace)
{
  Mesh input;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", input));
  // an open stroke (its ends inside: cut and refinement) and a closed one, through polylines_to_chain()
  {
    Mesh m = input;
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const std::vector<std::vector<Point> > strokes{{Point(0.3, 0.4, 0), Point(2.6, 1.7, 0)},
                                                   {Point(0.5, 2.2, 0), Point(1.5, 2.3, 0), Point(1.2, 2.8, 0), Point(0.5, 2.2, 0)}};
    const auto r = SWN::polylines_to_chain(m, strokes, chain, SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(r)) << r.error;
    EXPECT_GT(r.cut.cut_faces, 0u);
    EXPECT_GT(r.cut.refinement_faces, 0u);
    expect_origins_tile_input(input, m, origin);
  }
  // conforming_cut() directly: a segment between two edge midpoints of one face
  {
    Mesh m = input;
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const FI f = *m.faces().begin();
    const auto h = m.halfedge(f);
    const std::vector<std::vector<PMP::Face_location<Mesh, double> > > curves{
      {PMP::locate_on_halfedge(h, 0.5, m), PMP::locate_on_halfedge(m.next(h), 0.5, m)}};
    const auto r = SWN::conforming_cut(m, curves, chain, SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(r)) << r.message;
    expect_origins_tile_input(input, m, origin);
  }
}

const std::string repro = tdata + "fuzz_curves/";
typedef std::vector<std::vector<Point> > Polylines;
typedef std::vector<std::vector<std::array<double, 2> > > Drawing;

Mesh read(const std::string& file, double scale = 1)
{
  Mesh m;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(file, m)) << file;
  for(VI v : m.vertices()) m.point(v) = Point(scale * m.point(v).x(), scale * m.point(v).y(), scale * m.point(v).z());
  return m;
}

Polylines read_polylines(const std::string& file, double scale = 1)
{
  Polylines r;
  for(const auto& l : IO::read_obj_polylines(file).polylines)
  {
    r.emplace_back();
    for(const auto& p : l) r.back().emplace_back(scale * p[0], scale * p[1], scale * p[2]);
  }
  return r;
}

// what a curve on a mesh gives: the labels of the faces, their areas, the chain's edges and endpoints
struct Outcome
{
  std::vector<int> labels;
  std::vector<double> areas;
  int chain_edges = 0;
  int endpoints = 0;         // vertices of the chain with a nonzero boundary, not on the border
  double zero_area_faces = 0;
  // the area where the label is `depth` more than on the first face (the labels are defined up to a constant)
  double area_of(int depth) const
  {
    double a = 0;
    for(std::size_t f = 0; f < labels.size(); ++f) a += labels[f] - labels[0] == depth ? areas[f] : 0.;
    return a;
  }
};

// (the areas of the mesh's copy divided by `scale`)
Outcome solve(Mesh& m, const Mesh::Property_map<Mesh::Edge_index, int>& chain, double scale = 1)
{
  Outcome o;
  std::map<VI, int> boundary;
  for(auto e : m.edges())
  {
    if(chain[e] == 0) continue;
    ++o.chain_edges;
    boundary[m.target(m.halfedge(e))] += chain[e];
    boundary[m.source(m.halfedge(e))] -= chain[e];
  }
  for(const auto& b : boundary) o.endpoints += (b.second != 0 && !m.is_border(b.first));
  for(FI f : m.faces())
  {
    std::array<double, 9> xyz;
    int k = 0;
    for(VI v : m.vertices_around_face(m.halfedge(f)))
      for(int c = 0; c < 3; ++c) xyz[k++] = m.point(v)[c];
    o.areas.push_back(std::sqrt(CGAL::squared_area(Point(xyz[0] / scale, xyz[1] / scale, xyz[2] / scale),
                                                   Point(xyz[3] / scale, xyz[4] / scale, xyz[5] / scale),
                                                   Point(xyz[6] / scale, xyz[7] / scale, xyz[8] / scale))));
    const double unit = SWN::internal::unit_scale(xyz.data(), 3);
    for(double& x : xyz) x *= unit;
    o.zero_area_faces += SWN::internal::zero_area_triangle(&xyz[0], &xyz[3], &xyz[6]);
  }
  if(o.chain_edges == 0) return o;
  auto labels = m.add_property_map<FI, int>("f:labels", 0).first;
  SWN::Solve_report report;
  EXPECT_TRUE(CGAL::surface_winding_numbers(m, chain, labels, SWN::parameters::report(std::ref(report)))) << report.error;
  for(FI f : m.faces()) o.labels.push_back(labels[f]);
  m.remove_property_map(labels);
  return o;
}

Outcome polylines_outcome(Mesh& m, const Polylines& polylines, double scale = 1)
{
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  const auto r = SWN::polylines_to_chain(m, polylines, chain);
  EXPECT_TRUE(bool(r)) << r.error;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m));
  const Outcome o = solve(m, chain, scale);
  m.remove_property_map(chain);
  return o;
}

// the same regions: the area of every label (those of the scaled copy divided by the scale), and the same
// chain (the triangulation of cut faces may differ where two ears are equally good up to rounding)
void expect_same_up_to_scale(const Outcome& unit, const Outcome& scaled)
{
  EXPECT_EQ(unit.areas.size(), scaled.areas.size());
  std::map<int, double> a, b;
  for(std::size_t f = 0; f < unit.labels.size(); ++f) a[unit.labels[f]] += unit.areas[f];
  for(std::size_t f = 0; f < scaled.labels.size(); ++f) b[scaled.labels[f]] += scaled.areas[f];
  ASSERT_EQ(a.size(), b.size());
  for(const auto& [label, area] : a) EXPECT_NEAR(b[label], area, 1e-9) << "label " << label;
  EXPECT_EQ(unit.chain_edges, scaled.chain_edges);
  EXPECT_EQ(unit.endpoints, scaled.endpoints);
}

TEST(CurvesOffMesh, StrokeThereAndBackNeitherCrashesNorMakesADegenerateFace)
{
  for(const std::string file : {"asan_crash_segv_polylines_there_and_back.polylines.obj", "msg_polylines_there_and_back_cut_zero_area.polylines.obj",
                                 "asan_crash_segv_stamp_there_and_back.svg"})
  {
    Mesh m = read(repro + "grid10.offmesh.obj");
    Polylines strokes;
    if(file.back() == 'g')
    {
      const Drawing d = IO::read_svg_polylines(repro + file).polylines;
      strokes = SWN::stamp_polylines(m, d, SWN::fit_stamp_frame(m, d, K::Vector_3(0, 0, -1)));
      EXPECT_FALSE(strokes.empty());
    }
    else
      strokes = read_polylines(repro + file);
    const Outcome o = polylines_outcome(m, strokes);
    EXPECT_EQ(o.zero_area_faces, 0) << file;
    EXPECT_EQ(o.chain_edges, 0) << file << ": a stroke that doubles back on itself cancels";
  }
}

TEST(CurvesOffMesh, StampRefusesNonFiniteInputAndHugeDirectionsAreDirections)
{
  const Mesh m = read(repro + "grid10.offmesh.obj");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Drawing square{{{10, 10}, {90, 10}, {90, 90}, {10, 90}, {10, 10}}};
  const K::Vector_3 down(0, 0, -1);
  const auto frame = SWN::fit_stamp_frame(m, square, down);
  EXPECT_THROW(SWN::stamp_polylines(m, Drawing{{{5, 5}, {nan, 3}}}, frame), SWN::Invalid_input);
  EXPECT_THROW(SWN::fit_stamp_frame(m, Drawing{{{5, 5}, {nan, 3}}}, down), SWN::Invalid_input);
  EXPECT_THROW(SWN::fit_stamp_frame(m, square, K::Vector_3(0, 0, 0)), SWN::Invalid_input);
  EXPECT_THROW(SWN::fit_stamp_frame(m, square, K::Vector_3(nan, 0, -1)), SWN::Invalid_input);
  for(const K::Vector_3& d : {K::Vector_3(0, 0, 0), K::Vector_3(nan, 0, -1)})
  {
    SWN::Stamp_frame<K> bad = frame;
    bad.direction = d;
    EXPECT_THROW(SWN::stamp_polylines(m, square, bad), SWN::Invalid_input);
  }
  SWN::Stamp_frame<K> nan_axis = frame;
  nan_axis.x_axis = K::Vector_3(nan, 0, 0);
  EXPECT_THROW(SWN::stamp_polylines(m, square, nan_axis), SWN::Invalid_input);
  // relative coordinates that add up to infinity (the SVG reader refuses them; the library too)
  const Drawing overflow{{{0, 0}, {1e308, 0}, {std::numeric_limits<double>::infinity(), 0}}};
  EXPECT_THROW(SWN::fit_stamp_frame(m, overflow, down), SWN::Invalid_input);
  EXPECT_THROW(SWN::stamp_polylines(m, overflow, frame), SWN::Invalid_input);
  // a drawing far larger than its frame's mesh: refused, not divided without bound
  SWN::Stamp_frame<K> huge = frame;
  huge.x_axis = K::Vector_3(1e300, 0, 0);
  EXPECT_THROW(SWN::stamp_polylines(m, square, huge), SWN::Invalid_input);
  // --direction 0,0,-1e300 is the direction 0,0,-1
  const Drawing d = IO::read_svg_polylines(repro + "ubsan_hang_mem_direction_1e300.svg").polylines;
  const auto a = SWN::stamp_polylines(m, d, SWN::fit_stamp_frame(m, d, K::Vector_3(0, 0, -1e300)));
  const auto b = SWN::stamp_polylines(m, d, SWN::fit_stamp_frame(m, d, down));
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, b);
}

TEST(CurvesOffMesh, OrientEdgeSelectionRefusesEdgesNotOfTheMesh)
{
  Mesh m = read(repro + "grid10.offmesh.obj");
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  for(const Mesh::Edge_index bad : {Mesh::Edge_index(100000), Mesh::Edge_index()})
  {
    const std::vector<Mesh::Edge_index> selection{Mesh::Edge_index(3), bad};
    EXPECT_THROW(SWN::orient_edge_selection(m, selection, chain), SWN::Invalid_input);
    for(auto e : m.edges()) EXPECT_EQ(chain[e], 0);
  }
  EXPECT_EQ(SWN::orient_edge_selection(m, std::vector<Mesh::Edge_index>{Mesh::Edge_index(3)}, chain), 1u);
}

TEST(CurvesOffMesh, PolylinesOnScaledCopiesGiveTheUnitAnswer)
{
  // the reproducer: a mesh at 1e-140 (a closest-point query died of SIGFPE)
  {
    Mesh tiny = read(repro + "crash_sigfpe_polylines_tiny_scale.off");
    Mesh unit = read(repro + "crash_sigfpe_polylines_tiny_scale.off", 1e140);
    const Outcome a = polylines_outcome(tiny, read_polylines(repro + "crash_sigfpe_polylines_tiny_scale.polylines.obj"), 1e-140);
    const Outcome b = polylines_outcome(unit, read_polylines(repro + "crash_sigfpe_polylines_tiny_scale.polylines.obj", 1e140));
    expect_same_up_to_scale(b, a);
  }
  // a closed stroke and an open one on grid10 at 1e-140, 1e20 and 1e160
  const Polylines strokes{{Point(0.23, 0.31, 0), Point(0.71, 0.27, 0), Point(0.64, 0.77, 0), Point(0.23, 0.31, 0)},
                          {Point(0.12, 0.88, 0), Point(0.47, 0.93, 0)}};
  Mesh unit = read(repro + "grid10.offmesh.obj");
  const Outcome a = polylines_outcome(unit, strokes);
  EXPECT_GT(a.area_of(1), 0.05);
  for(double scale : {1e-140, 1e20, 1e160})
  {
    Polylines scaled = strokes;
    for(auto& l : scaled)
      for(Point& p : l) p = Point(scale * p.x(), scale * p.y(), scale * p.z());
    Mesh m = read(repro + "grid10.offmesh.obj", scale);
    expect_same_up_to_scale(a, polylines_outcome(m, scaled, scale));
  }
}

TEST(CurvesOffMesh, StampsOnScaledCopiesGiveTheUnitAnswer)
{
  const Drawing shapes = IO::read_svg_polylines(repro + "shapes.svg").polylines;
  const K::Vector_3 down(0, 0, -1);
  const Mesh unit = read(repro + "grid10.offmesh.obj");
  const auto a = SWN::stamp_polylines(unit, shapes, SWN::fit_stamp_frame(unit, shapes, down));
  ASSERT_FALSE(a.empty());
  Mesh cut_unit = unit;
  const Outcome oa = polylines_outcome(cut_unit, a);
  for(double scale : {1e-140, 1e20, 1e160})
  {
    const Mesh m = read(repro + "grid10.offmesh.obj", scale);
    const auto b = SWN::stamp_polylines(m, shapes, SWN::fit_stamp_frame(m, shapes, down));
    ASSERT_EQ(a.size(), b.size()) << "scale " << scale;
    for(std::size_t i = 0; i < a.size(); ++i)
    {
      ASSERT_EQ(a[i].size(), b[i].size());
      for(std::size_t j = 0; j < a[i].size(); ++j)
        EXPECT_LE(std::sqrt(CGAL::squared_distance(a[i][j], Point(b[i][j].x() / scale, b[i][j].y() / scale, b[i][j].z() / scale))),
                  1e-12) << "scale " << scale;
    }
    Mesh cut = m;
    expect_same_up_to_scale(oa, polylines_outcome(cut, b, scale));
  }
}

TEST(CurvesOffMesh, ClosedDrawingsAlongEdgesAndThroughVerticesStayClosed)
{
  // a square along grid edges, through its corners only, and with points on the midpoints of its sides
  for(const std::string file : {"silent_polylines_along_edges_corners_only_ok.polylines.obj", "silent_polylines_along_edges_with_midpoints.polylines.obj"})
  {
    Mesh m = read(tdata + "grid4.off");
    const Outcome o = polylines_outcome(m, read_polylines(repro + file));
    EXPECT_EQ(o.chain_edges, 4) << file;
    EXPECT_EQ(o.endpoints, 0) << file;
    EXPECT_NEAR(o.area_of(1) + o.area_of(-1), 1., 1e-12) << file;
  }
  // a stamped square whose sides land on grid lines of grid10 (0.1 to 0.9)
  {
    Mesh m = read(repro + "grid10.offmesh.obj");
    const Drawing square = IO::read_svg_polylines(repro + "silent_stamp_square_on_grid_lines.svg").polylines;
    const auto stamped = SWN::stamp_polylines(m, square, SWN::fit_stamp_frame(m, square, K::Vector_3(0, 0, -1)));
    const Outcome o = polylines_outcome(m, stamped);
    EXPECT_EQ(o.endpoints, 0);
    EXPECT_EQ(o.chain_edges, 32);
    EXPECT_NEAR(o.area_of(1) + o.area_of(-1), 0.64, 1e-12);
  }
  // the same square drawn as a polyline through every vertex it passes, and slightly rotated copies of
  // the mesh: closed, with the same area whatever the alignment
  for(double angle : {0., 1e-13, 0.3})
  {
    Mesh m = read(repro + "grid10.offmesh.obj");
    const double c = std::cos(angle), sn = std::sin(angle);
    auto turn = [&](double x, double y) { return Point(c * x - sn * y, sn * x + c * y, 0); };
    for(VI v : m.vertices()) m.point(v) = turn(m.point(v).x(), m.point(v).y());
    std::vector<Point> loop;
    for(int k = 0; k < 32; ++k)
    {
      const int side = k / 8, i = k % 8;
      const double t = 0.1 + 0.1 * i;
      loop.push_back(side == 0 ? turn(t, 0.1) : side == 1 ? turn(0.9, t) : side == 2 ? turn(1 - t, 0.9) : turn(0.1, 1 - t));
    }
    loop.push_back(loop.front());
    const Outcome o = polylines_outcome(m, Polylines{loop});
    EXPECT_EQ(o.endpoints, 0) << "angle " << angle;
    EXPECT_EQ(o.chain_edges, 32) << "angle " << angle;
    EXPECT_NEAR(o.area_of(1), 0.64, 1e-9) << "angle " << angle;
  }
}

TEST(CurvesOffMesh, PiecesAlongTheBorderAreDroppedAndCounted)
{
  // grid4 (the square [0,3]^2): a closed stroke whose one piece along the border runs through its first
  // point; a stroke along the border with a bump inside, then cutting a corner off; a loop all along the
  // border
  auto P = [](double x, double y) { return Point(x, y, 0); };
  const Polylines strokes{{P(1, 0), P(2, 0), P(2, 1), P(0, 1), P(0, 0), P(1, 0)},
                          {P(0, 0), P(1, 0), P(1, 1), P(2, 1), P(2, 0), P(3, 0), P(3, 2), P(2, 2), P(2, 3)},
                          {P(0, 0), P(3, 0), P(3, 3), P(0, 3), P(0, 0)}};
  // what is left: the strokes without their pieces along the border
  const Polylines rest{{P(2, 0), P(2, 1), P(0, 1)}, {P(1, 0), P(1, 1), P(2, 1), P(2, 0)}, {P(3, 2), P(2, 2), P(2, 3)}};
  Mesh m = read(tdata + "grid4.off"), n = m;
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  auto expected = n.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  const auto r = SWN::polylines_to_chain(m, strokes, chain);
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.border_pieces, 4u);
  EXPECT_EQ(r.polyline_border_pieces, (std::vector<std::size_t>{1, 2, 1}));
  EXPECT_EQ(r.failed_walks, 0u);
  const auto s = SWN::polylines_to_chain(n, rest, expected);
  ASSERT_TRUE(s) << s.error;
  EXPECT_EQ(s.border_pieces, 0u);
  EXPECT_EQ(r.curves, s.curves);
  ASSERT_EQ(m.number_of_edges(), n.number_of_edges());
  for(auto e : m.edges()) EXPECT_EQ(chain[e], expected[e]) << "edge " << e;
  // only along the border: nothing on the mesh, no error
  Mesh b = read(tdata + "grid4.off");
  auto none = b.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  const auto t = SWN::polylines_to_chain(b, Polylines{strokes[2]}, none);
  ASSERT_TRUE(t) << t.error;
  EXPECT_EQ(t.border_pieces, 1u);
  EXPECT_EQ(t.curves, 0u);
  for(auto e : b.edges()) EXPECT_EQ(none[e], 0) << "edge " << e;
}

// the regular pentagram on grid10 (centre 0.5, 0.5, circumradius r), drawn counter-clockwise: winding
// number 2 in the inner pentagon, 1 in the five tips; its crossings are inside faces
Polylines pentagram(double r)
{
  const double pi = std::acos(-1.);
  std::vector<Point> star;
  for(int k = 0; k <= 5; ++k)
  {
    const double a = pi / 2 + 0.1 + 2 * pi / 5 * double((2 * k) % 5);
    star.emplace_back(0.5 + r * std::cos(a), 0.5 + r * std::sin(a), 0);
  }
  return {star};
}

TEST(CurvesOffMesh, SelfCrossingStrokesAreCutOnceWithAVertexAtEveryCrossing)
{
  const double pi = std::acos(-1.), r = 0.41;
  Mesh input = read(repro + "grid10.offmesh.obj");
  {
    Mesh m = input;
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const auto res = SWN::polylines_to_chain(m, pentagram(r), chain, SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(res)) << res.error;
    EXPECT_EQ(res.dropped_crossings, 0u);
    EXPECT_EQ(res.cut.crossing_vertices, 5u);
    expect_origins_tile_input(input, m, origin);
    const Outcome o = solve(m, chain);
    EXPECT_EQ(o.zero_area_faces, 0);
    EXPECT_EQ(o.endpoints, 0);
    // inner pentagon: circumradius r cos(72) / cos(36); a regular pentagon of circumradius R has area
    // 5/2 R^2 sin(72); the integral of the winding number is the shoelace area of the star
    const double inner_r = r * std::cos(2 * pi / 5) / std::cos(pi / 5);
    const double inner = 2.5 * inner_r * inner_r * std::sin(2 * pi / 5);
    double shoelace = 0;
    const Polylines stars = pentagram(r);
    const auto& star = stars[0];
    for(std::size_t k = 0; k + 1 < star.size(); ++k) shoelace += (star[k].x() * star[k + 1].y() - star[k + 1].x() * star[k].y()) / 2;
    // up to the crossings of edges moved to a vertex within 2 % of the edge's length (0.002)
    EXPECT_NEAR(o.area_of(2), inner, 1e-3);
    EXPECT_NEAR(o.area_of(1), shoelace - 2 * inner, 1e-3);
  }
  // three strokes through one point inside a face: one crossing vertex
  {
    Mesh m = input;
    const Point x(0.537, 0.462, 0);
    Polylines strokes;
    for(double a : {0.2, 1.3, 2.4})
      strokes.push_back({Point(x.x() - 0.3 * std::cos(a), x.y() - 0.3 * std::sin(a), 0),
                         Point(x.x() + 0.3 * std::cos(a), x.y() + 0.3 * std::sin(a), 0)});
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const auto res = SWN::polylines_to_chain(m, strokes, chain, SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(res)) << res.error;
    EXPECT_EQ(res.cut.crossing_vertices, 1u);
    expect_origins_tile_input(input, m, origin);
    EXPECT_EQ(solve(m, chain).zero_area_faces, 0);
  }
  // the reproducer: 560 random points crossing each other everywhere
  {
    Mesh m = input;
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const auto res = SWN::polylines_to_chain(m, read_polylines(repro + "hang_polylines_random_crossings_10KB.polylines.obj"), chain,
                                             SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(res)) << res.error;
    EXPECT_GT(res.cut.crossing_vertices, 100u);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m));
    expect_origins_tile_input(input, m, origin);
    EXPECT_EQ(solve(m, chain).zero_area_faces, 0);
  }
}

TEST(CurvesOffMesh, ThreeHundredChordsCrossingInOneFaceAreCutInOnce)
{
  // n chords of one face, every two crossing: the tangents from (a, 0) to (1, a) of a parabola, no three
  // through a point. The cut searched all pieces of the face for every piece of chord it split, quadratic
  // in the crossings (a 500-point star stroke: 31,116 crossings, 57 s; fuzz timeouts under ASan).
  // Euler's formula gives the answer: C(n, 2) crossing vertices, 2 C(n, 2) + 2n + 1 triangles in the face,
  // n + 1 in its neighbour across the side x = 1.
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const Mesh input = m;
  const VI v0(0), v1(1), v5(5);
  ASSERT_EQ(m.point(v5), Point(1, 1, 0));
  const std::size_t n = 300, crossings = n * (n - 1) / 2;
  std::vector<std::vector<PMP::Face_location<Mesh, double> > > chords;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double a = 0.1 + 0.8 * double(i) / double(n - 1);
    chords.push_back({PMP::locate_on_halfedge(m.halfedge(v0, v1), a, m), PMP::locate_on_halfedge(m.halfedge(v1, v5), a, m)});
  }
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
  const auto r = SWN::conforming_cut(m, chords, chain, SWN::parameters::refine_short_pieces(false,
                                     SWN::parameters::face_origin_map(origin)));
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.crossing_vertices, crossings);
  EXPECT_EQ(r.cut_vertices, 2 * n + crossings);
  EXPECT_EQ(r.cut_faces, 2 * crossings + 2 * n + n);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m));
  expect_origins_tile_input(input, m, origin);
  // every chord runs through its n - 1 crossings: n edges each, from its first point to its last
  std::size_t chain_edges = 0;
  std::map<VI, int> boundary;
  for(auto e : m.edges())
  {
    const int c = chain[e];
    chain_edges += (c != 0);
    boundary[m.target(m.halfedge(e))] += c;
    boundary[m.source(m.halfedge(e))] -= c;
  }
  EXPECT_EQ(chain_edges, n * n);
  for(std::size_t i = 0; i < n; ++i)
  {
    EXPECT_EQ(boundary[r.curve_vertices[i][0]], -1);
    EXPECT_EQ(boundary[r.curve_vertices[i][1]], 1);
  }
  for(FI f : m.faces()) EXPECT_GT(PMP::face_area(f, m), 0.) << "face " << f;
}

TEST(CurvesOffMesh, WalksFromAVertexAndClockwiseStampsWithCornersOnEdges)
{
  // issue 42, observations rechecked after the one cut (grid10: the unit square, 10 x 10 cells split along
  // (i, j)-(i+1, j+1), as the Python tests' grid_disk(10))
  // a walk that starts at a vertex: (0.3, 0.7) -> (0.2, 0.2), through no other vertex, and back
  for(const Polylines& stroke : {Polylines{{Point(0.3, 0.7, 0), Point(0.2, 0.2, 0)}}, Polylines{{Point(0.2, 0.2, 0), Point(0.3, 0.7, 0)}}})
  {
    Mesh m = read(repro + "grid10.offmesh.obj");
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    const auto r = SWN::polylines_to_chain(m, stroke, chain, SWN::parameters::refine_short_pieces(false));
    ASSERT_TRUE(bool(r)) << r.error;
    EXPECT_EQ(r.failed_walks, 0u);
    EXPECT_EQ(r.points_off_surface, 0u);
    ASSERT_EQ(r.pieces.size(), 1u);
    ASSERT_EQ(r.pieces[0].size(), 1u);
    EXPECT_EQ(r.pieces[0][0], (std::vector<std::size_t>{0, 1}));
    // the chain runs from the first point's vertex to the last one's: boundary -1 and +1 there only, and
    // its edges add up to the segment's length (every vertex of the cut is on the segment)
    const VI from(Mesh::size_type(stroke[0][0] == Point(0.3, 0.7, 0) ? 7 * 11 + 3 : 2 * 11 + 2));
    const VI to(Mesh::size_type(stroke[0][0] == Point(0.3, 0.7, 0) ? 2 * 11 + 2 : 7 * 11 + 3));
    ASSERT_EQ(m.point(from), stroke[0][0]);
    ASSERT_EQ(m.point(to), stroke[0][1]);
    std::map<VI, int> boundary;
    double length = 0;
    for(auto e : m.edges())
    {
      const int c = chain[e];
      if(c == 0) continue;
      boundary[m.target(m.halfedge(e))] += c;
      boundary[m.source(m.halfedge(e))] -= c;
      length += std::abs(c) * std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
    }
    for(const auto& b : boundary) EXPECT_EQ(b.second, b.first == from ? -1 : (b.first == to ? 1 : 0)) << "vertex " << b.first;
    EXPECT_NEAR(length, std::sqrt(0.26), 1e-12);
  }
  // a parallelogram stamped straight down, with its corners on the cells' diagonals (the point halfway
  // along each), clockwise and counter-clockwise: closed, no zero-area face, label -1 or +1 on its area 0.16
  const Drawing clockwise{{{0.25, 0.25}, {0.35, 0.65}, {0.75, 0.65}, {0.65, 0.25}, {0.25, 0.25}}};
  Drawing counter = clockwise;
  std::reverse(counter[0].begin(), counter[0].end());
  // corners on the horizontal grid lines, one side through the vertex (0.3, 0.4)
  const Drawing on_lines{{{0.25, 0.2}, {0.35, 0.6}, {0.75, 0.6}, {0.65, 0.2}, {0.25, 0.2}}};
  for(const auto& [drawing, depth] : {std::make_pair(clockwise, -1), std::make_pair(counter, 1), std::make_pair(on_lines, -1)})
  {
    Mesh m = read(repro + "grid10.offmesh.obj");
    const SWN::Stamp_frame<K> frame{Point(0, 0, 1), K::Vector_3(1, 0, 0), K::Vector_3(0, 1, 0), K::Vector_3(0, 0, -1)};
    const Outcome o = polylines_outcome(m, SWN::stamp_polylines(m, drawing, frame));
    EXPECT_EQ(o.zero_area_faces, 0) << "depth " << depth;
    EXPECT_EQ(o.endpoints, 0) << "depth " << depth;
    EXPECT_NEAR(o.area_of(depth), 0.16, 1e-12) << "depth " << depth;
    EXPECT_NEAR(o.area_of(-depth), 0., 1e-12) << "depth " << depth;
  }
}

} // namespace
