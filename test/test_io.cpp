// Tests of the swn tool's readers (tools/swn/swn_io/): meshes in every format with their numbering kept,
// the authors' edge numbering, curve files, and a corpus of malformed inputs.

#include "swn_io/conforming_cut.h"
#include "swn_io/errors.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include "swn_io/write_outputs.h"

#include "test_io_support.h"

#include <CGAL/IO/OFF.h>  // independent readers: cross-checks of ours
#include <CGAL/IO/PLY.h>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

// ------------------------------------------------------------------------------------------------ errors

TEST(InputError, OneLineMessage)
{
  IO::Input_error e("dir/file.obj", 12, "bad\nthing");
  EXPECT_STREQ(e.what(), "dir/file.obj:12: bad thing");
  EXPECT_EQ(e.line, 12u);
  EXPECT_EQ(e.file, "dir/file.obj");
  IO::Input_error e0("f.txt", 0, "empty");
  EXPECT_STREQ(e0.what(), "f.txt: empty");
}

// ------------------------------------------------------------------------------------------------ mesh readers

TEST(ReadMesh, OrderPreservedOFF)
{
  TempDir d;
  write_file(d / "o.off", octa_off());
  Mesh m;
  auto info = IO::read_mesh(d / "o.off", m);
  EXPECT_EQ(info.format, "off");
  expect_octa_order(m);
}

TEST(ReadMesh, OrderPreservedOBJWithExtras)
{
  TempDir d;
  write_file(d / "o.obj", octa_obj());
  Mesh m;
  auto info = IO::read_mesh(d / "o.obj", m);
  EXPECT_EQ(info.format, "obj");
  expect_octa_order(m);
  EXPECT_TRUE(info.warnings.empty());
}

TEST(ReadMesh, OrderPreservedPLY)
{
  TempDir d;
  write_file(d / "a.ply", octa_ply_ascii());
  write_file(d / "b.ply", octa_ply_binary_be());
  Mesh a, b;
  IO::read_mesh(d / "a.ply", a);
  IO::read_mesh(d / "b.ply", b);
  expect_octa_order(a);
  expect_octa_order(b);
}

TEST(ReadMesh, STLMergesDuplicatesAndKeepsFaceOrder)
{
  TempDir d;
  write_file(d / "a.stl", octa_stl_ascii());
  write_file(d / "b.stl", octa_stl_binary());
  Mesh a, b;
  auto ia = IO::read_mesh(d / "a.stl", a);
  auto ib = IO::read_mesh(d / "b.stl", b);
  expect_stl_faces(a, false);
  expect_stl_faces(b, true);
  EXPECT_EQ(ia.merged_stl_vertices, 24u - 6u);
  EXPECT_EQ(ib.merged_stl_vertices, 24u - 6u);
  ASSERT_FALSE(ia.warnings.empty());
  EXPECT_NE(ia.warnings[0].find("merged"), std::string::npos);
}

TEST(ReadMesh, WrittenByOurWritersAndReadBackInEveryFormat)
{
  // write the octahedron with CGAL-independent code paths of ours (PLY writer, w.obj writer) and read back
  TempDir d;
  Mesh m;
  {
    std::istringstream is(octa_off());
    IO::read_mesh(is, "off", "octa", m);
  }
  {
    std::ofstream os(d / "w.ply", std::ios::binary);
    IO::write_labeled_ply(os, m, std::vector<int>(8, 1), std::vector<double>(8, 0.5), true);
  }
  {
    std::ofstream os(d / "w.obj");
    IO::write_w_obj(os, m, std::vector<double>(m.number_of_halfedges(), 0.25));
  }
  Mesh a, b;
  IO::read_mesh(d / "w.ply", a);
  IO::read_mesh(d / "w.obj", b);
  expect_octa_order(a);
  expect_octa_order(b);
}

