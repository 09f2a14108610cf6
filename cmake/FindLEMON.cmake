# FindLEMON: locates LEMON (Library for Efficient Modeling and Optimization in Networks) and
# defines the imported target LEMON::LEMON (headers <lemon/...> and the library).
# Debian's liblemon-dev installs liblemon.{so,a}; some distributions name the library `emon`
# (lib + emon). The network flow classes used by the package are header-only, so a missing
# library is tolerated (LEMON_LIBRARY is then empty and only the headers are used).
find_path(LEMON_INCLUDE_DIR NAMES lemon/cost_scaling.h lemon/network_simplex.h)
find_library(LEMON_LIBRARY NAMES lemon emon)
if(LEMON_INCLUDE_DIR AND EXISTS "${LEMON_INCLUDE_DIR}/lemon/config.h")
  file(STRINGS "${LEMON_INCLUDE_DIR}/lemon/config.h" _lemon_version_line REGEX "^#define LEMON_VERSION \"[^\"]*\"")
  string(REGEX REPLACE "^#define LEMON_VERSION \"([^\"]*)\".*" "\\1" LEMON_VERSION "${_lemon_version_line}")
  unset(_lemon_version_line)
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LEMON REQUIRED_VARS LEMON_INCLUDE_DIR VERSION_VAR LEMON_VERSION)
if(LEMON_FOUND AND NOT TARGET LEMON::LEMON)
  if(LEMON_LIBRARY)
    add_library(LEMON::LEMON UNKNOWN IMPORTED)
    set_target_properties(LEMON::LEMON PROPERTIES IMPORTED_LOCATION "${LEMON_LIBRARY}")
  else()
    add_library(LEMON::LEMON INTERFACE IMPORTED)
  endif()
  set_target_properties(LEMON::LEMON PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${LEMON_INCLUDE_DIR}")
endif()
mark_as_advanced(LEMON_INCLUDE_DIR LEMON_LIBRARY)
