#!/usr/bin/env bash
# Builds the downstream project of test/cmake_consumer both ways: add_subdirectory and
# find_package after cmake --install (with GLPK), add_subdirectory without GLPK (an optional backend:
# the default residual solver is LEMON's). Usage: cmake_consumer.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1; work=$2
rm -rf "$work"; mkdir -p "$work"
cmake -S "$src" -B "$work/pkg" -DCMAKE_BUILD_TYPE=Release -DCGAL_SWN_BUILD_TESTS=OFF -DCGAL_SWN_BUILD_EXAMPLES=OFF \
      -DCMAKE_INSTALL_PREFIX="$work/prefix" >/dev/null
cmake --install "$work/pkg" >/dev/null
test -f "$work/prefix/include/CGAL/surface_winding_numbers.h"
test -f "$work/prefix/include/CGAL/Surface_winding_numbers/conforming_cut.h"
# the swn tool's file handling (tools/swn/swn_io) is not part of the installed package
if [ -e "$work/prefix/include/CGAL/Surface_winding_numbers/IO" ] || find "$work/prefix" -name 'swn_io' | grep -q .; then
  echo "the tool's IO code was installed"; exit 1
fi
cmake -S "$src/test/cmake_consumer" -B "$work/installed" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/installed" >/dev/null
"$work/installed/consumer"
cmake -S "$src/test/cmake_consumer" -B "$work/subdir" -DCMAKE_BUILD_TYPE=Release -DSWN_SOURCE_DIR="$src" \
      -DCGAL_SWN_WITH_GLPK=OFF >/dev/null
if grep -q 'CGAL_USE_GLPK' "$work/subdir/CMakeFiles/consumer.dir/flags.make"; then echo "GLPK still used"; exit 1; fi
cmake --build "$work/subdir" >/dev/null
# EXCLUDE_FROM_ALL: only the consumer was built, no test or example of the package
if find "$work/subdir/swn" -type f -perm -u+x -name 'test_*' | grep -q .; then echo "package targets were built"; exit 1; fi
"$work/subdir/consumer"
echo "consumer OK"