TEST(ReadMesh, AgreesWithCGALSoupReaders)
{
  // CGAL's soup readers keep the file order too: ours must give the same points and faces on OFF and PLY
  Mesh bunny;
  IO::read_mesh(demo + "double-torus.obj", bunny);
  TempDir d;
  {
    std::ofstream off(d / "b.off");
    ASSERT_TRUE(CGAL::IO::write_OFF(off, bunny, CGAL::parameters::stream_precision(17)));
    std::ofstream ply(d / "b.ply", std::ios::binary);
    ASSERT_TRUE(CGAL::IO::write_PLY(ply, bunny, CGAL::parameters::stream_precision(17)));
  }
  for(const char* name : {"b.off", "b.ply"})
  {
    std::vector<Point> points;
    std::vector<std::vector<std::size_t> > polygons;
    const std::string path = d / name;
    ASSERT_TRUE(IO::mesh_file_format(name) == "off" ? CGAL::IO::read_OFF(path, points, polygons)
                                                     : CGAL::IO::read_PLY(path, points, polygons));
    Mesh m;
    IO::read_mesh(path, m);
    ASSERT_EQ(m.number_of_vertices(), points.size());
    ASSERT_EQ(m.number_of_faces(), polygons.size());
    for(VI v : m.vertices()) ASSERT_EQ(m.point(v), points[std::size_t(v)]);
    for(FI f : m.faces())
    {
      auto t = triple(m, f);
      ASSERT_EQ(std::vector<std::size_t>(t.begin(), t.end()), polygons[std::size_t(f)]);
    }
    // and the same as the original
    for(FI f : m.faces()) ASSERT_EQ(triple(m, f), triple(bunny, f));
  }
}

TEST(ReadMesh, UnreferencedAndDuplicatedVerticesAreReportedNotRenumbered)
{
  std::istringstream is("v 0 0 0\nv 1 0 0\nv 9 9 9\nv 0 1 0\nv 1 0 0\nf 1 2 4\nf 2 5 4\n");
  // vertex 2 unreferenced; vertex 4 duplicates vertex 1's position but is a distinct vertex
  Mesh m;
  auto info = IO::read_mesh(is, "obj", "mem.obj", m);
  EXPECT_EQ(m.number_of_vertices(), 5u);
  EXPECT_TRUE(m.is_valid(false));
  EXPECT_TRUE(m.is_isolated(VI(2)));
  EXPECT_EQ(info.unreferenced_vertices, 1u);
  EXPECT_EQ(info.duplicated_vertex_positions, 1u);
  EXPECT_EQ(info.degenerate_faces, 1u);  // face 1 has two corners at the same position
  EXPECT_EQ(info.warnings.size(), 3u);
  EXPECT_EQ(triple(m, FI(1)), (std::array<std::size_t, 3>{1, 4, 3}));
}

