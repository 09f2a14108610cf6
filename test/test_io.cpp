// Tests of the swn tool's file handling (tools/swn/swn_io/) and of the library's conforming_cut().

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "swn_io/errors.h"
#include "swn_io/read_mesh.h"
#include "swn_io/read_curves.h"
#include "swn_io/conforming_cut.h"
#include "swn_io/write_outputs.h"
#include "swn_io/json.h"
#include "swn_io/atomic_output_dir.h"

#include <CGAL/Surface_winding_numbers/conforming_cut.h>
#include <CGAL/surface_winding_numbers.h>

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <CGAL/IO/OFF.h>  // independent readers: cross-checks of ours
#include <CGAL/IO/PLY.h>

#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#ifndef SWN_TEST_DATA_DIR
#define SWN_TEST_DATA_DIR "test/data"
#endif
#ifndef SWN_REPO_DATA_DIR
#define SWN_REPO_DATA_DIR "data"
#endif

namespace IO = CGAL::Surface_winding_numbers::IO;
namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index VI;
typedef Mesh::Face_index FI;

namespace {

const std::string demo = std::string(SWN_REPO_DATA_DIR) + "/swn-demo/";
const std::string tdata = std::string(SWN_TEST_DATA_DIR) + "/";

// a fresh temporary directory per test
class TempDir
{
public:
  TempDir()
  {
    std::random_device rd;
    path_ = fs::temp_directory_path() / ("swn_test_io_" + std::to_string(rd()) + "_" + std::to_string(rd()));
    fs::create_directories(path_);
  }
  ~TempDir() { std::error_code ec; fs::remove_all(path_, ec); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }
private:
  fs::path path_;
};

void write_file(const std::string& path, const std::string& content)
{
  std::ofstream os(path, std::ios::binary);
  os << content;
}

std::string read_file(const std::string& path)
{
  std::ifstream is(path, std::ios::binary);
  std::stringstream s;
  s << is.rdbuf();
  return s.str();
}

std::array<std::size_t, 3> triple(const Mesh& m, FI f)
{
  std::array<std::size_t, 3> r;
  std::size_t k = 0;
  for(VI v : CGAL::vertices_around_face(m.halfedge(f), m)) r[k++] = std::size_t(v);
  return r;
}

// `mesh` as OBJ text with its faces shuffled and each rotated (random with `seed`); `faces` gets them
// in the order written
std::string shuffled_obj(const Mesh& mesh, unsigned seed, std::vector<std::array<std::size_t, 3> >& faces)
{
  faces.clear();
  for(FI f : mesh.faces()) faces.push_back(triple(mesh, f));
  std::mt19937 rng(seed);
  std::shuffle(faces.begin(), faces.end(), rng);
  for(auto& t : faces) std::rotate(t.begin(), t.begin() + (rng() % 3), t.end());
  std::ostringstream os;
  os.precision(17);
  for(VI v : mesh.vertices()) os << "v " << mesh.point(v) << "\n";
  for(auto& t : faces) os << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << "\n";
  return os.str();
}

// boundary of a chain: arrivals minus departures
std::vector<long long> chain_boundary(const Mesh& m, const std::vector<int>& chain)
{
  std::vector<long long> b(m.number_of_vertices(), 0);
  for(auto e : m.edges())
  {
    auto h = m.halfedge(e);
    b[std::size_t(m.target(h))] += chain[std::size_t(e)];
    b[std::size_t(m.source(h))] -= chain[std::size_t(e)];
  }
  return b;
}

std::size_t count_nonzero(const std::vector<long long>& v)
{
  std::size_t n = 0;
  for(long long x : v) n += (x != 0);
  return n;
}

// ---- a small closed test mesh: an octahedron with an unusual vertex and face order
const std::vector<std::array<double, 3> > octa_points = {
  {0, 0, 1.25}, {1, 0, 0}, {0, -1, 0}, {0.1, 0.2, -1}, {-1, 0, 0}, {0, 1.0000000000000002, 0}};
// faces, CCW from outside, deliberately rotated
const std::vector<std::array<std::size_t, 3> > octa_faces = {
  {1, 5, 0}, {5, 4, 0}, {0, 4, 2}, {2, 1, 0}, {3, 5, 1}, {4, 5, 3}, {3, 2, 4}, {1, 2, 3}};

std::string fmt17(double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

std::string octa_off()
{
  std::string s = "OFF\n# octahedron\n6 8 0\n";
  for(auto& p : octa_points) s += fmt17(p[0]) + " " + fmt17(p[1]) + " " + fmt17(p[2]) + "\n";
  for(auto& f : octa_faces) s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
  return s;
}

std::string octa_obj()
{
  std::string s = "# octahedron\nmtllib x.mtl\no oct\n";
  for(auto& p : octa_points) s += "v  " + fmt17(p[0]) + " " + fmt17(p[1]) + "  " + fmt17(p[2]) + "\r\n";
  s += "vt 0 0\nvt 1 0\nvn 0 0 1\ng group\nusemtl m\ns 1\n";
  int k = 0;
  for(auto& f : octa_faces)
  {
    // mix the token styles: 12, 12/, 12/5/3, 12//3, negative
    std::string t[3];
    for(int c = 0; c < 3; ++c)
    {
      long long i = static_cast<long long>(f[c]) + 1;
      switch((k + c) % 5)
      {
        case 0: t[c] = std::to_string(i); break;
        case 1: t[c] = std::to_string(i) + "/"; break;
        case 2: t[c] = std::to_string(i) + "/1/1"; break;
        case 3: t[c] = std::to_string(i) + "//1"; break;
        default: t[c] = std::to_string(i - 7); break;  // relative: -1 is the last vertex (6 vertices)
      }
    }
    s += "f " + t[0] + "  " + t[1] + " " + t[2] + (k % 2 ? "\r\n" : "\n");
    ++k;
  }
  return s;
}

std::string octa_ply_ascii()
{
  std::string s = "ply\nformat ascii 1.0\ncomment test\nelement vertex 6\nproperty double x\nproperty double y\n"
                  "property double z\nproperty uchar red\nelement face 8\nproperty list uchar int vertex_indices\n"
                  "property int extra\nelement edge 0\nproperty int vertex1\nend_header\n";
  for(auto& p : octa_points) s += fmt17(p[0]) + " " + fmt17(p[1]) + " " + fmt17(p[2]) + " 7\n";
  for(auto& f : octa_faces) s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " 42\n";
  return s;
}

template <class T>
void put_be(std::string& s, T v)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  for(std::size_t i = 0; i < sizeof(T); ++i) s += static_cast<char>(b[sizeof(T) - 1 - i]);  // host is LE
}

std::string octa_ply_binary_be()
{
  std::string s = "ply\nformat binary_big_endian 1.0\nelement vertex 6\nproperty float nx\nproperty double x\n"
                  "property double y\nproperty double z\nelement face 8\nproperty list uchar uint vertex_indices\nend_header\n";
  for(auto& p : octa_points)
  {
    put_be<float>(s, 0.5f);
    for(int c = 0; c < 3; ++c) put_be<double>(s, p[c]);
  }
  for(auto& f : octa_faces)
  {
    s += static_cast<char>(3);
    for(int c = 0; c < 3; ++c) put_be<std::uint32_t>(s, static_cast<std::uint32_t>(f[c]));
  }
  return s;
}

std::string octa_stl_ascii()
{
  std::string s = "solid octa\n";
  for(auto& f : octa_faces)
  {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for(int c = 0; c < 3; ++c)
    {
      auto& p = octa_points[f[c]];
      s += "      vertex " + fmt17(p[0]) + " " + fmt17(p[1]) + " " + fmt17(p[2]) + "\n";
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid octa\n";
}

std::string octa_stl_binary()
{
  std::string s(80, ' ');
  s.replace(0, 5, "solid");  // a binary STL may start with "solid": the size decides
  std::uint32_t n = static_cast<std::uint32_t>(octa_faces.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for(auto& f : octa_faces)
  {
    float zero[3] = {0, 0, 0};
    s.append(reinterpret_cast<const char*>(zero), 12);
    for(int c = 0; c < 3; ++c)
      for(int d = 0; d < 3; ++d)
      {
        float x = static_cast<float>(octa_points[f[c]][d]);
        s.append(reinterpret_cast<const char*>(&x), 4);
      }
    s += std::string(2, '\0');
  }
  return s;
}

void expect_octa_order(const Mesh& m, bool exact_points = true)
{
  ASSERT_EQ(m.number_of_vertices(), octa_points.size());
  ASSERT_EQ(m.number_of_faces(), octa_faces.size());
  EXPECT_TRUE(m.is_valid(false));
  for(std::size_t i = 0; i < octa_points.size(); ++i)
  {
    const Point& p = m.point(VI(static_cast<Mesh::size_type>(i)));
    for(int c = 0; c < 3; ++c)
    {
      if(exact_points) EXPECT_EQ(p[c], octa_points[i][c]) << "vertex " << i;
      else EXPECT_EQ(p[c], static_cast<double>(static_cast<float>(octa_points[i][c]))) << "vertex " << i;
    }
  }
  for(std::size_t j = 0; j < octa_faces.size(); ++j)
    EXPECT_EQ(triple(m, FI(static_cast<Mesh::size_type>(j))), octa_faces[j]) << "face " << j;
}

// the STL reader numbers vertices by first occurrence; check that face j has the file's corner positions
void expect_stl_faces(const Mesh& m, bool as_float)
{
  ASSERT_EQ(m.number_of_faces(), octa_faces.size());
  EXPECT_EQ(m.number_of_vertices(), 6u);
  EXPECT_TRUE(m.is_valid(false));
  std::vector<std::size_t> first_occurrence;
  for(std::size_t j = 0; j < octa_faces.size(); ++j)
  {
    auto t = triple(m, FI(static_cast<Mesh::size_type>(j)));
    for(int c = 0; c < 3; ++c)
    {
      const Point& p = m.point(VI(static_cast<Mesh::size_type>(t[c])));
      for(int d = 0; d < 3; ++d)
      {
        double expected = octa_points[octa_faces[j][c]][d];
        if(as_float) expected = static_cast<double>(static_cast<float>(expected));
        EXPECT_EQ(p[d], expected);
      }
      if(std::find(first_occurrence.begin(), first_occurrence.end(), octa_faces[j][c]) == first_occurrence.end())
      {
        EXPECT_EQ(t[c], first_occurrence.size()) << "STL vertices are numbered by first occurrence";
        first_occurrence.push_back(octa_faces[j][c]);
      }
    }
  }
}

} // namespace

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

// ------------------------------------------------------------------------------------------------ conforming cut

TEST(ConformingCut, DemoCounts)
{
  struct Case { const char* mesh; const char* curve; std::size_t v_cut, f_cut; std::size_t endpoints; bool cut; };
  for(Case c : {Case{"bunny.obj", "bunny-brokenheart.txt", 14318, 28632, 2, true},
                Case{"bunny.obj", "bunny-heart.txt", 14321, 28638, 0, true},
                Case{"double-torus.obj", "double-torus.txt", 3070 + 87, 6318, 0, true},
                Case{"annulus.obj", "annulus.txt", 3649, 7104, 2, false}})
  {
    Mesh m;
    IO::read_mesh(demo + c.mesh, m);
    IO::Curve_set cs = IO::read_curve_file(demo + c.curve, m);
    auto r = IO::conforming_cut(m, cs);
    EXPECT_EQ(r.cut, c.cut) << c.curve;
    EXPECT_EQ(r.vertices_after_cut, c.v_cut) << c.curve;
    EXPECT_EQ(r.faces_after_cut, c.f_cut) << c.curve;
    // none of these needs the short-piece refinement
    EXPECT_EQ(r.refine_new_vertices, 0u) << c.curve;
    EXPECT_EQ(r.mesh.number_of_vertices(), c.v_cut);
    EXPECT_TRUE(r.mesh.is_valid(false));
    ASSERT_EQ(r.chain.size(), r.mesh.number_of_edges());
    std::size_t curve_edges = 0;
    for(int x : r.chain) curve_edges += (x != 0);
    EXPECT_EQ(curve_edges, cs.segments.size()) << c.curve;  // every segment became one edge
    EXPECT_EQ(count_nonzero(chain_boundary(r.mesh, r.chain)), c.endpoints) << c.curve;
    // existing vertices keep index and position
    for(VI v : m.vertices()) ASSERT_EQ(r.mesh.point(v), m.point(v));
    // each used edge point became a vertex at (1-t) first + t second
    auto ae = IO::authors_edge_numbering(m);
    for(std::size_t i = 0; i < cs.points.size(); ++i)
    {
      const auto& p = cs.points[i];
      if(p.kind != IO::Curve_point::EDGE || r.point_vertex[i] == std::size_t(-1)) continue;
      EXPECT_GE(r.point_vertex[i], m.number_of_vertices());
      Point a = m.point(VI(static_cast<Mesh::size_type>(ae[p.element].first)));
      Point b = m.point(VI(static_cast<Mesh::size_type>(ae[p.element].second)));
      Point q = r.mesh.point(VI(static_cast<Mesh::size_type>(r.point_vertex[i])));
      EXPECT_NEAR(q.x(), (1 - p.t) * a.x() + p.t * b.x(), 1e-15);
      EXPECT_NEAR(q.y(), (1 - p.t) * a.y() + p.t * b.y(), 1e-15);
      EXPECT_NEAR(q.z(), (1 - p.t) * a.z() + p.t * b.z(), 1e-15);
    }
  }
}

TEST(ConformingCut, AnnulusEndpointsOnBoundary)
{
  Mesh m;
  IO::read_mesh(demo + "annulus.obj", m);
  auto r = IO::conforming_cut(m, IO::read_curve_file(demo + "annulus.txt", m));
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(b[3612], -1);  // start on the outer boundary
  EXPECT_EQ(b[3632], 1);   // end on the inner boundary
  EXPECT_EQ(r.refined_pieces, 0u);
}

TEST(ConformingCut, TorusPhiRefinement)
{
  Mesh m;
  IO::read_mesh(demo + "torus.obj", m);
  IO::Curve_set cs = IO::read_curve_file(demo + "torus-phi.txt", m);
  auto r = IO::conforming_cut(m, cs);
  EXPECT_FALSE(r.cut);
  EXPECT_EQ(r.vertices_after_cut, 3840u);
  // the authors' reference output torus_w.obj has 3899 V / 7798 F (+59 from splitting)
  EXPECT_EQ(r.mesh.number_of_vertices(), 3899u);
  EXPECT_EQ(r.mesh.number_of_faces(), 7798u);
  EXPECT_EQ(r.refine_new_vertices, 59u);
  EXPECT_TRUE(r.mesh.is_valid(false));
  // refinement keeps the endpoints and the total boundary
  auto b0 = chain_boundary(m, IO::vertex_curve_chain(m, cs));
  auto b1 = chain_boundary(r.mesh, r.chain);
  for(std::size_t v = 0; v < b0.size(); ++v) ASSERT_EQ(b0[v], b1[v]);
  for(std::size_t v = b0.size(); v < b1.size(); ++v) ASSERT_EQ(b1[v], 0);
  // without refinement: unchanged mesh
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r0 = IO::conforming_cut(m, cs, o);
  EXPECT_EQ(r0.mesh.number_of_vertices(), 3840u);
}

TEST(ConformingCut, ShortPieceRule)
{
  // grid: single-edge piece 5->6 with two interior endpoints -> 8 sub-edges (7 new vertices, 14 new faces)
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  std::istringstream is("# swn polylines\n5 6\n");
  auto r = IO::conforming_cut(g, IO::read_curves(is, "one.txt", g));
  EXPECT_EQ(r.refined_pieces, 1u);
  EXPECT_EQ(r.refine_new_vertices, 7u);
  EXPECT_EQ(r.refine_new_faces, 14u);
  std::size_t curve_edges = 0;
  for(int x : r.chain) curve_edges += (x != 0);
  EXPECT_EQ(curve_edges, 8u);
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(b[5], -1);
  EXPECT_EQ(b[6], 1);
  EXPECT_EQ(count_nonzero(b), 2u);
  // a piece between two boundary vertices is not refined: 0->1 lies on the boundary
  std::istringstream is2("# swn polylines\n0 1\n");
  auto r2 = IO::conforming_cut(g, IO::read_curves(is2, "bd.txt", g));
  EXPECT_EQ(r2.refined_pieces, 0u);
  // a closed loop is never refined
  std::istringstream is3("# swn polylines\n5 6 10 5\n");
  auto r3 = IO::conforming_cut(g, IO::read_curves(is3, "loop.txt", g));
  EXPECT_EQ(r3.refined_pieces, 0u);
  EXPECT_EQ(r3.mesh.number_of_vertices(), 16u);
  // a piece along the mesh boundary then inside: 0->1 (boundary edge) ->5 (interior endpoint), n=2:
  // 4 sub-edges each; splits of the boundary edge add one face, the others two
  std::istringstream is5("# swn polylines\n0 1 5\n");
  auto r5 = IO::conforming_cut(g, IO::read_curves(is5, "bd2.txt", g));
  EXPECT_EQ(r5.refined_pieces, 1u);
  EXPECT_EQ(r5.refine_new_vertices, 6u);
  EXPECT_EQ(r5.refine_new_faces, 9u);
  EXPECT_TRUE(r5.mesh.is_valid(false));
  auto b5 = chain_boundary(r5.mesh, r5.chain);
  EXPECT_EQ(b5[0], -1);
  EXPECT_EQ(b5[5], 1);
  EXPECT_EQ(count_nonzero(b5), 2u);
  // two edges 5->6->7 with an interior start: n=2 -> 4 sub-edges each (6 new vertices)
  std::istringstream is4("# swn polylines\n5 6 7\n");
  auto r4 = IO::conforming_cut(g, IO::read_curves(is4, "two.txt", g));
  EXPECT_EQ(r4.refine_new_vertices, 6u);
}

TEST(ConformingCut, SmallCutOnGrid)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  // edges (authors' numbering): 0:(0,1) 1:(1,5) 2:(5,0); face 0 = (0,1,5)
  // a chord from vertex 0 to the midpoint of 1-5, then along edge 1-5 to vertex 5 (through the new point)
  std::istringstream is("#offset 0\nv 0\ne 1 0.5\nv 5\nv 1\nl 0 1 2\nl 3 2\n");
  IO::Curve_set cs = IO::read_curves(is, "cut.txt", g);
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, cs, o);
  EXPECT_TRUE(r.cut);
  EXPECT_EQ(r.cut_new_vertices, 1u);
  EXPECT_EQ(r.cut_new_faces, 2u);  // both faces of edge 1-5 split in two
  EXPECT_EQ(r.point_vertex[1], 16u);
  EXPECT_EQ(r.mesh.point(VI(16)), Point(1, 0.5, 0));
  EXPECT_TRUE(r.mesh.is_valid(false));
  // face 0 keeps its slot
  auto t0 = triple(r.mesh, FI(0));
  EXPECT_TRUE(std::find(t0.begin(), t0.end(), std::size_t(0)) != t0.end());
  // chain: 0->16 (+1), 16->5 (+1), 1->16->5 (+1 each): boundary -1 at 0 and 1, +2 at 5
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(b[0], -1);
  EXPECT_EQ(b[1], -1);
  EXPECT_EQ(b[5], 2);
  EXPECT_EQ(b[16], 0);
  auto hb = r.mesh.halfedge(VI(16), VI(5));
  ASSERT_TRUE(hb.is_valid());
  auto e = r.mesh.edge(hb);
  int along = r.chain[std::size_t(e)] * ((std::size_t(hb) % 2 == 0) ? 1 : -1);
  EXPECT_EQ(along, 2);
  // no degenerate triangle
  for(FI f : r.mesh.faces())
  {
    auto t = triple(r.mesh, f);
    EXPECT_FALSE(CGAL::collinear(r.mesh.point(VI(static_cast<Mesh::size_type>(t[0]))),
                                 r.mesh.point(VI(static_cast<Mesh::size_type>(t[1]))),
                                 r.mesh.point(VI(static_cast<Mesh::size_type>(t[2])))));
  }
  // total area unchanged
  auto area = [](const Mesh& m) {
    double a = 0;
    for(FI f : m.faces())
    {
      auto t = triple(m, f);
      a += std::sqrt(CGAL::squared_area(m.point(VI(static_cast<Mesh::size_type>(t[0]))),
                                        m.point(VI(static_cast<Mesh::size_type>(t[1]))),
                                        m.point(VI(static_cast<Mesh::size_type>(t[2])))));
    }
    return a;
  };
  EXPECT_NEAR(area(r.mesh), area(g), 1e-12);
}

TEST(ConformingCut, ManyPointsInOneFace)
{
  // points on all three sides of face 0 = (0,1,5) and a path through them: fan-free triangulation
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  std::istringstream is("#offset 0\ne 0 0.25\ne 0 0.75\ne 1 0.5\ne 2 0.3\ne 2 0.6\nl 0 2 3\nl 4 0\nl 1 2\n");
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, IO::read_curves(is, "many.txt", g), o);
  EXPECT_EQ(r.cut_new_vertices, 5u);
  EXPECT_TRUE(r.mesh.is_valid(false));
  // Euler: a disk keeps V - E + F = 1
  EXPECT_EQ(long(r.mesh.number_of_vertices()) - long(r.mesh.number_of_edges()) + long(r.mesh.number_of_faces()), 1);
  for(FI f : r.mesh.faces())
  {
    auto t = triple(r.mesh, f);
    EXPECT_FALSE(CGAL::collinear(r.mesh.point(VI(static_cast<Mesh::size_type>(t[0]))),
                                 r.mesh.point(VI(static_cast<Mesh::size_type>(t[1]))),
                                 r.mesh.point(VI(static_cast<Mesh::size_type>(t[2])))))
      << "face " << f;
  }
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(count_nonzero(b), 4u);
  // p0->p2 and p4->p1 cross inside face 0
  std::istringstream is2("#offset 0\ne 0 0.25\ne 0 0.75\ne 1 0.5\ne 2 0.3\ne 2 0.6\nl 0 2\n#\nl 4 1\n");
  try { IO::conforming_cut(g, IO::read_curves(is2, "cross.txt", g)); FAIL(); }
  catch(const IO::Input_error& e)
  {
    EXPECT_EQ(e.line, 9u);
    EXPECT_NE(std::string(e.what()).find("line 7"), std::string::npos);
  }
}

