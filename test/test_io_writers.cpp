// Tests of the swn tool's writers (tools/swn/swn_io/): labels, the labelled PLY, the authors' w.obj, curve
// OBJ files, JSON and the all-or-nothing output directory.

#include "swn_io/atomic_output_dir.h"
#include "swn_io/conforming_cut.h"
#include "swn_io/json.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include "swn_io/write_outputs.h"

#include "test_io_support.h"

#include <CGAL/IO/PLY.h>

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

// ------------------------------------------------------------------------------------------------ writers


TEST(Writers, Labels)
{
  Mesh m = octahedron();
  std::vector<int> labels = {0, 1, -2, 3, 4, 5, 6, 1000};
  std::ostringstream os;
  IO::write_labels(os, m, labels);
  std::istringstream is(os.str());
  std::vector<int> back;
  int x;
  while(is >> x) back.push_back(x);
  EXPECT_EQ(back, labels);
  EXPECT_THROW(IO::write_labels(os, m, std::vector<int>(3)), std::invalid_argument);
}

TEST(Writers, PlyRoundTripAsciiAndBinary)
{
  Mesh m = octahedron();
  std::vector<int> labels = {0, 1, -1, 2, 3, 10, 11, 0};
  TempDir d;
  for(bool binary : {false, true})
  {
    // NaN only in binary (CGAL's ASCII reader rejects "nan")
    std::vector<double> w = {0.25, 1.5, -0.75, 2.0, 3.0, 10.125, 11.0, binary ? std::nan("") : -1e-3};
    std::string path = d / (binary ? "b.ply" : "a.ply");
    {
      std::ofstream os(path, std::ios::binary);
      IO::write_labeled_ply(os, m, labels, w, binary);
    }
    // our reader: geometry and order
    Mesh back;
    IO::read_mesh(path, back);
    expect_octa_order(back);
    // CGAL's reader: the face properties
    Mesh cg;
    std::ifstream is(path, std::ios::binary);
    ASSERT_TRUE(CGAL::IO::read_PLY(is, cg)) << path;
    ASSERT_EQ(cg.number_of_faces(), 8u);
    auto lab = cg.property_map<FI, int>("f:label");
    auto wn = cg.property_map<FI, float>("f:winding_number");
    auto col = cg.property_map<FI, CGAL::IO::Color>("f:color");
    ASSERT_TRUE(lab.second);
    ASSERT_TRUE(wn.second);
    ASSERT_TRUE(col.second);
    for(FI f : cg.faces())
    {
      EXPECT_EQ(lab.first[f], labels[std::size_t(f)]);
      if(std::isnan(w[std::size_t(f)])) EXPECT_TRUE(std::isnan(wn.first[f]));
      else EXPECT_EQ(wn.first[f], static_cast<float>(w[std::size_t(f)]));
      auto c = IO::label_color(labels[std::size_t(f)]);
      EXPECT_EQ(col.first[f].red(), c[0]);
      EXPECT_EQ(col.first[f].green(), c[1]);
      EXPECT_EQ(col.first[f].blue(), c[2]);
    }
  }
  // palette: stable, neighbours differ, negative labels fine
  EXPECT_EQ(IO::label_color(3), IO::label_color(13));
  EXPECT_EQ(IO::label_color(-1), IO::label_color(9));
  for(int l = -20; l < 20; ++l) EXPECT_NE(IO::label_color(l), IO::label_color(l + 1));
}

