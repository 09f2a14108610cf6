// Hostile inputs for the swn tool's readers (issue 33): huge `#offset` values, header counts that no
// data backs, files that are not regular files, curves that ask for unbounded work, zero-area faces and
// meshes in extreme units. Each case fails fast with one `FILE:LINE: reason`, or is read as its unit-size
// copy would be.

#include "swn_io/atomic_output_dir.h"
#include "swn_io/errors.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include "swn_io/soup_curves.h"

#include "test_io_support.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

namespace {

// runs `read`, which must throw an Input_error at `line` whose reason contains every one of `parts`
void expect_input_error(const std::function<void()>& read, std::size_t line, std::initializer_list<std::string> parts)
{
  try
  {
    read();
    ADD_FAILURE() << "no Input_error";
  }
  catch(const IO::Input_error& e)
  {
    EXPECT_EQ(e.line, line) << e.what();
    for(const std::string& p : parts) EXPECT_NE(e.reason.find(p), std::string::npos) << "'" << p << "' not in: " << e.what();
  }
}

Mesh read_text(const std::string& text, const std::string& format)
{
  std::istringstream is(text);
  Mesh m;
  IO::read_mesh(is, format, "mem." + format, m);
  return m;
}

IO::Curve_set read_curve_text(const std::string& text, const Mesh& m)
{
  std::istringstream is(text);
  return IO::read_curves(is, "c.txt", m);
}

// the octahedron's OBJ with every coordinate multiplied by `scale`
std::string scaled_octa_obj(double scale)
{
  std::string s;
  for(auto& p : octa_points) s += "v " + fmt17(p[0] * scale) + " " + fmt17(p[1] * scale) + " " + fmt17(p[2] * scale) + "\n";
  for(auto& f : octa_faces)
    s += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
  return s;
}

const std::string llong_max = std::to_string(std::numeric_limits<long long>::max());
const std::string llong_min = std::to_string(std::numeric_limits<long long>::min());

} // namespace

// 1. Offsets whose sum with an index overflows are out of range, and the message quotes the index and the
// offset as written, never a wrapped sum.
TEST(HostileInput, HugeOffsetsAreOutOfRangeWithoutOverflow)
{
  const std::string obj = scaled_octa_obj(1.);   // 14 lines
  expect_input_error([&] { read_text(obj + "#offset " + llong_max + "\nl 1 2\n", "obj"); }, 16,
                     {"index 1 in 'l' record is out of range (offset " + llong_max + ")"});
  expect_input_error([&] { read_text(obj + "#offset " + llong_min + "\nl 1 2\n", "obj"); }, 16,
                     {"index 1 in 'l' record is out of range (offset " + llong_min + ")"});
  const Mesh m = octahedron();
  expect_input_error([&] { read_curve_text("#offset " + llong_min + "\nv -1\n", m); }, 2,
                     {"vertex index -1 is out of range (offset " + llong_min + ")"});
  expect_input_error([&] { read_curve_text("#offset " + llong_max + "\nv 1\n", m); }, 2,
                     {"vertex index 1 is out of range (offset " + llong_max + ")"});
  expect_input_error([&] { read_curve_text("v 1\nv 2\n#offset " + llong_max + "\nl 1 2\n", m); }, 4,
                     {"node index 1 is out of range (offset " + llong_max + ")"});
  expect_input_error([&] { read_curve_text("#offset " + llong_max + "\ne 5 0.5\n", m); }, 2, {"edge index 5"});
}

// 2. PLY counts are checked against the size of the data before anything is read: an element without
// properties (nothing bounds its count) and counts no data can hold fail at once, on their header line.
TEST(HostileInput, PlyCountsMustFitTheData)
{
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string tail = "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(read_text(head + tail, "ply").number_of_faces(), 1u);
  expect_input_error([&] { read_text(head + "element junk " + llong_max + "\n" + tail, "ply"); }, 7,
                     {"element 'junk' declares " + llong_max + " records but no property"});
  expect_input_error([&] { read_text(head + "element junk 1000000000000\nproperty int a\n" + tail, "ply"); }, 7,
                     {"element 'junk' declares 1000000000000 records, more than the"});
  std::string big = head;
  big.replace(big.find("vertex 3"), 8, "vertex 4000000000");
  expect_input_error([&] { read_text(big + tail, "ply"); }, 3, {"element 'vertex' declares 4000000000 records"});
  // binary: 4e9 vertices of 12 bytes announced, 36 bytes given
  std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
  bin += std::string(36, '\0');
  expect_input_error([&] { read_text(bin, "ply"); }, 3, {"element 'vertex' declares 4000000000 records, more than the 36 bytes"});
}