TEST(ConformingCut, DuplicatePointsAndDegenerateSegments)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  // points 1 and 2 are equal: one new vertex; segment 1->2 is skipped
  std::istringstream is("#offset 0\nv 0\ne 1 0.5\ne 1 0.5\nv 5\nl 0 1 2 3\n");
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, IO::read_curves(is, "dup.txt", g), o);
  EXPECT_EQ(r.cut_new_vertices, 1u);
  EXPECT_EQ(r.skipped_segments, 1u);
  EXPECT_EQ(r.point_vertex[1], r.point_vertex[2]);
}

// ------------------------------------------------------------------------------------------------ library conforming_cut()

namespace {

namespace SWN = CGAL::Surface_winding_numbers;
namespace PMP = CGAL::Polygon_mesh_processing;

// A closed curve around vertex 5 = (1, 1, 0) of grid4.off, crossing its six spokes at known parameters: the
// point on spoke k is at (1 - t[k]) * p5 + t[k] * p(ring[k]). The ring is counter-clockwise seen from +z (the
// side the faces face), so the inside of the curve, around vertex 5, is one higher than the outside.
const std::size_t ring[6] = {6, 10, 9, 4, 0, 1};
const double spoke_t[6] = {0.25, 0.5, 0.75, 0.375, 0.625, 0.5};

template <class TriangleMesh>
std::vector<PMP::Face_location<TriangleMesh, double> >
hexagon_around_vertex_5(const TriangleMesh& tm, const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& v)
{
  std::vector<PMP::Face_location<TriangleMesh, double> > curve;
  for(int k = 0; k <= 6; ++k)
  {
    auto h = halfedge(v[5], v[ring[k % 6]], tm).first;   // from vertex 5 to the ring
    // close the loop with the first point located from the other side of its edge
    curve.push_back(k < 6 ? PMP::locate_on_halfedge(h, spoke_t[k], tm)
                          : PMP::locate_on_halfedge(opposite(h, tm), 1 - spoke_t[0], tm));
  }
  return curve;
}

// the vertices of grid4.off by index: vertex i is at (i % 4, i / 4, 0)
template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> grid_vertices(const TriangleMesh& tm)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> v(num_vertices(tm));
  for(auto x : vertices(tm))
    v.at(std::size_t(get(CGAL::vertex_point, tm, x).x() + 4 * get(CGAL::vertex_point, tm, x).y())) = x;
  return v;
}

