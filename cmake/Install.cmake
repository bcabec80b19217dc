# Installation, the CMake package (find_package(offsetgen), offsetgen_generate()) and the build-tree
# export. Included by the top-level CMakeLists.txt after src/.
#
# Installed layout (the templates are compiled into the executable; `offsetgen check --plot` finds
# its plot script at <exe>/../share/offsetgen/tools, so bin/ and share/ are fixed):
#   bin/offsetgen
#   bin/offsetgen-mesh (where built with OpenVDB: `offsetgen mesh` execs it from offsetgen's directory)
#   share/offsetgen/tools/plot_convergence.py
#   <OFFSETGEN_INSTALL_CMAKEDIR>/offsetgenConfig.cmake, offsetgenConfigVersion.cmake,
#       offsetgenTargets*.cmake, offsetgenGenerate.cmake, offsetgenGlslString.cmake
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

option(OFFSETGEN_INSTALL "Generate offsetgen's install rules" ${PROJECT_IS_TOP_LEVEL})
set(OFFSETGEN_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/offsetgen" CACHE STRING
    "Where to install offsetgen's CMake package, relative to the prefix")
mark_as_advanced(OFFSETGEN_INSTALL_CMAKEDIR)

# The registries as data: cmake/registries.json is what `offsetgen list --registries` prints (the
# surfaces, the offset methods with their orders, the targets with their extensions), committed so
# that offsetgen_generate() can check SURFACE, METHOD, ORDERS and LANG and name its files at configure
# time, before offsetgen is built. Test Cli.RegistriesJsonIsWhatTheToolPrints keeps it current;
# tools/update_golden.sh rewrites it.
file(READ "${PROJECT_SOURCE_DIR}/cmake/registries.json" _offsetgen_registries)

# The offset methods as "name:max_order:even" entries (even: every order it builds is even), sorted;
# and as "name:1,2,3" entries with every order it builds, in registry order (the tests' matrix).
set(OFFSETGEN_METHODS "")
set(OFFSETGEN_METHOD_ORDERS "")
string(JSON _count LENGTH "${_offsetgen_registries}" methods)
math(EXPR _last "${_count} - 1")
foreach(_i RANGE ${_last})
  string(JSON _name GET "${_offsetgen_registries}" methods ${_i} name)
  string(JSON _max GET "${_offsetgen_registries}" methods ${_i} max_order)
  string(JSON _default GET "${_offsetgen_registries}" methods ${_i} default)
  string(JSON _orders LENGTH "${_offsetgen_registries}" methods ${_i} orders)
  set(_even true)
  set(_order_list "")
  math(EXPR _orders_last "${_orders} - 1")
  foreach(_k RANGE ${_orders_last})
    string(JSON _order GET "${_offsetgen_registries}" methods ${_i} orders ${_k})
    list(APPEND _order_list ${_order})
    math(EXPR _odd "${_order} % 2")
    if(_odd)
      set(_even false)
    endif()
  endforeach()
  list(APPEND OFFSETGEN_METHODS "${_name}:${_max}:${_even}")
  list(JOIN _order_list "," _order_list)
  list(APPEND OFFSETGEN_METHOD_ORDERS "${_name}:${_order_list}")
  if(_default)
    set(OFFSETGEN_DEFAULT_METHOD ${_name})
  endif()
endforeach()
list(SORT OFFSETGEN_METHODS)
if(NOT OFFSETGEN_METHODS OR NOT OFFSETGEN_DEFAULT_METHOD)
  message(FATAL_ERROR "offsetgen: cmake/registries.json lists no offset method or no default one")
endif()

# The output languages as "name:extension" entries, in registry order.
set(OFFSETGEN_LANGUAGES "")
string(JSON _count LENGTH "${_offsetgen_registries}" targets)
math(EXPR _last "${_count} - 1")
foreach(_i RANGE ${_last})
  string(JSON _name GET "${_offsetgen_registries}" targets ${_i} name)
  string(JSON _ext GET "${_offsetgen_registries}" targets ${_i} extension)
  list(APPEND OFFSETGEN_LANGUAGES "${_name}:${_ext}")
endforeach()

