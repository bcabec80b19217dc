# Installation, the CMake package (find_package(offsetgen), offsetgen_generate()) and the build-tree
# export. Included by the top-level CMakeLists.txt after src/.
#
# Installed layout (the executable finds its templates at <exe>/../share/offsetgen/templates, and
# `offsetgen check` its plot script at <exe>/../share/offsetgen/tools, so bin/ and share/ are fixed):
#   bin/offsetgen
#   bin/offsetgen-mesh (where built with OpenVDB: `offsetgen mesh` execs it from offsetgen's directory)
#   share/offsetgen/templates/<lang>/*.in
#   share/offsetgen/tools/plot_convergence.py
#   <OFFSETGEN_INSTALL_CMAKEDIR>/offsetgenConfig.cmake, offsetgenConfigVersion.cmake,
#       offsetgenTargets*.cmake, offsetgenGenerate.cmake, offsetgenGlslString.cmake
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

option(OFFSETGEN_INSTALL "Generate offsetgen's install rules" ${PROJECT_IS_TOP_LEVEL})
set(OFFSETGEN_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/offsetgen" CACHE STRING
    "Where to install offsetgen's CMake package, relative to the prefix")
mark_as_advanced(OFFSETGEN_INSTALL_CMAKEDIR)

# The offset methods (the registry in src/offset/method_registry.cpp: one *_method.cpp each) with
# their highest order and whether they build even orders only, as "name:max_order:even" entries, so
# offsetgen_generate() can check METHOD and ORDERS and name the files at configure time.
set(OFFSETGEN_METHODS "")
file(GLOB _offsetgen_method_files "${PROJECT_SOURCE_DIR}/src/offset/*_method.cpp")
foreach(_file IN LISTS _offsetgen_method_files)
  file(STRINGS "${_file}" _lines REGEX "kMethod(Name|MaxOrder|EvenOrdersOnly) = ")
  if(_lines MATCHES "kMethodName = \"([a-z]+)\"" )
    set(_name ${CMAKE_MATCH_1})
    string(REGEX MATCH "kMethodMaxOrder = ([0-9]+)" _ "${_lines}")
    set(_max ${CMAKE_MATCH_1})
    string(REGEX MATCH "kMethodEvenOrdersOnly = (true|false)" _ "${_lines}")
    list(APPEND OFFSETGEN_METHODS "${_name}:${_max}:${CMAKE_MATCH_1}")
  endif()
endforeach()
list(SORT OFFSETGEN_METHODS)
if(NOT OFFSETGEN_METHODS)
  message(FATAL_ERROR "offsetgen: no offset method found under src/offset/*_method.cpp")
endif()
file(STRINGS "${PROJECT_SOURCE_DIR}/src/offset/method.h" _lines REGEX "kDefaultMethod = ")
string(REGEX MATCH "kDefaultMethod = \"([a-z]+)\"" _ "${_lines}")
set(OFFSETGEN_DEFAULT_METHOD ${CMAKE_MATCH_1})
unset(_offsetgen_method_files)
unset(_lines)

# The output languages (the backends of src/emit/backends/, registered in
# src/emit/backend_registry.cpp) as "name:extension" entries in registry order, so
# offsetgen_generate() can check LANG and name the files at configure time.
set(OFFSETGEN_LANGUAGES "")
# The list may span lines (clang-format wraps it): read up to its closing brace.
file(READ "${PROJECT_SOURCE_DIR}/src/emit/backend_registry.cpp" _lines)
string(REGEX MATCH "static const std::vector<const Backend\\*> all = {[^}]*}" _lines "${_lines}")
string(REGEX MATCHALL "&([a-z]+)_backend\\(\\)" _names "${_lines}")
foreach(_name IN LISTS _names)
  string(REGEX REPLACE "&([a-z]+)_backend.*" "\\1" _name "${_name}")
  file(STRINGS "${PROJECT_SOURCE_DIR}/src/emit/backends/${_name}.cpp" _ext REGEX "extension\\(\\) const override")
  string(REGEX MATCH "return \"([a-z]+)\"" _ "${_ext}")
  list(APPEND OFFSETGEN_LANGUAGES "${_name}:${CMAKE_MATCH_1}")
endforeach()
if(NOT OFFSETGEN_LANGUAGES)
  message(FATAL_ERROR "offsetgen: no backend found in src/emit/backend_registry.cpp")
endif()
unset(_names)
unset(_ext)