// the boundary of the chain (arrivals minus departures) is zero everywhere, and the chain has `edges` edges
template <class TriangleMesh, class ChainMap>
void expect_closed_chain(const TriangleMesh& tm, const ChainMap& chain, int edges)
{
  std::map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, int> boundary;
  int count = 0;
  for(auto e : CGAL::edges(tm))
  {
    const int c = get(chain, e);
    boundary[target(halfedge(e, tm), tm)] += c;
    boundary[source(halfedge(e, tm), tm)] -= c;
    count += (c != 0);
  }
  for(const auto& b : boundary) EXPECT_EQ(b.second, 0);
  EXPECT_EQ(count, edges);
}

} // namespace

TEST(LibraryConformingCut, LoopAcrossSpokesAtKnownParameters)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const std::vector<VI> v = grid_vertices(m);
  const Point p5 = m.point(v[5]);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  const std::vector<std::vector<PMP::Face_location<Mesh, double> > > curves{hexagon_around_vertex_5(m, v)};

  const SWN::Conforming_cut_result<Mesh> r = SWN::conforming_cut(m, curves, chain);
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.cut_vertices, 6u);
  EXPECT_EQ(r.cut_faces, 12u);   // each of the six triangles around vertex 5: a triangle inside, a quad outside in two
  EXPECT_EQ(r.segments, 6u);
  EXPECT_EQ(r.refined_pieces, 0u);   // a closed loop has no endpoint
  EXPECT_EQ(m.number_of_vertices(), 16u + 6u);
  EXPECT_EQ(m.number_of_faces(), 18u + 12u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  // the new vertices lie at the given points (exactly: the parameters are binary fractions), in curve order
  ASSERT_EQ(r.curve_vertices.size(), 1u);
  ASSERT_EQ(r.curve_vertices[0].size(), 7u);
  EXPECT_EQ(r.curve_vertices[0][6], r.curve_vertices[0][0]);
  for(int k = 0; k < 6; ++k)
  {
    EXPECT_EQ(std::size_t(r.curve_vertices[0][k]), 16u + k) << "new vertices are numbered in the order of the curve";
    const Point& q = m.point(v[ring[k]]);
    const double t = spoke_t[k];
    EXPECT_EQ(m.point(r.curve_vertices[0][k]), Point((1 - t) * p5.x() + t * q.x(), (1 - t) * p5.y() + t * q.y(), 0.));
  }
  // the chain runs once around the loop, from each point to the next
  expect_closed_chain(m, chain, 6);
  for(int k = 0; k < 6; ++k)
  {
    const auto h = m.halfedge(r.curve_vertices[0][k], r.curve_vertices[0][k + 1]);
    ASSERT_TRUE(h.is_valid());
    std::vector<Mesh::Halfedge_index> along{h};
    auto one = m.add_property_map<Mesh::Edge_index, int>("e:one", 0).first;
    SWN::add_halfedges_to_chain(m, along, one);
    EXPECT_EQ(chain[m.edge(h)], one[m.edge(h)]);
    m.remove_property_map(one);
  }
  // the winding numbers: the six triangles around vertex 5 are inside (1), everything else outside (0)
  auto labels = m.add_property_map<FI, int>("f:label", 0).first;
  SWN::Solve_report report;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, labels, SWN::parameters::report(std::ref(report)))) << report.error;
  double inside_area = 0;
  for(FI f : m.faces())
  {
    const auto t = triple(m, f);
    const bool around_5 = std::find(t.begin(), t.end(), std::size_t(5)) != t.end();
    EXPECT_EQ(labels[f], around_5 ? 1 : 0) << "face " << f;
    if(around_5)
      inside_area += std::sqrt(CGAL::squared_area(m.point(VI(Mesh::size_type(t[0]))), m.point(VI(Mesh::size_type(t[1]))),
                                                  m.point(VI(Mesh::size_type(t[2])))));
  }
  // triangle (p5, a, b) with a, b at t_a, t_b along two spokes of a half-unit triangle: area t_a * t_b / 2
  double expected_area = 0;
  for(int k = 0; k < 6; ++k) expected_area += spoke_t[k] * spoke_t[(k + 1) % 6] / 2;
  EXPECT_NEAR(inside_area, expected_area, 1e-14);
}