# The catalog's surface names, so offsetgen_generate() can reject an unknown SURFACE at configure time
# (tests/cmake_consumer checks that this list is `offsetgen list`'s).
set(OFFSETGEN_SURFACES "")
string(JSON _count LENGTH "${_offsetgen_registries}" surfaces)
math(EXPR _last "${_count} - 1")
foreach(_i RANGE ${_last})
  string(JSON _name GET "${_offsetgen_registries}" surfaces ${_i} name)
  list(APPEND OFFSETGEN_SURFACES "${_name}")
endforeach()
foreach(_var _offsetgen_registries _count _last _i _name _max _default _orders _orders_last _k _order _odd _even _ext
        _order_list)
  unset(${_var})
endforeach()

# --- The same names inside this build (add_subdirectory / FetchContent users, and our tests) -------
add_executable(offsetgen::offsetgen ALIAS offsetgen)
set_property(GLOBAL PROPERTY OFFSETGEN_METHODS "${OFFSETGEN_METHODS}")
set_property(GLOBAL PROPERTY OFFSETGEN_METHOD_ORDERS "${OFFSETGEN_METHOD_ORDERS}")
set_property(GLOBAL PROPERTY OFFSETGEN_LANGUAGES "${OFFSETGEN_LANGUAGES}")
set_property(GLOBAL PROPERTY OFFSETGEN_DEFAULT_METHOD "${OFFSETGEN_DEFAULT_METHOD}")
set_property(GLOBAL PROPERTY OFFSETGEN_SURFACES "${OFFSETGEN_SURFACES}")
include("${CMAKE_CURRENT_LIST_DIR}/offsetgenGenerate.cmake")

# --- Build-tree package: find_package(offsetgen) with offsetgen_DIR=<this build dir> ------------
export(TARGETS offsetgen NAMESPACE offsetgen:: FILE "${PROJECT_BINARY_DIR}/offsetgenTargets.cmake")
set(OFFSETGEN_CONFIG_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/offsetgenConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/offsetgenConfig.cmake"
  INSTALL_DESTINATION "${PROJECT_BINARY_DIR}"
  INSTALL_PREFIX "${PROJECT_BINARY_DIR}"
  PATH_VARS OFFSETGEN_CONFIG_MODULE_DIR)
# offsetgen is a build tool: a 32-bit consumer can run a 64-bit offsetgen, hence ARCH_INDEPENDENT.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/offsetgenConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)

# --- Installation --------------------------------------------------------------------------------
if(OFFSETGEN_INSTALL)
  install(TARGETS offsetgen EXPORT offsetgenTargets RUNTIME DESTINATION bin)
  # `offsetgen mesh` and `offsetgen step` exec these from offsetgen's own directory (cli/siblings.h).
  if(TARGET offsetgen-mesh)
    install(TARGETS offsetgen-mesh RUNTIME DESTINATION bin)
  endif()
  if(TARGET offsetgen-step)
    install(TARGETS offsetgen-step RUNTIME DESTINATION bin)
  endif()
  install(PROGRAMS "${PROJECT_SOURCE_DIR}/tools/plot_convergence.py" DESTINATION share/offsetgen/tools)

  install(EXPORT offsetgenTargets NAMESPACE offsetgen:: FILE offsetgenTargets.cmake
          DESTINATION "${OFFSETGEN_INSTALL_CMAKEDIR}")
  set(OFFSETGEN_CONFIG_MODULE_DIR "${OFFSETGEN_INSTALL_CMAKEDIR}")
  configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/offsetgenConfig.cmake.in"
    "${PROJECT_BINARY_DIR}/CMakeFiles/offsetgen-install/offsetgenConfig.cmake"
    INSTALL_DESTINATION "${OFFSETGEN_INSTALL_CMAKEDIR}"
    PATH_VARS OFFSETGEN_CONFIG_MODULE_DIR)
  install(FILES
    "${PROJECT_BINARY_DIR}/CMakeFiles/offsetgen-install/offsetgenConfig.cmake"
    "${PROJECT_BINARY_DIR}/offsetgenConfigVersion.cmake"
    "${CMAKE_CURRENT_LIST_DIR}/offsetgenGenerate.cmake"
    "${CMAKE_CURRENT_LIST_DIR}/offsetgenGlslString.cmake"
    DESTINATION "${OFFSETGEN_INSTALL_CMAKEDIR}")
endif()