TEST(Writers, WObjAuthorsFormat)
{
  Mesh m = octahedron();
  // w at corner h: a value depending on face and vertex; NaN at vertex 3
  std::vector<double> w(m.number_of_halfedges(), -1.);
  for(FI f : m.faces())
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
      w[std::size_t(h)] = (std::size_t(m.target(h)) == 3) ? std::nan("") : 0.1 * double(f) + std::size_t(m.target(h)) / 3.0;
  std::ostringstream os;
  IO::write_w_obj(os, m, w);
  std::istringstream is(os.str());
  std::string line;
  std::vector<std::array<double, 3> > v;
  std::vector<std::pair<double, double> > vt;
  std::vector<std::vector<std::string> > f;
  std::vector<std::string> header;
  while(std::getline(is, line))
  {
    std::istringstream ls(line);
    std::string kw;
    ls >> kw;
    if(kw == "#") header.push_back(line);
    else if(kw == "v") { std::array<double, 3> p; ls >> p[0] >> p[1] >> p[2]; v.push_back(p); }
    else if(kw == "vt") { double a, b; ls >> a >> b; vt.emplace_back(a, b); }
    else if(kw == "f") { std::vector<std::string> t(3); ls >> t[0] >> t[1] >> t[2]; f.push_back(t); }
    else FAIL() << "unexpected line " << line;
  }
  ASSERT_EQ(header.size(), 5u);
  EXPECT_EQ(header[1], "#  vertices: 6");
  EXPECT_EQ(header[2], "#     edges: 12");
  EXPECT_EQ(header[3], "#     faces: 8");
  EXPECT_EQ(header[4], "# texture coordinates: YES");
  ASSERT_EQ(v.size(), 6u);
  for(std::size_t i = 0; i < 6; ++i)
    for(int c = 0; c < 3; ++c) EXPECT_EQ(v[i][c], octa_points[i][c]);  // full precision
  ASSERT_EQ(vt.size(), 24u);
  ASSERT_EQ(f.size(), 8u);
  std::size_t corner = 0;
  for(std::size_t j = 0; j < 8; ++j)
    for(int c = 0; c < 3; ++c)
    {
      ++corner;
      std::size_t vid = octa_faces[j][c];
      EXPECT_EQ(f[j][c], std::to_string(vid + 1) + "/" + std::to_string(corner) + "/");
      if(vid == 3) { EXPECT_EQ(vt[corner - 1].first, 0.); EXPECT_EQ(vt[corner - 1].second, 0.); }
      else
      {
        EXPECT_EQ(vt[corner - 1].first, 0.1 * double(j) + vid / 3.0);
        EXPECT_EQ(vt[corner - 1].second, 1.);
      }
    }
}

