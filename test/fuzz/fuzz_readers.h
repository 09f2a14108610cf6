// The input the fuzzers feed to the swn tool's readers (test/fuzz): bytes read as a mesh in one format
// (OFF, OBJ, PLY, STL; an OBJ's `l` records as its curve) or as a curve file on a fixed mesh, then cut
// so that the curve lies on edges, as the tool does before solving; or read as curves off the mesh (OBJ
// polylines, an SVG drawing stamped along -z) and put on a fixed unit grid by the library; or read by
// the soup route (an OBJ file with its `l`/`c` curves, solved as a polygon soup when it is not an oriented
// 2-manifold triangle mesh); or read as a mesh onto which a fixed stroke and a fixed drawing are put
// (meshes of any size). Every outcome but "read" or "Input_error" is a defect: another exception, a
// crash, a hang, a sanitizer report.

#ifndef SWN_FUZZ_READERS_H
#define SWN_FUZZ_READERS_H

// The readers and the library are compiled once, in fuzz_readers.cpp (with the fuzzers' coverage
// instrumentation in the libFuzzer build); this header is all a fuzzer's entry point needs.

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <vector>

namespace swn_fuzz {

// what the readers can be asked to read: the four mesh formats, curve files, curves off the mesh (OBJ
// polylines, SVG drawings), the soup route, meshes with curves off them
inline const std::vector<std::string>& formats()
{
  static const std::vector<std::string> f = {"obj", "off", "ply", "stl", "curve", "polylines", "svg", "soup", "offmesh"};
  return f;
}

// the file name ending of a format: curve files are .txt; polylines, soup and offmesh are OBJ files
// named X.polylines.obj, X.soup.obj, X.offmesh.obj
inline std::string extension_of(const std::string& format)
{
  if(format == "curve") return "txt";
  if(format == "polylines" || format == "soup" || format == "offmesh") return format + ".obj";
  return format;
}

// the format of a corpus file, from its name's ending; "" if none applies
inline std::string format_of(const std::string& filename)
{
  auto ends_with = [&](const std::string& e) {
    return filename.size() > e.size() + 1 && filename.compare(filename.size() - e.size() - 1, std::string::npos, "." + e) == 0;
  };
  for(const char* f : {"polylines", "soup", "offmesh"})
    if(ends_with(extension_of(f))) return f;
  const std::size_t dot = filename.find_last_of("./");
  std::string ext = dot == std::string::npos || filename[dot] != '.' ? std::string() : filename.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext == "txt") return "curve";
  for(const std::string& f : formats())
    if(f == ext) return f;
  return std::string();
}

enum class Outcome { READ, INPUT_ERROR };

// the fixed meshes: curve files refer to the 4 x 4 grid of test/data/grid4.off (the malformed corpus's
// too); curves off the mesh go onto a 10 x 10 grid of the unit square (the reproducers' grid10.obj)
struct Fixed_meshes;

// the fixed meshes, the grid read from `grid_path`
std::shared_ptr<const Fixed_meshes> fixed_meshes(const std::string& grid_path);

// Reads `data` in `format`; curve files refer to `meshes`' grid, curves off the mesh go onto its unit
// grid. Returns READ or INPUT_ERROR; any other exception passes to the caller (a defect).
Outcome read_input(const std::string& data, const std::string& format, const Fixed_meshes& meshes);

} // namespace swn_fuzz

#endif // SWN_FUZZ_READERS_H
