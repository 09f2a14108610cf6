// libFuzzer target of one reader of the swn tool (built once per format by the CMake option
// CGAL_SWN_BUILD_FUZZERS, with clang: swn_fuzz_obj, swn_fuzz_off, swn_fuzz_ply, swn_fuzz_stl,
// swn_fuzz_curve, swn_fuzz_polylines, swn_fuzz_svg, swn_fuzz_soup, swn_fuzz_offmesh). SWN_FUZZ_FORMAT names the format; SWN_FUZZ_GRID the mesh of curve files.
// Run: swn_fuzz_obj -max_total_time=60 CORPUS_DIR test/data/fuzz (see scripts/sanitize).

#include "fuzz_readers.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const auto meshes = swn_fuzz::fixed_meshes(SWN_FUZZ_GRID);
  // anything but a read or an Input_error escapes: libFuzzer reports the uncaught exception as a crash
  swn_fuzz::read_input(std::string(reinterpret_cast<const char*>(data), size), SWN_FUZZ_FORMAT, *meshes);
  return 0;
}