TEST(ReadMesh, ObjCurveRecordsAndOffset)
{
  std::istringstream is("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\nl 1 2 4\n#offset 0\nl 0 2\nc 0 1\nl -1 -2\n");
  Mesh m;
  auto info = IO::read_mesh(is, "obj", "mem.obj", m);
  ASSERT_EQ(info.obj_polylines.size(), 3u);
  EXPECT_EQ(info.obj_polylines[0].vertices, (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(info.obj_polylines[0].line, 7u);
  EXPECT_EQ(info.obj_polylines[1].vertices, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(info.obj_polylines[2].vertices, (std::vector<std::size_t>{3, 2}));
  ASSERT_EQ(info.obj_dual_chains.size(), 1u);
  EXPECT_EQ(info.obj_dual_chains[0].faces, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(info.obj_dual_chains[0].line, 10u);
  IO::Curve_set cs = IO::curve_set_from_obj(info, m);
  EXPECT_EQ(cs.segments.size(), 4u);
  EXPECT_EQ(cs.dual_pairs.size(), 1u);
  // the chain conversion refuses dual chains, naming the c line
  try
  {
    IO::conforming_cut(m, cs);
    FAIL() << "expected Input_error";
  }
  catch(const IO::Input_error& e)
  {
    EXPECT_EQ(e.line, 10u);
    EXPECT_NE(std::string(e.what()).find("dual chains (c lines) are not supported yet"), std::string::npos);
  }
}

TEST(ReadMesh, ShuffledBunnyKeepsOrder)
{
  Mesh bunny;
  IO::read_mesh(demo + "bunny.obj", bunny);
  ASSERT_EQ(bunny.number_of_vertices(), 14290u);
  ASSERT_EQ(bunny.number_of_faces(), 28576u);
  // shuffle faces and rotate each face, write as OBJ, read back, compare
  std::vector<std::array<std::size_t, 3> > faces;
  std::istringstream is(shuffled_obj(bunny, 7, faces));
  Mesh m;
  IO::read_mesh(is, "obj", "shuffled.obj", m);
  EXPECT_TRUE(m.is_valid(false));
  for(std::size_t j = 0; j < faces.size(); ++j)
    ASSERT_EQ(triple(m, FI(static_cast<Mesh::size_type>(j))), faces[j]);
  for(VI v : bunny.vertices()) ASSERT_EQ(m.point(v), bunny.point(v));
}

TEST(ReadMesh, DirectWiringEqualsFaceByFaceInsertion)
{
  // read_mesh() wires the halfedge structure directly from the validated soup; CGAL's face-by-face
  // insertion (Surface_mesh::add_face) on the same faces must give the same indices and connectivity:
  // every halfedge's target, next and face, every face's and every vertex's halfedge, borders included
  // (annulus: two border loops; the small OBJ: an unreferenced vertex; the bunny shuffled and rotated)
  std::vector<std::pair<std::string, std::string> > inputs;   // (name, OBJ text)
  for(const char* file : {"annulus.obj", "bunny.obj", "torus.obj"}) inputs.emplace_back(file, read_file(demo + file));
  inputs.emplace_back("small.obj", "v 0 0 0\nv 1 0 0\nv 9 9 9\nv 0 1 0\nv 1 1 0\nf 1 2 4\nf 2 5 4\n");
  {
    Mesh bunny;
    IO::read_mesh(demo + "bunny.obj", bunny);
    std::vector<std::array<std::size_t, 3> > faces;
    inputs.emplace_back("shuffled bunny", shuffled_obj(bunny, 11, faces));
  }
  for(const auto& input : inputs)
  {
    std::istringstream is(input.second);
    Mesh m;
    IO::read_mesh(is, "obj", input.first, m);
    ASSERT_TRUE(m.is_valid(false)) << input.first;
    Mesh ref;
    for(VI v : m.vertices()) ref.add_vertex(m.point(v));
    for(FI f : m.faces())
    {
      const auto t = triple(m, f);
      const FI g = ref.add_face(VI(Mesh::size_type(t[0])), VI(Mesh::size_type(t[1])), VI(Mesh::size_type(t[2])));
      ASSERT_EQ(g, f) << input.first;
    }
    ASSERT_EQ(m.number_of_halfedges(), ref.number_of_halfedges()) << input.first;
    std::size_t border = 0;
    for(auto h : m.halfedges())
    {
      ASSERT_EQ(m.target(h), ref.target(h)) << input.first << " halfedge " << h;
      ASSERT_EQ(m.next(h), ref.next(h)) << input.first << " halfedge " << h;
      ASSERT_EQ(m.prev(h), ref.prev(h)) << input.first << " halfedge " << h;
      ASSERT_EQ(m.face(h), ref.face(h)) << input.first << " halfedge " << h;
      border += m.is_border(h);
    }
    for(VI v : m.vertices())
    {
      // any incoming halfedge will do inside; on a border, the incoming border halfedge
      if(ref.is_isolated(v)) { ASSERT_TRUE(m.is_isolated(v)); continue; }
      ASSERT_EQ(m.target(m.halfedge(v)), v);
      ASSERT_EQ(m.is_border(v), ref.is_border(v)) << input.first << " vertex " << v;
      if(ref.is_border(v)) ASSERT_EQ(m.halfedge(v), ref.halfedge(v)) << input.first << " vertex " << v;
    }
    for(FI f : m.faces()) ASSERT_EQ(m.target(m.halfedge(f)), VI(Mesh::size_type(triple(m, f)[0])));
    if(input.first == "annulus.obj") EXPECT_GT(border, 0u);
  }
}

TEST(ReadMesh, DemoMeshes)
{
  struct Case { const char* file; std::size_t v, f; std::size_t polylines; };
  for(Case c : {Case{"annulus.obj", 3649, 7104, 0}, Case{"bunny.obj", 14290, 28576, 0},
                Case{"double-torus.obj", 3070, 6144, 0}, Case{"torus.obj", 3840, 7680, 0},
                Case{"DoubleTorusWithLoops.obj", 17476, 34956, 7}})
  {
    Mesh m;
    auto info = IO::read_mesh(demo + c.file, m);
    EXPECT_EQ(m.number_of_vertices(), c.v) << c.file;
    EXPECT_EQ(m.number_of_faces(), c.f) << c.file;
    EXPECT_EQ(info.obj_polylines.size(), c.polylines) << c.file;
    EXPECT_EQ(info.unreferenced_vertices, 0u) << c.file;
  }
}

TEST(ReadMesh, MissingFileAndBadExtension)
{
  Mesh m;
  try { IO::read_mesh(tdata + "does-not-exist.obj", m); FAIL(); }
  catch(const IO::Input_error& e)
  {
    EXPECT_EQ(e.line, 0u);
    EXPECT_NE(std::string(e.what()).find("does-not-exist.obj"), std::string::npos);
  }
  TempDir d;
  write_file(d / "x.xyz", "1 2 3\n");
  EXPECT_THROW(IO::read_mesh(d / "x.xyz", m), IO::Input_error);
  EXPECT_THROW(IO::read_mesh(d.path().string(), m), IO::Input_error);  // a directory
}

// ------------------------------------------------------------------------------------------------ edge numbering

TEST(AuthorsEdgeNumbering, HandMadeMesh)
{
  // faces (0,1,2), (2,1,3), (0,2,4): halfedges scanned 0>1 1>2 2>0 | 2>1 1>3 3>2 | 0>2 2>4 4>0
  std::istringstream is("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv -1 0.5 0\nf 1 2 3\nf 3 2 4\nf 1 3 5\n");
  Mesh m;
  IO::read_mesh(is, "obj", "hand.obj", m);
  auto ae = IO::authors_edge_numbering(m);
  std::vector<std::pair<std::size_t, std::size_t> > expected = {{0, 1}, {1, 2}, {2, 0}, {1, 3}, {3, 2}, {2, 4}, {4, 0}};
  EXPECT_EQ(ae, expected);

  // rotating a face in the file changes the numbering (the first vertex of each face matters)
  std::istringstream is2("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv -1 0.5 0\nf 2 3 1\nf 3 2 4\nf 1 3 5\n");
  Mesh m2;
  IO::read_mesh(is2, "obj", "hand2.obj", m2);
  std::vector<std::pair<std::size_t, std::size_t> > expected2 = {{1, 2}, {2, 0}, {0, 1}, {1, 3}, {3, 2}, {2, 4}, {4, 0}};
  EXPECT_EQ(IO::authors_edge_numbering(m2), expected2);
}

TEST(AuthorsEdgeNumbering, Grid)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  auto ae = IO::authors_edge_numbering(g);
  EXPECT_EQ(ae.size(), 33u);
  EXPECT_EQ(ae[0], (std::pair<std::size_t, std::size_t>{0, 1}));
  EXPECT_EQ(ae[1], (std::pair<std::size_t, std::size_t>{1, 5}));
  EXPECT_EQ(ae[2], (std::pair<std::size_t, std::size_t>{5, 0}));
  EXPECT_EQ(ae[3], (std::pair<std::size_t, std::size_t>{5, 4}));
  EXPECT_EQ(ae[4], (std::pair<std::size_t, std::size_t>{4, 0}));
}

// ------------------------------------------------------------------------------------------------ curve files

TEST(CurveFiles, DemoCounts)
{
  // algorithm-notes section 5.6
  struct Case { const char* mesh; const char* curve; std::size_t vpts, epts, segs; };
  for(Case c : {Case{"annulus.obj", "annulus.txt", 386, 0, 193}, Case{"bunny.obj", "bunny-heart.txt", 66, 31, 97},
                Case{"bunny.obj", "bunny-brokenheart.txt", 66, 31, 92},
                Case{"double-torus.obj", "double-torus.txt", 3, 87, 90}, Case{"torus.obj", "torus-phi.txt", 114, 0, 88}})
  {
    Mesh m;
    IO::read_mesh(demo + c.mesh, m);
    IO::Curve_set cs = IO::read_curve_file(demo + c.curve, m);
    std::size_t nv = 0, ne = 0;
    for(const auto& p : cs.points) (p.kind == IO::Curve_point::VERTEX ? nv : ne)++;
    EXPECT_EQ(nv, c.vpts) << c.curve;
    EXPECT_EQ(ne, c.epts) << c.curve;
    EXPECT_EQ(cs.segments.size(), c.segs) << c.curve;
    EXPECT_TRUE(cs.dual_pairs.empty());
    EXPECT_EQ(cs.file, demo + c.curve);
    for(const auto& p : cs.points)
      if(p.kind == IO::Curve_point::EDGE) { EXPECT_GT(p.t, 0.); EXPECT_LT(p.t, 1.); }
  }
  // first records of bunny-heart.txt: "v 9512" (line 2), "e 18761 0.686136" (line 4), "l 0 1" (line 3)
  Mesh bunny;
  IO::read_mesh(demo + "bunny.obj", bunny);
  IO::Curve_set heart = IO::read_curve_file(demo + "bunny-heart.txt", bunny);
  EXPECT_EQ(heart.points[0].kind, IO::Curve_point::VERTEX);
  EXPECT_EQ(heart.points[0].element, 9512u);
  EXPECT_EQ(heart.points[0].line, 2u);
  EXPECT_EQ(heart.points[1].kind, IO::Curve_point::EDGE);
  EXPECT_EQ(heart.points[1].element, 18761u);
  EXPECT_DOUBLE_EQ(heart.points[1].t, 0.686136);
  EXPECT_EQ(heart.segments[0].a, 0u);
  EXPECT_EQ(heart.segments[0].b, 1u);
  EXPECT_EQ(heart.segments[0].line, 3u);
}

TEST(CurveFiles, InlineObjPolylines)
{
  Mesh m;
  auto info = IO::read_mesh(demo + "DoubleTorusWithLoops.obj", m);
  ASSERT_TRUE(IO::has_curve_records(info));
  IO::Curve_set cs = IO::curve_set_from_obj(info, m);
  EXPECT_EQ(cs.segments.size(), 1086u);
  std::vector<int> chain = IO::vertex_curve_chain(m, cs);
  EXPECT_EQ(count_nonzero(chain_boundary(m, chain)), 14u);  // 7 open polylines
}

TEST(CurveFiles, FormatsAndDetection)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  TempDir d;
  // vertex polylines: a closed loop around the centre cell (5, 6, 10, 9) and an open path
  write_file(d / "p.txt", "# SWN  Polylines\n5 6 10 9 5   # loop\n\n0 1 2\n");
  IO::Curve_set p = IO::read_curve_file(d / "p.txt", g);
  EXPECT_EQ(p.segments.size(), 6u);
  EXPECT_EQ(p.points.size(), 7u);
  EXPECT_EQ(p.segments[0].line, 2u);
  EXPECT_EQ(p.segments[5].line, 4u);
  auto chain = IO::vertex_curve_chain(g, p);
  auto b = chain_boundary(g, chain);
  EXPECT_EQ(count_nonzero(b), 2u);
  EXPECT_EQ(b[0], -1);
  EXPECT_EQ(b[2], 1);

  // halfedges with multiplicity; opposite halfedges cancel
  write_file(d / "h.txt", "# swn halfedges\nh 5 6 2\nh 6 5\n# comment\nh 6 10\n");
  IO::Curve_set h = IO::read_curve_file(d / "h.txt", g);
  EXPECT_EQ(h.segments.size(), 4u);
  auto hc = IO::vertex_curve_chain(g, h);
  auto e56 = g.edge(g.halfedge(VI(5), VI(6)));
  EXPECT_EQ(std::abs(hc[std::size_t(e56)]), 1);
  auto hb = chain_boundary(g, hc);
  EXPECT_EQ(hb[5], -1);
  EXPECT_EQ(hb[10], 1);

  // authors' format with the default 1-based offset, a forward node reference and n/#l lines
  write_file(d / "a.txt", "l 1 2\nv 6\n#l 2 1\nn 3\nv 7\n");
  IO::Curve_set a = IO::read_curve_file(d / "a.txt", g);
  ASSERT_EQ(a.segments.size(), 1u);
  EXPECT_EQ(a.points[a.segments[0].a].element, 5u);
  EXPECT_EQ(a.points[a.segments[0].b].element, 6u);

  // CRLF line ends, trailing blanks and a UTF-8 byte order mark are harmless
  write_file(d / "crlf.txt", "\xEF\xBB\xBF#offset 0 \r\nv 5 \r\nv 6\t\r\nl 0 1 \r\n");
  IO::Curve_set crlf = IO::read_curve_file(d / "crlf.txt", g);
  ASSERT_EQ(crlf.segments.size(), 1u);
  EXPECT_EQ(crlf.points[1].element, 6u);

  // forced format
  write_file(d / "f.txt", "5 6\n");
  EXPECT_EQ(IO::read_curve_file(d / "f.txt", g, IO::Curve_file_format::POLYLINES).segments.size(), 1u);
  EXPECT_THROW(IO::read_curve_file(d / "f.txt", g), IO::Input_error);  // authors' format: unknown record '5'
}

TEST(CurveFiles, EdgeParameterZeroOrOneIsAVertex)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  // edge 1 runs 1 -> 5
  std::istringstream is("#offset 0\ne 1 0\ne 1 1\nl 0 1\n");
  IO::Curve_set cs = IO::read_curves(is, "t01.txt", g);
  ASSERT_EQ(cs.points.size(), 2u);
  EXPECT_EQ(cs.points[0].kind, IO::Curve_point::VERTEX);
  EXPECT_EQ(cs.points[0].element, 1u);
  EXPECT_EQ(cs.points[1].kind, IO::Curve_point::VERTEX);
  EXPECT_EQ(cs.points[1].element, 5u);
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, cs, o);
  EXPECT_FALSE(r.cut);
  EXPECT_EQ(r.mesh.number_of_vertices(), 16u);
  EXPECT_EQ(count_nonzero(chain_boundary(r.mesh, r.chain)), 2u);
}