// 3. Devices, FIFOs and sockets are refused before they are opened (no endless read, no blocking open).
TEST(HostileInput, OnlyRegularFilesAreRead)
{
  TempDir d;
  fs::create_symlink("/dev/zero", d / "zero.obj");
  ASSERT_EQ(::mkfifo((d / "fifo.obj").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((d / "fifo.txt").c_str(), 0600), 0);
  Mesh m;
  expect_input_error([&] { IO::read_mesh(d / "zero.obj", m); }, 0, {"is not a regular file (a device)", "a mesh file"});
  expect_input_error([&] { IO::read_mesh("/dev/zero", m); }, 0, {"is not a regular file (a device)"});
  expect_input_error([&] { IO::read_mesh(d / "fifo.obj", m); }, 0, {"is not a regular file (a FIFO)"});
  const Mesh octa = octahedron();
  expect_input_error([&] { IO::read_curve_file(d / "fifo.txt", octa); }, 0, {"is not a regular file (a FIFO)", "a curve file"});
  expect_input_error([&] { IO::read_curve_file("/dev/zero", octa); }, 0, {"is not a regular file (a device)"});
  write_file(d / "o.obj", octa_obj());
  fs::create_symlink(d / "o.obj", d / "link.obj");   // a link to a regular file is read
  EXPECT_EQ(IO::read_mesh(d / "link.obj", m).number_of_faces, 8u);
}

// 4. A line `h A B 1000` is a thousand segments: the curve is refused on the line where the total passes
// 10^6 + 2 x edges, before the work (and the output) grow with it.
TEST(HostileInput, CurveMassIsBounded)
{
  const Mesh m = octahedron();   // 12 edges: at most 1,000,024 segments
  ASSERT_EQ(m.number_of_edges(), 12u);
  std::string text = "# swn halfedges\n";
  for(int k = 0; k < 500; ++k) text += "h 0 1 1000\nh 1 0 1000\n";
  text += "h 0 1 24\n";
  EXPECT_EQ(read_curve_text(text, m).segments.size(), 1000024u);   // exactly at the limit: read
  expect_input_error([&] { read_curve_text(text + "h 1 0\n", m); }, 1003, {"more than 1000024 segments", "12 mesh edges"});
}

// 6. Zero-area faces are refused by the reader with their line (the library would refuse them later
// without one); the test is the library's, on the mesh brought to a unit box, so that meshes in extreme
// units are read as their unit-size copies and slivers are judged by their shape.
TEST(HostileInput, ZeroAreaFacesAndExtremeUnits)
{
  expect_input_error([] { read_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 2 3 4\nf 1 3 2\n", "obj"); }, 7,
                     {"face 2 has zero area (degenerate triangle): its vertices 0, 2, 1 are collinear or coincide"});
  expect_input_error([] { read_text("OFF\n4 2 0\n0 0 0\n1 0 0\n1 0 0\n0 1 0\n3 0 1 3\n3 1 2 3\n", "off"); }, 8,
                     {"face 1 has zero area"});
  const Mesh unit = read_text(scaled_octa_obj(1.), "obj");
  for(double scale : {1e160, 1e-160, 1e300, 1e-300})
  {
    const Mesh m = read_text(scaled_octa_obj(scale), "obj");
    ASSERT_EQ(m.number_of_faces(), unit.number_of_faces());
    for(FI f : m.faces()) EXPECT_EQ(triple(m, f), triple(unit, f)) << scale;
  }
  // a sliver is a face, a needle of width 1e-20 relative to the box is not, at every scale
  for(double scale : {1., 1e150, 1e-150})
  {
    auto sliver = [&](double h) {
      return "v 0 0 0\nv " + fmt17(scale) + " 0 0\nv " + fmt17(scale / 2) + " " + fmt17(h * scale) + " 0\nf 1 2 3\n";
    };
    EXPECT_EQ(read_text(sliver(1e-6), "obj").number_of_faces(), 1u) << scale;
    expect_input_error([&] { read_text(sliver(1e-20), "obj"); }, 4, {"face 0 has zero area"});
  }
}

// Polygon soups (the tool's soup route): every bad record is named with the file and line that hold it
// (issue 42, item 6; the files are reproducers of messages that had neither), and the faces of a `c`
// record are numbered as in the file.
TEST(HostileInput, SoupMessagesNameTheRecordsFileAndLine)
{
  const std::string dir = tdata + "soup_messages/";
  Mesh m;
  IO::Triangle_soup soup;
  IO::Mesh_read_info info;
  // a zero-area triangle among polygons (it was a warning, then the library's message without a line)
  expect_input_error([&] { IO::read_mesh_or_soup(dir + "zero_area_triangle.obj", m, soup, info); }, 7,
                     {"face 0 has zero area (degenerate triangle): its vertices 0, 1, 2 are collinear"});
  // a quad with three collinear corners is refused only if the library's triangulation of it (along the
  // shorter diagonal) has a flat triangle
  auto with_apex = [](const std::string& y) { return "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 1 " + y + " 0\nv 1 -1 0\nf 1 2 3 4\nf 1 5 3\n"; };
  const fs::path quad_file = fs::temp_directory_path() / "swn_soup_quad_area.obj";
  std::ofstream(quad_file) << with_apex("1");
  EXPECT_NE(IO::read_mesh_or_soup(quad_file.string(), m, soup, info), "");   // read, as a soup
  std::ofstream(quad_file) << with_apex("5");
  expect_input_error([&] { IO::read_mesh_or_soup(quad_file.string(), m, soup, info); }, 6,
                     {"face 0 has zero area (degenerate polygon)"});
  fs::remove(quad_file);

  ASSERT_NE(IO::read_mesh_or_soup(dir + "grid10q.obj", m, soup, info), "");
  // `c 1 50`: faces 1 and 50 of the file (0 and 49 inside) are not adjacent; the curve file is blamed
  try
  {
    IO::read_curve_file(dir + "dual_chain_nonadjacent.txt", soup);
    ADD_FAILURE() << "no Input_error";
  }
  catch(const IO::Input_error& e)
  {
    EXPECT_EQ(e.file, dir + "dual_chain_nonadjacent.txt");
    EXPECT_EQ(e.line, 1u);
    EXPECT_NE(e.reason.find("the faces 1 and 50 of this dual chain record (numbered as in the file) share no edge"),
              std::string::npos) << e.what();
  }
  // with `#offset 0` the same record names faces 0 and 49
  const fs::path offset_file = fs::temp_directory_path() / "swn_soup_offset0.txt";
  std::ofstream(offset_file) << "#offset 0\nc 0 49\n";
  expect_input_error([&] { IO::read_curve_file(offset_file.string(), soup); }, 2, {"the faces 0 and 49 of this"});
  fs::remove(offset_file);
  // the polyline 0 -> 1 runs along the border: refused at its line in the curve file; there and back is not
  const std::vector<IO::Curve_set> border{IO::read_curve_file(dir + "curve_on_border.txt", soup)};
  expect_input_error([&] { IO::soup_curve(border, soup); }, 2, {"from vertex 0 to vertex 1, on the border of the mesh"});
  std::vector<IO::Curve_set> cancelled = border;
  cancelled.push_back(border[0]);
  std::swap(cancelled[1].segments[0].a, cancelled[1].segments[0].b);
  EXPECT_EQ(IO::soup_curve(cancelled, soup).edges.size(), 2u);
}

// 5. A signal ends the process without the destructor of Atomic_output_dir: the handler installed by
// remove_temporaries_on_signals() removes the temporaries and the directories created, and the process
// still ends by the signal. A child process writes two temporaries in a new directory two levels deep,
// tells the parent through a pipe and waits; the parent signals it.
TEST(HostileInput, SignalsLeaveNoTemporaries)
{
  for(int sig : {SIGTERM, SIGINT, SIGHUP})
  {
    TempDir d;
    const std::string target = d / "new/out";
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    std::fflush(nullptr);   // nothing buffered is written twice
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if(child == 0)
    {
      ::close(ready[0]);
      try
      {
        IO::Atomic_output_dir::remove_temporaries_on_signals();
        IO::Atomic_output_dir out(target);
        out.write("a.txt", [](std::ostream& os) { os << "a\n"; });
        out.write("b.txt", [](std::ostream& os) { os << std::string(1 << 16, 'b'); });
        if(::write(ready[1], "r", 1) != 1) ::_exit(3);
        for(;;) ::pause();
      }
      catch(...) {}
      ::_exit(4);
    }
    ::close(ready[1]);
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1) << "the child failed before writing";
    ::close(ready[0]);
    std::size_t temporaries = 0;
    for(const auto& e : fs::directory_iterator(target)) temporaries += e.path().filename().string().find(".swn-tmp-") != std::string::npos;
    EXPECT_EQ(temporaries, 2u);   // the state the signal interrupts
    ASSERT_EQ(::kill(child, sig), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "status " << status;
    EXPECT_FALSE(fs::exists(d / "new")) << "left behind after signal " << sig;
    EXPECT_TRUE(fs::is_empty(d.path()));
  }
}
