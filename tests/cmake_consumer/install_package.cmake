# Installs offsetgen from its build tree into a scratch prefix, checks the layout, moves the prefix
# (the package and the executable must not care where they live) and checks that the installed
# executable reads the templates of its own prefix (share/offsetgen/templates), not the source tree.
#   cmake -DOFFSETGEN_BINARY_DIR=<build> -DOFFSETGEN_SOURCE_DIR=<src> -DCONFIG=<build type>
#         -DWORK_DIR=<scratch> [-DWITH_MESH=1] -P install_package.cmake
# Leaves the relocated prefix in WORK_DIR/prefix for the consumer tests.
cmake_minimum_required(VERSION 3.25)
foreach(variable OFFSETGEN_BINARY_DIR OFFSETGEN_SOURCE_DIR CONFIG WORK_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_package.cmake: -D${variable}=... is required")
  endif()
endforeach()
unset(ENV{DESTDIR})
unset(ENV{OFFSETGEN_TEMPLATE_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${command}\n${output}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

set(staging "${WORK_DIR}/staging")
set(prefix "${WORK_DIR}/prefix")
set(marked "${WORK_DIR}/marked-prefix")
file(REMOVE_RECURSE "${staging}" "${prefix}" "${marked}")

run("${CMAKE_COMMAND}" --install "${OFFSETGEN_BINARY_DIR}" --prefix "${staging}" --config "${CONFIG}")
message("${output}")

# The layout. The package directory is wherever OFFSETGEN_INSTALL_CMAKEDIR put it (lib/cmake/offsetgen
# by default), as long as find_package() looks there: <prefix>/(lib*|share)/cmake/offsetgen.
file(GLOB configs RELATIVE "${staging}" "${staging}/lib*/cmake/offsetgen/offsetgenConfig.cmake"
     "${staging}/lib/*/cmake/offsetgen/offsetgenConfig.cmake" "${staging}/share/cmake/offsetgen/offsetgenConfig.cmake")
list(LENGTH configs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one offsetgenConfig.cmake where find_package() looks, found: '${configs}'")
endif()
get_filename_component(CMAKEDIR "${configs}" DIRECTORY)
file(GLOB_RECURSE templates RELATIVE "${OFFSETGEN_SOURCE_DIR}/templates" "${OFFSETGEN_SOURCE_DIR}/templates/*.in")
set(expected bin/offsetgen share/offsetgen/tools/plot_convergence.py)
if(WITH_MESH)  # built with OpenVDB: `offsetgen mesh` execs offsetgen-mesh from offsetgen's directory
  list(APPEND expected bin/offsetgen-mesh)
endif()
foreach(template IN LISTS templates)
  list(APPEND expected "share/offsetgen/templates/${template}")
endforeach()
foreach(file offsetgenConfig.cmake offsetgenConfigVersion.cmake offsetgenTargets.cmake
             offsetgenGenerate.cmake offsetgenGlslString.cmake)
  list(APPEND expected "${CMAKEDIR}/${file}")
endforeach()
foreach(file IN LISTS expected)
  if(NOT EXISTS "${staging}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
file(GLOB target_files "${staging}/${CMAKEDIR}/offsetgenTargets*.cmake")
foreach(file IN LISTS target_files)
  file(READ "${file}" text)
  foreach(path "${OFFSETGEN_BINARY_DIR}" "${staging}")
    string(FIND "${text}" "${path}" at)
    if(NOT at LESS 0)
      message(FATAL_ERROR "${file} holds the absolute path ${path}: the package is not relocatable")
    endif()
  endforeach()
endforeach()
file(READ "${staging}/${CMAKEDIR}/offsetgenTargets.cmake" text)
if(NOT text MATCHES "add_executable\\(offsetgen::offsetgen IMPORTED\\)")
  message(FATAL_ERROR "offsetgenTargets.cmake does not import offsetgen::offsetgen")
endif()
message(STATUS "installed: ${expected}")

# Move the prefix: everything must still work from the new place.
file(RENAME "${staging}" "${prefix}")
run("${prefix}/bin/offsetgen" generate --surface gyroid --order 2 -o "${WORK_DIR}/from_prefix.h")
if(WITH_MESH)  # a small part, meshed through the installed pair
  file(REMOVE "${WORK_DIR}/from_prefix.stl")
  run("${prefix}/bin/offsetgen" mesh --surface gyroid --thickness 0.25 --cells 1 --resolution 8 -q
      -o "${WORK_DIR}/from_prefix.stl")
  if(NOT EXISTS "${WORK_DIR}/from_prefix.stl")
    message(FATAL_ERROR "the installed `offsetgen mesh` exited 0 but wrote no from_prefix.stl")
  endif()
endif()

# A copy of the prefix whose template carries a marker: its executable must put the marker in the
# header, so it reads share/offsetgen/templates first, not the compiled-in source tree (which is
# still there; OFFSETGEN_TEMPLATE_DIR is unset).
file(COPY "${prefix}/" DESTINATION "${marked}")
set(marker "/* offsetgen install test: template read from the prefix's share/offsetgen/templates */")
file(APPEND "${marked}/share/offsetgen/templates/c/c_header.h.in" "${marker}\n")
run("${marked}/bin/offsetgen" generate --surface gyroid --order 2 -o "${WORK_DIR}/from_marked_prefix.h")
file(READ "${WORK_DIR}/from_marked_prefix.h" text)
string(FIND "${text}" "${marker}" at)
if(at LESS 0)
  message(FATAL_ERROR "the installed offsetgen did not read its templates from <prefix>/share/offsetgen/templates")
endif()
file(READ "${WORK_DIR}/from_prefix.h" text)
string(FIND "${text}" "${marker}" at)
if(NOT at LESS 0)
  message(FATAL_ERROR "the marker leaked into the unmarked prefix")
endif()
file(REMOVE_RECURSE "${marked}")

# The installed executable knows no source tree: no string in it names the source directory, and a
# copy of the prefix without its templates stops with a message instead of reading the source tree's.
file(STRINGS "${prefix}/bin/offsetgen" strings)
foreach(text IN LISTS strings)
  string(FIND "${text}" "${OFFSETGEN_SOURCE_DIR}" at)
  if(NOT at LESS 0)
    message(FATAL_ERROR "the installed offsetgen holds a path of the source tree: ${text}")
  endif()
endforeach()
set(bare "${WORK_DIR}/bare-prefix")
file(REMOVE_RECURSE "${bare}")
file(COPY "${prefix}/" DESTINATION "${bare}")
file(REMOVE_RECURSE "${bare}/share/offsetgen/templates")
execute_process(COMMAND "${bare}/bin/offsetgen" generate --surface gyroid --order 1 -o "${WORK_DIR}/from_bare.h"
                RESULT_VARIABLE rc OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(rc EQUAL 0 OR EXISTS "${WORK_DIR}/from_bare.h")
  message(FATAL_ERROR "an installed offsetgen without its templates still generated a header (from the source tree?)")
endif()
if(NOT output MATCHES "cannot find offsetgen's templates")
  message(FATAL_ERROR "no clear message without the templates:\n${output}")
endif()
file(REMOVE_RECURSE "${bare}")
message(STATUS "the relocated offsetgen reads <prefix>/share/offsetgen/templates first, knows no source path; prefix left in ${prefix}")
