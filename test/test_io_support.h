// Shared by the tests of the swn tool's file handling (test_io*.cpp): temporary directories, files,
// and small meshes written in every format (an octahedron with an unusual vertex and face order).

#ifndef SWN_TEST_IO_SUPPORT_H
#define SWN_TEST_IO_SUPPORT_H

#include "swn_io/read_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
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

namespace swn_test {


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

inline void write_file(const std::string& path, const std::string& content)
{
  std::ofstream os(path, std::ios::binary);
  os << content;
}

inline std::string read_file(const std::string& path)
{
  std::ifstream is(path, std::ios::binary);
  std::stringstream s;
  s << is.rdbuf();
  return s.str();
}

inline std::array<std::size_t, 3> triple(const Mesh& m, FI f)
{
  std::array<std::size_t, 3> r;
  std::size_t k = 0;
  for(VI v : CGAL::vertices_around_face(m.halfedge(f), m)) r[k++] = std::size_t(v);
  return r;
}

// `mesh` as OBJ text with its faces shuffled and each rotated (random with `seed`); `faces` gets them
// in the order written
inline std::string shuffled_obj(const Mesh& mesh, unsigned seed, std::vector<std::array<std::size_t, 3> >& faces)
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
inline std::vector<long long> chain_boundary(const Mesh& m, const std::vector<int>& chain)
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

inline std::size_t count_nonzero(const std::vector<long long>& v)
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

inline std::string fmt17(double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

inline std::string octa_off()
{
  std::string s = "OFF\n# octahedron\n6 8 0\n";
  for(auto& p : octa_points) s += fmt17(p[0]) + " " + fmt17(p[1]) + " " + fmt17(p[2]) + "\n";
  for(auto& f : octa_faces) s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
  return s;
}

inline std::string octa_obj()
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

inline std::string octa_ply_ascii()
{
  std::string s = "ply\nformat ascii 1.0\ncomment test\nelement vertex 6\nproperty double x\nproperty double y\n"
                  "property double z\nproperty uchar red\nelement face 8\nproperty list uchar int vertex_indices\n"
                  "property int extra\nelement edge 0\nproperty int vertex1\nend_header\n";
  for(auto& p : octa_points) s += fmt17(p[0]) + " " + fmt17(p[1]) + " " + fmt17(p[2]) + " 7\n";
  for(auto& f : octa_faces) s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " 42\n";
  return s;
}

template <class T>
inline void put_be(std::string& s, T v)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  for(std::size_t i = 0; i < sizeof(T); ++i) s += static_cast<char>(b[sizeof(T) - 1 - i]);  // host is LE
}

inline std::string octa_ply_binary_be()
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

inline std::string octa_stl_ascii()
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

inline std::string octa_stl_binary()
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

inline void expect_octa_order(const Mesh& m, bool exact_points = true)
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
inline void expect_stl_faces(const Mesh& m, bool as_float)
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


inline Mesh octahedron()
{
  Mesh m;
  std::istringstream is(octa_off());
  IO::read_mesh(is, "off", "octa", m);
  return m;
}

} // namespace swn_test

using namespace swn_test;

#endif // SWN_TEST_IO_SUPPORT_H
