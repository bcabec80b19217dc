# offsetgen_generate() checks SURFACE at configure time against the catalog. Before offsetgen is
# built (add_subdirectory) that list is read from the source tree (cmake/Install.cmake) and recorded
# in the package; it must be exactly what `offsetgen list --json` prints.
#   cmake -DOFFSETGEN=<executable> -DPACKAGE_DIR=<dir with offsetgenConfig.cmake> -P check_catalog.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND "${OFFSETGEN}" list --json RESULT_VARIABLE rc OUTPUT_VARIABLE json)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "offsetgen list --json failed (${rc})")
endif()
string(JSON count LENGTH "${json}")
math(EXPR last "${count} - 1")
set(from_tool "")
foreach(i RANGE ${last})
  string(JSON name GET "${json}" ${i} name)
  list(APPEND from_tool "${name}")
endforeach()
file(STRINGS "${PACKAGE_DIR}/offsetgenConfig.cmake" line REGEX "OFFSETGEN_SURFACES")
if(NOT line MATCHES "OFFSETGEN_SURFACES \"([^\"]*)\"")
  message(FATAL_ERROR "offsetgenConfig.cmake records no OFFSETGEN_SURFACES")
endif()
if(NOT CMAKE_MATCH_1 STREQUAL "${from_tool}")
  message(FATAL_ERROR "the package's catalog '${CMAKE_MATCH_1}' differs from `offsetgen list`: '${from_tool}'")
endif()
message(STATUS "catalog of the package = offsetgen list: ${from_tool}")