// A grid of 2 * 60 * 60 triangles: every writer's output spans many of the 64 KiB blocks it is gathered in.
// Extreme doubles (denormals, huge, negative zero, values with 17 significant digits) read back bit for bit
// from w.obj and the ASCII PLY; the binary PLY has exactly the size its header announces.
TEST(Writers, LargeOutputsReadBackExactly)
{
  constexpr int n = 60;
  Mesh m;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) m.add_vertex(Point(i / 7.0, j * 1e-3 / 3.0, 1e10 + i * 0.1));
  auto vid = [](int i, int j) { return VI(static_cast<Mesh::size_type>(j * (n + 1) + i)); };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      ASSERT_NE(m.add_face(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)), Mesh::null_face());
      ASSERT_NE(m.add_face(vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)), Mesh::null_face());
    }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> w(m.number_of_halfedges());
  for(std::size_t k = 0; k < w.size(); ++k)
  {
    switch(k % 6)
    {
      case 0: w[k] = u(rng); break;
      case 1: w[k] = u(rng) * 1e300; break;
      case 2: w[k] = std::numeric_limits<double>::denorm_min() * double(k); break;
      case 3: w[k] = -0.0; break;
      case 4: w[k] = std::nan(""); break;
      default: w[k] = std::nextafter(double(k % 11), 20.0); break;
    }
  }
  auto bits = [](double x) { std::uint64_t b; std::memcpy(&b, &x, 8); return b; };
  auto parse = [](const std::string& tok) {   // exact, locale independent, denormals included
    double x = 0;
    const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), x);
    EXPECT_TRUE(r.ec == std::errc() && r.ptr == tok.data() + tok.size()) << tok;
    return x;
  };

  std::ostringstream wobj;
  IO::write_w_obj(wobj, m, w);
  ASSERT_GT(wobj.str().size(), std::size_t(10) << 16);
  std::istringstream is(wobj.str());
  std::string line;
  std::size_t nv = 0, nvt = 0, nf = 0;
  std::vector<double> expected;   // w per corner, in the writer's order
  for(FI f : m.faces())
  {
    auto h = m.halfedge(f);
    for(int k = 0; k < 3; ++k, h = m.next(h)) expected.push_back(w[std::size_t(h)]);
  }
  while(std::getline(is, line))
  {
    std::istringstream ls(line);
    std::string kw, a, b, c;
    ls >> kw >> a >> b >> c;
    if(kw == "v")
    {
      const Point& p = m.point(VI(static_cast<Mesh::size_type>(nv++)));
      EXPECT_EQ(bits(parse(a)), bits(p.x()));
      EXPECT_EQ(bits(parse(b)), bits(p.y()));
      EXPECT_EQ(bits(parse(c)), bits(p.z()));
    }
    else if(kw == "vt")
    {
      const double x = expected.at(nvt++);
      if(std::isnan(x)) { EXPECT_EQ(a, "0"); EXPECT_EQ(b, "0"); }
      else { EXPECT_EQ(bits(parse(a)), bits(x)) << a; EXPECT_EQ(b, "1"); }
    }
    else if(kw == "f") ++nf;
  }
  EXPECT_EQ(nv, m.number_of_vertices());
  EXPECT_EQ(nvt, 3 * m.number_of_faces());
  EXPECT_EQ(nf, m.number_of_faces());

  std::vector<int> labels(m.number_of_faces());
  std::vector<double> wf(m.number_of_faces());
  for(std::size_t f = 0; f < labels.size(); ++f) { labels[f] = int(f % 7) - 3; wf[f] = u(rng); }
  std::ostringstream bin, ascii;
  IO::write_labeled_ply(bin, m, labels, wf, true);
  IO::write_labeled_ply(ascii, m, labels, wf, false);
  const std::string b = bin.str();
  const std::size_t header = b.find("end_header\n") + std::string("end_header\n").size();
  // vertices: 3 doubles; faces: count, 3 indices, label, float, 4 colour bytes (RGBA)
  EXPECT_EQ(b.size() - header, m.number_of_vertices() * 24 + m.number_of_faces() * (1 + 12 + 4 + 4 + 4));
  std::istringstream as(ascii.str());
  while(std::getline(as, line) && line != "end_header") {}
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
  {
    ASSERT_TRUE(std::getline(as, line));
    std::istringstream ls(line);
    std::string x, y, z;
    ls >> x >> y >> z;
    const Point& p = m.point(VI(static_cast<Mesh::size_type>(v)));
    EXPECT_EQ(bits(parse(x)), bits(p.x()));
    EXPECT_EQ(bits(parse(z)), bits(p.z()));
  }
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    ASSERT_TRUE(std::getline(as, line));
    std::istringstream ls(line);
    int three, i0, i1, i2, label;
    std::string wtok;
    ls >> three >> i0 >> i1 >> i2 >> label >> wtok;
    EXPECT_EQ(three, 3);
    EXPECT_EQ(label, labels[f]);
    float wv = 0;
    EXPECT_EQ(std::from_chars(wtok.data(), wtok.data() + wtok.size(), wv).ec, std::errc());
    EXPECT_EQ(wv, static_cast<float>(wf[f]));
  }
  EXPECT_FALSE(std::getline(as, line));
}

TEST(Writers, ChainObjRoundTripWithMultiplicity)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  // loop 5->6->10->9->5 twice, plus an open path 0->1->2, plus 12->13 reversed (-1 on a canonical edge)
  std::vector<int> chain(g.number_of_edges(), 0);
  auto add = [&](std::size_t a, std::size_t b, int k) {
    auto h = g.halfedge(VI(static_cast<Mesh::size_type>(a)), VI(static_cast<Mesh::size_type>(b)));
    chain[std::size_t(g.edge(h))] += (std::size_t(h) % 2 == 0) ? k : -k;
  };
  add(5, 6, 2); add(6, 10, 2); add(10, 9, 2); add(9, 5, 2);
  add(0, 1, 1); add(1, 2, 1);
  add(13, 12, 1);
  auto pieces = IO::chain_to_polylines(g, chain);
  EXPECT_EQ(pieces.size(), 3u);  // 0-1-2, 13-12, one circuit traversing the loop twice
  for(bool all : {true, false})
  {
    std::ostringstream os;
    IO::write_chain_obj(os, g, chain, all);
    // parse: v lines and l lines; rebuild the chain through the positions
    std::istringstream is(os.str());
    std::string line;
    std::vector<Point> pts;
    std::vector<int> back(g.number_of_edges(), 0);
    std::map<std::array<double, 3>, std::size_t> vid;
    for(VI v : g.vertices()) vid[{g.point(v).x(), g.point(v).y(), g.point(v).z()}] = std::size_t(v);
    while(std::getline(is, line))
    {
      std::istringstream ls(line);
      std::string kw;
      ls >> kw;
      if(kw == "v") { double x, y, z; ls >> x >> y >> z; pts.emplace_back(x, y, z); }
      else if(kw == "l")
      {
        std::vector<std::size_t> idx;
        std::size_t i;
        while(ls >> i) idx.push_back(i);
        for(std::size_t k = 0; k + 1 < idx.size(); ++k)
        {
          const Point& a = pts.at(idx[k] - 1);
          const Point& b = pts.at(idx[k + 1] - 1);
          std::size_t va = vid.at({a.x(), a.y(), a.z()}), vb = vid.at({b.x(), b.y(), b.z()});
          auto h = g.halfedge(VI(static_cast<Mesh::size_type>(va)), VI(static_cast<Mesh::size_type>(vb)));
          ASSERT_TRUE(h.is_valid());
          back[std::size_t(g.edge(h))] += (std::size_t(h) % 2 == 0) ? 1 : -1;
        }
      }
    }
    EXPECT_EQ(pts.size(), all ? 16u : 9u);
    EXPECT_EQ(back, chain);
  }
}

