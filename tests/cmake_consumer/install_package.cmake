# Installs offsetgen from its build tree into a scratch prefix, checks the layout, moves the prefix
# (the package and the executable must not care where they live) and checks that the executable
# needs nothing beside it: its templates are compiled in, and it holds no path of the source tree.
#   cmake -DOFFSETGEN_BINARY_DIR=<build> -DOFFSETGEN_SOURCE_DIR=<src> -DCONFIG=<build type>
#         -DWORK_DIR=<scratch> [-DWITH_MESH=1] [-DWITH_STEP=1] -P install_package.cmake
# Leaves the relocated prefix in WORK_DIR/prefix for the consumer tests.
cmake_minimum_required(VERSION 3.25)
foreach(variable OFFSETGEN_BINARY_DIR OFFSETGEN_SOURCE_DIR CONFIG WORK_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_package.cmake: -D${variable}=... is required")
  endif()
endforeach()
unset(ENV{DESTDIR})

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
set(expected bin/offsetgen share/offsetgen/tools/plot_convergence.py)
if(WITH_MESH)  # built with OpenVDB: `offsetgen mesh` execs offsetgen-mesh from offsetgen's directory
  list(APPEND expected bin/offsetgen-mesh)
endif()
if(WITH_STEP)  # built with OpenCASCADE: `offsetgen step` execs offsetgen-step the same way
  list(APPEND expected bin/offsetgen-step)
endif()
foreach(file offsetgenConfig.cmake offsetgenConfigVersion.cmake offsetgenTargets.cmake
             offsetgenGenerate.cmake offsetgenGlslString.cmake)
  list(APPEND expected "${CMAKEDIR}/${file}")
endforeach()
foreach(file IN LISTS expected)
  if(NOT EXISTS "${staging}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
# The templates are compiled into the executable: none is installed beside it.
if(EXISTS "${staging}/share/offsetgen/templates")
  message(FATAL_ERROR "share/offsetgen/templates was installed, but offsetgen carries its templates inside")
endif()
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

if(WITH_STEP)  # a small STEP block through the installed pair
  file(REMOVE "${WORK_DIR}/from_prefix.step")
  run("${prefix}/bin/offsetgen" step --surface schwarzp --thickness 0.1 --cells 1 --cell-size 10 -q
      -o "${WORK_DIR}/from_prefix.step")
  if(NOT EXISTS "${WORK_DIR}/from_prefix.step")
    message(FATAL_ERROR "the installed `offsetgen step` exited 0 but wrote no from_prefix.step")
  endif()
endif()

# The installed executable knows no source tree: no string in it names the source directory.
file(STRINGS "${prefix}/bin/offsetgen" strings)
foreach(text IN LISTS strings)
  string(FIND "${text}" "${OFFSETGEN_SOURCE_DIR}" at)
  if(NOT at LESS 0)
    message(FATAL_ERROR "the installed offsetgen holds a path of the source tree: ${text}")
  endif()
endforeach()

# The executable alone, copied where nothing of the prefix or the source tree lies beside it, writes
# the same bytes: its templates are inside it.
set(alone "${WORK_DIR}/offsetgen-alone")
file(REMOVE_RECURSE "${alone}")
file(MAKE_DIRECTORY "${alone}")
file(COPY "${prefix}/bin/offsetgen" DESTINATION "${alone}")
run("${alone}/offsetgen" generate --surface gyroid --order 2 -o "${alone}/from_prefix.h")
file(READ "${alone}/from_prefix.h" alone_text)
file(READ "${WORK_DIR}/from_prefix.h" prefix_text)
if(NOT alone_text STREQUAL prefix_text)
  message(FATAL_ERROR "offsetgen copied alone wrote other bytes than the installed one")
endif()
file(REMOVE_RECURSE "${alone}")
message(STATUS "the relocated offsetgen works, alone too, and knows no source path; prefix left in ${prefix}")