TEST(LibraryConformingCut, PolyhedronAndExistingChain)
{
  // the same loop on a Polyhedron_3 with maps outside the mesh; the chain already holds a curve along
  // spokes 5->6 and 5->4, which the cut splits: both halves keep its value
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::edge_descriptor edge_descriptor;
  Mesh sm;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", sm));
  Polyhedron p;
  CGAL::copy_face_graph(sm, p);
  const auto v = grid_vertices(p);
  std::unordered_map<edge_descriptor, int> chain_values;
  auto chain = boost::make_assoc_property_map(chain_values);
  std::vector<boost::graph_traits<Polyhedron>::halfedge_descriptor> before{halfedge(v[6], v[5], p).first,
                                                                         halfedge(v[5], v[4], p).first};
  SWN::add_halfedges_to_chain(p, before, chain);
  const std::vector<std::vector<PMP::Face_location<Polyhedron, double> > > curves{hexagon_around_vertex_5(p, v)};

  const auto r = SWN::conforming_cut(p, curves, chain, SWN::parameters::refine_short_pieces(false));
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.cut_vertices, 6u);
  EXPECT_EQ(r.cut_faces, 12u);
  EXPECT_EQ(p.size_of_vertices(), 22u);
  EXPECT_EQ(p.size_of_facets(), 30u);
  EXPECT_TRUE(p.is_valid() && p.is_pure_triangle());
  // the old curve 6 -> 5 -> 4 now runs 6 -> new -> 5 -> new -> 4; the loop adds 6 edges
  std::map<boost::graph_traits<Polyhedron>::vertex_descriptor, int> boundary;
  int edges_with_chain = 0;
  for(auto e : edges(p))
  {
    const int c = get(chain, e);
    boundary[target(halfedge(e, p), p)] += c;
    boundary[source(halfedge(e, p), p)] -= c;
    edges_with_chain += (c != 0);
  }
  EXPECT_EQ(edges_with_chain, 4 + 6);
  for(const auto& b : boundary)
    EXPECT_EQ(b.second, b.first == v[6] ? -1 : (b.first == v[4] ? 1 : 0));
  const auto on_old_curve = halfedge(r.curve_vertices[0][0], v[5], p);   // the point on spoke 5 -> 6, towards 5
  ASSERT_TRUE(on_old_curve.second);
  std::unordered_map<edge_descriptor, int> one_values;
  auto one = boost::make_assoc_property_map(one_values);
  std::vector<boost::graph_traits<Polyhedron>::halfedge_descriptor> along{on_old_curve.first};
  SWN::add_halfedges_to_chain(p, along, one);
  EXPECT_EQ(get(chain, edge(on_old_curve.first, p)), get(one, edge(on_old_curve.first, p)));
}