// ------------------------------------------------------------------------------------------------ malformed corpus

TEST(Malformed, Corpus)
{
  const std::string dir = tdata + "malformed/";
  Mesh grid;
  IO::read_mesh(tdata + "grid4.off", grid);
  std::ifstream manifest(dir + "MANIFEST");
  ASSERT_TRUE(manifest) << "missing " << dir << "MANIFEST";
  std::string line;
  std::size_t cases = 0;
  std::set<std::string> listed;
  while(std::getline(manifest, line))
  {
    if(line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string file, substring;
    std::size_t expected_line;
    ls >> file >> expected_line;
    std::getline(ls, substring);
    substring.erase(0, substring.find_first_not_of(' '));
    substring = substring.substr(0, substring.find("  # soup"));   // the tool's own marker (test_tool)
    listed.insert(file);
    ++cases;
    const std::string path = dir + file;
    SCOPED_TRACE(file);
    try
    {
      if(IO::mesh_file_format(file) == "txt")
      {
        IO::Curve_set cs = IO::read_curve_file(path, grid);
        IO::conforming_cut(grid, cs);
      }
      else
      {
        Mesh m;
        auto info = IO::read_mesh(path, m);
        IO::Curve_set cs = IO::curve_set_from_obj(info, m);
        if(!cs.segments.empty() || !cs.dual_pairs.empty()) IO::conforming_cut(m, cs);
      }
      ADD_FAILURE() << "no Input_error for " << file;
    }
    catch(const IO::Input_error& e)
    {
      const std::string what = e.what();
      EXPECT_EQ(e.line, expected_line) << what;
      EXPECT_NE(what.find(file), std::string::npos) << what;
      if(expected_line != 0)
      {
        EXPECT_NE(what.find(file + ":" + std::to_string(expected_line) + ": "), std::string::npos) << what;
      }
      EXPECT_NE(what.find(substring), std::string::npos) << "expected '" << substring << "' in: " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos);
    }
    catch(const std::exception& e)
    {
      ADD_FAILURE() << "unexpected exception type for " << file << ": " << e.what();
    }
  }
  EXPECT_GE(cases, 20u);
  // every file of the directory is in the manifest
  for(const auto& entry : fs::directory_iterator(dir))
  {
    std::string name = entry.path().filename().string();
    if(name != "MANIFEST")
    {
      EXPECT_TRUE(listed.count(name)) << name << " not listed in MANIFEST";
    }
  }
}