TEST(Writers, ChainPolylinesAreLong)
{
  // the closed heart after cutting is one polyline; the broken heart one open polyline
  Mesh bunny;
  IO::read_mesh(demo + "bunny.obj", bunny);
  for(auto c : {std::make_pair("bunny-heart.txt", true), std::make_pair("bunny-brokenheart.txt", false)})
  {
    auto r = IO::conforming_cut(bunny, IO::read_curve_file(demo + c.first, bunny));
    auto pieces = IO::chain_to_polylines(r.mesh, r.chain);
    ASSERT_EQ(pieces.size(), 1u) << c.first;
    EXPECT_EQ(pieces[0].front() == pieces[0].back(), c.second) << c.first;
  }
}

TEST(Writers, Json)
{
  IO::Json j = IO::Json::object();
  j["name"] = "a \"quoted\"\\path\n\t\x01";
  j["vertices"] = std::size_t(14318);
  j["negative"] = -3;
  j["ratio"] = 0.1;
  j["nan"] = std::nan("");
  j["ok"] = true;
  j["none"] = nullptr;
  j["files"] = IO::Json::array();
  j["files"].push_back("w.obj");
  j["files"].push_back(IO::Json::object());
  j["counts"] = std::vector<int>{1, 2};
  j["nested"]["a"] = 1;
  EXPECT_EQ(j.dump(-1),
            "{\"name\":\"a \\\"quoted\\\"\\\\path\\n\\t\\u0001\",\"vertices\":14318,\"negative\":-3,\"ratio\":0.1,"
            "\"nan\":null,\"ok\":true,\"none\":null,\"files\":[\"w.obj\",{}],\"counts\":[1,2],\"nested\":{\"a\":1}}");
  std::string pretty = j.dump();
  EXPECT_NE(pretty.find("\n  \"vertices\": 14318,\n"), std::string::npos);
  EXPECT_EQ(pretty.back(), '\n');
}

TEST(Writers, JsonStreaming)
{
  IO::Json j;
  j.begin_object()
    .key("version").value(std::string("0.1.0"))
    .key("input").begin_object().key("vertices").value(std::size_t(3)).key("ok").value(true).end_object()
    .key("labels").begin_array();
  for(int l : {0, 1})
    j.begin_object().key("label").value(double(l)).key("faces").value(l + 10).end_object();
  j.end_array().key("t").value(0.5).end_object();
  EXPECT_EQ(j.str(-1), "{\"version\":\"0.1.0\",\"input\":{\"vertices\":3,\"ok\":true},\"labels\":[{\"label\":0,"
                       "\"faces\":10},{\"label\":1,\"faces\":11}],\"t\":0.5}");
  IO::Json bad;
  bad.begin_array();
  EXPECT_THROW(bad.end_object(), std::logic_error);
  EXPECT_THROW(bad.key("x"), std::logic_error);
  EXPECT_THROW(bad.str(), std::logic_error);
}