TEST(LibraryConformingCut, RefusedCurvesLeaveEverythingUnchanged)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const std::vector<VI> v = grid_vertices(m);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  chain[m.edge(m.halfedge(v[0], v[1]))] = 3;
  const Mesh before = m;
  auto unchanged = [&]() {
    EXPECT_EQ(m.number_of_vertices(), before.number_of_vertices());
    EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
    for(VI x : m.vertices()) EXPECT_EQ(m.point(x), before.point(x));
    int nonzero = 0;
    for(auto e : m.edges()) nonzero += (chain[e] != 0);
    EXPECT_EQ(nonzero, 1);
    EXPECT_EQ(chain[m.edge(m.halfedge(v[0], v[1]))], 3);
  };
  typedef PMP::Face_location<Mesh, double> Location;
  auto on = [&](std::size_t a, std::size_t b, double t) { return PMP::locate_on_halfedge(m.halfedge(v[a], v[b]), t, m); };
  auto at = [&](std::size_t a) { return PMP::locate_vertex<double>(v[a], m); };

  // in face (0, 1, 5): the midpoint of 0-1 to the midpoint of 1-5, then vertex 1 to the midpoint of 5-0: they cross
  std::vector<std::vector<Location> > crossing{{on(0, 1, 0.5), on(1, 5, 0.5)}, {at(1), on(5, 0, 0.5)}};
  auto r = SWN::conforming_cut(m, crossing, chain);
  EXPECT_FALSE(bool(r));
  EXPECT_EQ(r.error, r.CROSSING_SEGMENTS);
  EXPECT_EQ(r.curve, 1u);
  EXPECT_EQ(r.index, 0u);
  EXPECT_EQ(r.other_curve, 0u);
  EXPECT_EQ(r.other_index, 0u);
  unchanged();
  // a point strictly inside a face
  const FI f0 = *m.faces().begin();
  std::vector<std::vector<Location> > inside{{at(0), Location(f0, {0.2, 0.3, 0.5})}};
  r = SWN::conforming_cut(m, inside, chain);
  EXPECT_EQ(r.error, r.INVALID_LOCATION);
  EXPECT_EQ(r.index, 1u);
  unchanged();
  // two points on no common face (the second segment of the curve)
  std::vector<std::vector<Location> > apart{{on(0, 1, 0.5), at(5), at(15)}};
  r = SWN::conforming_cut(m, apart, chain);
  EXPECT_EQ(r.error, r.NO_COMMON_FACE);
  EXPECT_EQ(r.curve, 0u);
  EXPECT_EQ(r.index, 1u);
  unchanged();
  // an open curve ending inside: its single edge is refined into 8 (as the tool does by default)
  std::vector<std::vector<Location> > short_piece{{at(5), at(6)}};
  r = SWN::conforming_cut(m, short_piece, chain);
  ASSERT_TRUE(bool(r));
  EXPECT_EQ(r.cut_vertices, 0u);
  EXPECT_EQ(r.refined_pieces, 1u);
  EXPECT_EQ(r.refinement_vertices, 7u);
  EXPECT_EQ(r.refinement_faces, 14u);
}

// ------------------------------------------------------------------------------------------------ writers

namespace {
Mesh octahedron()
{
  Mesh m;
  std::istringstream is(octa_off());
  IO::read_mesh(is, "off", "octa", m);
  return m;
}
}

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