# The catalog's surface names, so offsetgen_generate() can reject an unknown SURFACE at configure time
# before offsetgen is built (tests/cmake_consumer checks that this list is `offsetgen list`'s).
file(STRINGS "${PROJECT_SOURCE_DIR}/src/surfaces/catalog.cpp" _offsetgen_catalog_lines
     REGEX "^[ \t]*\{\"[A-Za-z0-9_]+\", \"")
set(OFFSETGEN_SURFACES "")
foreach(_line IN LISTS _offsetgen_catalog_lines)
  if(_line MATCHES "^[ \t]*\{\"([A-Za-z0-9_]+)\"")
    list(APPEND OFFSETGEN_SURFACES "${CMAKE_MATCH_1}")
  endif()
endforeach()
unset(_offsetgen_catalog_lines)
unset(_line)

# --- The same names inside this build (add_subdirectory / FetchContent users, and our tests) -------
add_executable(offsetgen::offsetgen ALIAS offsetgen)
file(GLOB_RECURSE _offsetgen_templates "${PROJECT_SOURCE_DIR}/templates/*.in")
set_property(GLOBAL PROPERTY OFFSETGEN_METHODS "${OFFSETGEN_METHODS}")
set_property(GLOBAL PROPERTY OFFSETGEN_LANGUAGES "${OFFSETGEN_LANGUAGES}")
set_property(GLOBAL PROPERTY OFFSETGEN_DEFAULT_METHOD "${OFFSETGEN_DEFAULT_METHOD}")
set_property(GLOBAL PROPERTY OFFSETGEN_SURFACES "${OFFSETGEN_SURFACES}")
set_property(GLOBAL PROPERTY OFFSETGEN_TEMPLATE_FILES ${_offsetgen_templates})
unset(_offsetgen_templates)
include("${CMAKE_CURRENT_LIST_DIR}/offsetgenGenerate.cmake")

# --- Build-tree package: find_package(offsetgen) with offsetgen_DIR=<this build dir> ------------
export(TARGETS offsetgen NAMESPACE offsetgen:: FILE "${PROJECT_BINARY_DIR}/offsetgenTargets.cmake")
set(OFFSETGEN_CONFIG_TEMPLATE_DIR "${PROJECT_SOURCE_DIR}/templates")
set(OFFSETGEN_CONFIG_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/offsetgenConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/offsetgenConfig.cmake"
  INSTALL_DESTINATION "${PROJECT_BINARY_DIR}"
  INSTALL_PREFIX "${PROJECT_BINARY_DIR}"
  PATH_VARS OFFSETGEN_CONFIG_TEMPLATE_DIR OFFSETGEN_CONFIG_MODULE_DIR)
# offsetgen is a build tool: a 32-bit consumer can run a 64-bit offsetgen, hence ARCH_INDEPENDENT.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/offsetgenConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)

# --- Installation --------------------------------------------------------------------------------
if(OFFSETGEN_INSTALL)
  install(TARGETS offsetgen EXPORT offsetgenTargets RUNTIME DESTINATION bin)
  if(TARGET offsetgen-mesh)
    install(TARGETS offsetgen-mesh RUNTIME DESTINATION bin)
  endif()
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/templates/" DESTINATION share/offsetgen/templates)
  install(PROGRAMS "${PROJECT_SOURCE_DIR}/tools/plot_convergence.py" DESTINATION share/offsetgen/tools)

  install(EXPORT offsetgenTargets NAMESPACE offsetgen:: FILE offsetgenTargets.cmake
          DESTINATION "${OFFSETGEN_INSTALL_CMAKEDIR}")
  set(OFFSETGEN_CONFIG_TEMPLATE_DIR share/offsetgen/templates)
  set(OFFSETGEN_CONFIG_MODULE_DIR "${OFFSETGEN_INSTALL_CMAKEDIR}")
  configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/offsetgenConfig.cmake.in"
    "${PROJECT_BINARY_DIR}/CMakeFiles/offsetgen-install/offsetgenConfig.cmake"
    INSTALL_DESTINATION "${OFFSETGEN_INSTALL_CMAKEDIR}"
    PATH_VARS OFFSETGEN_CONFIG_TEMPLATE_DIR OFFSETGEN_CONFIG_MODULE_DIR)
  install(FILES
    "${PROJECT_BINARY_DIR}/CMakeFiles/offsetgen-install/offsetgenConfig.cmake"
    "${PROJECT_BINARY_DIR}/offsetgenConfigVersion.cmake"
    "${CMAKE_CURRENT_LIST_DIR}/offsetgenGenerate.cmake"
    "${CMAKE_CURRENT_LIST_DIR}/offsetgenGlslString.cmake"
    DESTINATION "${OFFSETGEN_INSTALL_CMAKEDIR}")
endif()
