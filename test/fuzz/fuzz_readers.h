// The input the fuzzers feed to the swn tool's readers (test/fuzz): bytes read as a mesh in one format
// (OFF, OBJ, PLY, STL; an OBJ's `l` records as its curve) or as a curve file on a fixed mesh, then cut
// so that the curve lies on edges, as the tool does before solving. Every outcome but "read" or
// "Input_error" is a defect: another exception, a crash, a hang, a sanitizer report.

#ifndef SWN_FUZZ_READERS_H
#define SWN_FUZZ_READERS_H

#include "swn_io/conforming_cut.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace swn_fuzz {

namespace SIO = CGAL::Surface_winding_numbers::IO;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

// what the readers can be asked to read: the four mesh formats, and curve files
inline const std::vector<std::string>& formats()
{
  static const std::vector<std::string> f = {"obj", "off", "ply", "stl", "curve"};
  return f;
}

// the format of a corpus file, from its extension (.txt: a curve file); "" if none applies
inline std::string format_of(const std::string& filename)
{
  const std::string ext = SIO::mesh_file_format(filename);
  if(ext == "txt") return "curve";
  for(const std::string& f : formats())
    if(f == ext) return f;
  return std::string();
}

enum class Outcome { READ, INPUT_ERROR };

// Reads `data` in `format`; curve files refer to `curve_mesh`. Returns READ or INPUT_ERROR; any other
// exception passes to the caller (a defect).
inline Outcome read_input(const std::string& data, const std::string& format, const Mesh& curve_mesh)
{
  try
  {
    std::istringstream is(data, std::ios::in | std::ios::binary);
    std::vector<SIO::Curve_set> curves;
    if(format == "curve")
    {
      curves.push_back(SIO::read_curves(is, "fuzz.txt", curve_mesh));
      SIO::conforming_cut(curve_mesh, curves);
      return Outcome::READ;
    }
    Mesh mesh;
    const SIO::Mesh_read_info info = SIO::read_mesh(is, format, "fuzz." + format, mesh);
    if(SIO::has_curve_records(info))
    {
      curves.push_back(SIO::curve_set_from_obj(info, mesh));
      SIO::conforming_cut(mesh, curves);
    }
    return Outcome::READ;
  }
  catch(const SIO::Input_error&)
  {
    return Outcome::INPUT_ERROR;
  }
}

// the fixed mesh of curve files: the 4 x 4 grid of test/data/grid4.off (the malformed corpus's too)
inline Mesh grid_mesh(const std::string& path)
{
  Mesh m;
  SIO::read_mesh(path, m);
  return m;
}

} // namespace swn_fuzz

#endif // SWN_FUZZ_READERS_H
