// The readers of curves off the mesh: 3D polylines in OBJ files, 2D drawings in SVG files (straight
// segments only), with file and line on bad input.
#include "swn_io/read_polylines.h"

#include "test_io_support.h"

#include <sstream>

using namespace swn_test;

namespace {

typedef std::vector<std::array<double, 2> > Polyline_2;

TEST(ObjPolylines, PointsAndPolylinesOneBasedNegativeAndClosed)
{
  TempDir dir;
  write_file(dir / "p.obj", "# strokes\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nl 1 2 3 1\nv 0 1 2.5\nl -1 -2\n");
  const auto r = IO::read_obj_polylines(dir / "p.obj");
  const auto& p = r.polylines;
  EXPECT_EQ(r.lines, (std::vector<std::size_t>{6, 8}));
  ASSERT_EQ(p.size(), 2u);
  ASSERT_EQ(p[0].size(), 4u);
  EXPECT_EQ(p[0][2], (std::array<double, 3>{1, 1, 0}));
  EXPECT_EQ(p[0].front(), p[0].back());
  ASSERT_EQ(p[1].size(), 2u);
  EXPECT_EQ(p[1][0], (std::array<double, 3>{0, 1, 2.5}));
  EXPECT_EQ(p[1][1], (std::array<double, 3>{1, 1, 0}));
}

TEST(ObjPolylines, BadInputNamesFileAndLine)
{
  TempDir dir;
  auto error_of = [&](const std::string& content) {
    write_file(dir / "bad.obj", content);
    try { IO::read_obj_polylines(dir / "bad.obj"); }
    catch(const IO::Input_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  EXPECT_NE(error_of("v 0 0 0\nv nan 0 0\nl 1 2\n").find("bad.obj:2: vertex coordinate is not finite"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nl 1 2\n").find("bad.obj:2: index '2' does not name a point"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nl 1 x\n").find("bad.obj:2: cannot parse index 'x'"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\n").find("bad.obj: no polyline"), std::string::npos);
  EXPECT_NE(error_of("v 0 0\n").find("bad.obj:1:"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\n#offset 9223372036854775807\nl 2 1\n").find("bad.obj:3: index '2' does not name a point"),
            std::string::npos) << "the offset overflows: out of range, not undefined behaviour";
  std::istringstream in("v 0 0 0\nv 1 0 0\nl 1 2\n");
  EXPECT_EQ(IO::read_obj_polylines(in, "stream.obj").lines, (std::vector<std::size_t>{3}));
}

TEST(Svg, PathCommandsAbsoluteAndRelative)
{
  TempDir dir;
  write_file(dir / "d.svg",
             "<?xml version=\"1.0\"?>\n<!-- a comment <path d=\"M 9 9\"/> -->\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n"
             "  <title>test</title>\n"
             "  <path d=\"M1,2 L3,2 h2 v-1 H1 Z m1 1 l1-1.5 V7z\" fill=\"none\"/>\n"
             "  <polyline points=\"0,0 1,1 2-0\"/>\n  <polygon points='0 0 4 0 4 4'/>\n"
             "  <g><line x1=\"1\" y1=\"1\" x2=\"2\" y2=\"3\"/></g>\n</svg>\n");
  const auto d = IO::read_svg_polylines(dir / "d.svg");
  EXPECT_TRUE(d.warnings.empty());
  ASSERT_EQ(d.polylines.size(), 5u);
  EXPECT_EQ(d.polylines[0], (Polyline_2{{1, 2}, {3, 2}, {5, 2}, {5, 1}, {1, 1}, {1, 2}}));
  // after Z the current point is the subpath's start (1,2): m1 1 -> (2,3), l1-1.5 -> (3,1.5), then
  // V7 -> (3,7) ('.5' alone is not a pair: see the path below), z back to (2,3)
  EXPECT_EQ(d.polylines[1].front(), (std::array<double, 2>{2, 3}));
  EXPECT_EQ(d.polylines[1][1], (std::array<double, 2>{3, 1.5}));
  EXPECT_EQ(d.polylines[1].back(), d.polylines[1].front()) << "z closes the subpath";
  EXPECT_EQ(d.polylines[2], (Polyline_2{{0, 0}, {1, 1}, {2, 0}}));
  EXPECT_EQ(d.polylines[3], (Polyline_2{{0, 0}, {4, 0}, {4, 4}, {0, 0}})) << "a polygon is closed";
  EXPECT_EQ(d.polylines[4], (Polyline_2{{1, 1}, {2, 3}}));
  EXPECT_EQ(d.lines, (std::vector<std::size_t>{5, 5, 6, 7, 8})) << "each polyline's element line";
}

TEST(Svg, UnsupportedElementsWarnCurvesAndTransformsAreErrors)
{
  TempDir dir;
  write_file(dir / "w.svg", "<svg>\n<circle cx=\"1\" cy=\"1\" r=\"2\"/>\n<path d=\"M0 0 L1 0 L1 1\"/>\n</svg>\n");
  const auto d = IO::read_svg_polylines(dir / "w.svg");
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find("w.svg:2: <circle> is not supported and is ignored"), std::string::npos) << d.warnings[0];
  EXPECT_EQ(d.polylines.size(), 1u);
  // markup inside a quoted attribute value is text, not an element
  write_file(dir / "q.svg", "<svg>\n<path d=\"M 10 10 L 90 10 L 90 90 Z\" data-note=\"a>b <path d='M 0 0 L 100 100'/>\"/>\n</svg>\n");
  EXPECT_EQ(IO::read_svg_polylines(dir / "q.svg").polylines.size(), 1u);

  auto error_of = [&](const std::string& content) {
    write_file(dir / "bad.svg", content);
    try { IO::read_svg_polylines(dir / "bad.svg"); }
    catch(const IO::Input_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  EXPECT_NE(error_of("<svg>\n\n<path d=\"M0 0 C 1 1 2 2 3 3\"/></svg>").find("bad.svg:3: path command 'C' is not supported"),
            std::string::npos);
  EXPECT_NE(error_of("<svg>\n<path transform=\"scale(2)\" d=\"M0 0 L1 1\"/></svg>").find("bad.svg:2: <path>: transform"),
            std::string::npos);
  EXPECT_NE(error_of("<svg><polyline points=\"0 0 1\"/></svg>").find("bad.svg:1: odd number of coordinates"), std::string::npos);
  EXPECT_NE(error_of("<svg><path d=\"M0 0 L1 x\"/></svg>").find("bad.svg:1: a number was expected"), std::string::npos);
  EXPECT_NE(error_of("<svg><circle r=\"1\"/></svg>").find("bad.svg: no polyline"), std::string::npos);
  EXPECT_NE(error_of("<svg><path d=\"M0 0 L1 1\"").find("bad.svg:1: unterminated"), std::string::npos);
  EXPECT_NE(error_of("<svg>\n<path d=\"m 1e308 0 1e308 0 l 1 1\"/></svg>").find("bad.svg:2: the path's coordinates add up to a number that is not finite"),
            std::string::npos) << "relative moves that overflow";
  EXPECT_NE(error_of("<svg>\n<line x1=\"-1e308\" x2=\"1e308\"/></svg>").find("bad.svg:2: the drawing's extent or centre is not a finite number"),
            std::string::npos);
  EXPECT_NE(error_of("<svg>\n\n<path d=\"M 1e308 0 l 0e308 0\"/></svg>").find("bad.svg:3: the drawing's extent or centre is not"),
            std::string::npos) << "found by swn_fuzz_svg: a point drawing at 1e308 (its centre overflows when the stamp places it)";
}

} // namespace