TEST(Malformed, RandomGarbageNeverCrashes)
{
  // random byte strings and random mutations of valid files: readers either succeed or throw Input_error
  Mesh grid;
  IO::read_mesh(tdata + "grid4.off", grid);
  std::mt19937 rng(12345);
  const std::string seeds[] = {octa_off(), octa_obj(), octa_ply_ascii(), octa_ply_binary_be(), octa_stl_ascii(),
                               octa_stl_binary(), read_file(demo + "double-torus.txt").substr(0, 400)};
  const char* fmts[] = {"off", "obj", "ply", "ply", "stl", "stl", "txt"};
  for(int iter = 0; iter < 700; ++iter)
  {
    std::size_t k = static_cast<std::size_t>(iter) % 7;
    std::string s = seeds[k];
    int mutations = 1 + static_cast<int>(rng() % 4);
    for(int m = 0; m < mutations && !s.empty(); ++m)
    {
      std::size_t pos = rng() % s.size();
      switch(rng() % 4)
      {
        case 0: s[pos] = static_cast<char>(rng() % 256); break;
        case 1: s.erase(pos, 1 + rng() % 8); break;
        case 2: s.insert(pos, std::string(1 + rng() % 3, "0123456789 -.\n/#eEnafl"[rng() % 22])); break;
        default: s.resize(pos); break;
      }
    }
    std::istringstream is(s);
    try
    {
      if(k == 6) IO::read_curves(is, "fuzz.txt", grid);
      else { Mesh m; IO::read_mesh(is, fmts[k], "fuzz", m); }
    }
    catch(const IO::Input_error&) {}
  }
  SUCCEED();
}