TEST(Writers, PropertyMapsAndPaths)
{
  // the calling style of the swn tool: Surface_mesh property maps, files written through Atomic_output_dir
  Mesh m = octahedron();
  auto labels = m.add_property_map<FI, int>("f:label", 0).first;
  auto w = m.add_property_map<Mesh::Halfedge_index, double>("h:w", 0.).first;
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  for(FI f : m.faces()) labels[f] = int(std::size_t(f)) % 3;
  for(auto h : m.halfedges()) w[h] = std::size_t(m.target(h)) == 0 ? std::nan("") : double(std::size_t(m.target(h)));
  // a loop around vertex 0: 1 -> 5 -> 4 -> 2 -> 1
  std::size_t loop[] = {1, 5, 4, 2, 1};
  for(int k = 0; k < 4; ++k)
  {
    auto h = m.halfedge(VI(static_cast<Mesh::size_type>(loop[k])), VI(static_cast<Mesh::size_type>(loop[k + 1])));
    chain[m.edge(h)] += (std::size_t(h) % 2 == 0) ? 1 : -1;
  }
  TempDir d;
  {
    IO::Atomic_output_dir out(d / "o");
    IO::write_labels(out.path("labels.txt"), m, labels);
    IO::write_labeled_ply(out.path("mesh.ply"), m, labels, w);
    IO::write_w_obj(out.path("w.obj"), m, w);
    IO::write_chain_obj(out.path("bounding.obj"), m, chain);
    IO::write_text_file(out.path("summary.json"), "{}\n");
    out.commit();
  }
  EXPECT_EQ(read_file(d / "o/labels.txt"), "0\n1\n2\n0\n1\n2\n0\n1\n");
  Mesh cg;
  std::ifstream is(d / "o/mesh.ply", std::ios::binary);
  ASSERT_TRUE(CGAL::IO::read_PLY(is, cg));
  auto wn = cg.property_map<FI, float>("f:winding_number");
  ASSERT_TRUE(wn.second);
  // face 0 = (1, 5, 0): corner 0 undefined, mean of 1 and 5
  EXPECT_FLOAT_EQ(wn.first[FI(0)], 3.f);
  std::string wobj = read_file(d / "o/w.obj");
  EXPECT_NE(wobj.find("\nvt 1 1\nvt 5 1\nvt 0 0\n"), std::string::npos);
  EXPECT_NE(wobj.find("\nf 2/1/ 6/2/ 1/3/\n"), std::string::npos);
  std::string bobj = read_file(d / "o/bounding.obj");
  EXPECT_NE(bobj.find("\n# mesh vertices: 1 2 4 5\n"), std::string::npos) << bobj;
  EXPECT_NE(bobj.find("\nl 1 4 3 2 1\n"), std::string::npos) << bobj;
}

TEST(Writers, AtomicOutputDir)
{
  TempDir d;
  const std::string target = d / "out/nested";
  // failure: an exception after some files were written leaves nothing (and removes the created dirs)
  try
  {
    IO::Atomic_output_dir out(target);
    EXPECT_TRUE(fs::is_directory(target));
    out.write("labels.txt", [](std::ostream& os) { os << "1\n2\n"; });
    out.write("w.obj", [](std::ostream& os) { os << "v 0 0 0\n"; });
    EXPECT_EQ(std::distance(fs::directory_iterator(target), fs::directory_iterator()), 2);
    EXPECT_FALSE(fs::exists(target + "/labels.txt"));  // only temporaries so far
    out.write("summary.json", [](std::ostream&) { throw std::runtime_error("solver failed"); });
    FAIL();
  }
  catch(const std::runtime_error& e)
  {
    EXPECT_STREQ(e.what(), "solver failed");
  }
  EXPECT_FALSE(fs::exists(d / "out"));
  EXPECT_TRUE(fs::is_empty(d.path()));

  // an existing directory is kept, and existing files are not touched on failure
  fs::create_directories(target);
  write_file(target + "/labels.txt", "old\n");
  {
    IO::Atomic_output_dir out(target);
    out.write("labels.txt", [](std::ostream& os) { os << "new\n"; });
  }
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(read_file(target + "/labels.txt"), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(target), fs::directory_iterator()), 1);

  // success
  {
    IO::Atomic_output_dir out(target);
    out.write("labels.txt", [](std::ostream& os) { os << "new\n"; });
    out.write("summary.json", [](std::ostream& os) { os << "{}\n"; });
    EXPECT_THROW(out.write("labels.txt", [](std::ostream&) {}), std::invalid_argument);
    EXPECT_THROW(out.temporary_path("../escape"), std::invalid_argument);
    out.commit();
  }
  EXPECT_EQ(read_file(target + "/labels.txt"), "new\n");
  EXPECT_EQ(read_file(target + "/summary.json"), "{}\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(target), fs::directory_iterator()), 2);
}
