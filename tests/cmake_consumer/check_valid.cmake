# Configures and builds errors/ with CASE=valid through the package of offsetgen's build tree
# (export()), and checks the files offsetgen_generate() promised: SURFACE and EXPR forms, every
# LANG, PRECISION float, THICKNESS, PARAMS, relative and default OUTPUT_DIR.
#   cmake -DPACKAGE_DIR=<offsetgen build dir> -DWORK_DIR=<scratch> -P check_valid.cmake
cmake_minimum_required(VERSION 3.25)
foreach(variable PACKAGE_DIR WORK_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "check_valid.cmake: -D${variable}=... is required")
  endif()
endforeach()
foreach(variable MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES OFFSETGEN_TEMPLATE_DIR)
  unset(ENV{${variable}})
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${command}\n${output}")
  endif()
  message("${output}")
  set(output "${output}" PARENT_SCOPE)
endfunction()

set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${build}")
run("${CMAKE_COMMAND}" -S "${CMAKE_CURRENT_LIST_DIR}/errors" -B "${build}" "-Doffsetgen_DIR=${PACKAGE_DIR}"
    -DCASE=valid --warn-uninitialized)
if(output MATCHES "CMake (Deprecation )?Warning")
  message(FATAL_ERROR "configuring printed a warning")
endif()
run("${CMAKE_COMMAND}" --build "${build}")

set(gen "${build}/gen")
foreach(file "${gen}/gyroid_o1.h" "${gen}/gyroid_o1.glsl" "${gen}/gyroid_o1_glsl.h"
             "${gen}/gyroid_o2.h" "${gen}/gyroid_o2.glsl" "${gen}/gyroid_o2_glsl.h"
             "${build}/wave_offsets/wave_o2.glsl")
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "not generated: ${file}")
  endif()
endforeach()
if(EXISTS "${build}/wave_offsets/wave_o2.h")
  message(FATAL_ERROR "LANG glsl generated a C header too")
endif()
file(READ "${gen}/gyroid_o2.h" header)
if(NOT header MATCHES "float gyroid_o2_shellf\\(" OR header MATCHES "double gyroid_o2_shell\\("
   OR NOT header MATCHES "gyroid_o2_gradedf")
  message(FATAL_ERROR "gyroid_o2.h: expected float functions only, with _graded (PRECISION float, THICKNESS)")
endif()
file(READ "${build}/outputs.txt" lists)
string(FIND "${lists}" "${build}/wave_offsets/wave_o2.glsl" at)
if(at LESS 0)
  message(FATAL_ERROR "wave_offsets_GLSL_FILES does not list wave_o2.glsl:\n${lists}")
endif()

run("${CMAKE_COMMAND}" --build "${build}")
if(output MATCHES "offsetgen: generating")
  message(FATAL_ERROR "a second build with nothing changed ran offsetgen again")
endif()
# OFFSETGEN_EXECUTABLE (a host offsetgen, for cross builds) replaces offsetgen::offsetgen: a wrapper
# that logs its runs and forwards to the real tool must now do the work, and the changed tool must
# regenerate everything.
if(CMAKE_HOST_UNIX)
  set(wrapper "${WORK_DIR}/host-offsetgen.sh")
  set(log "${WORK_DIR}/host-offsetgen.log")
  file(REMOVE "${log}")
  file(WRITE "${wrapper}" "#!/bin/sh\necho \"$*\" >> '${log}'\nexec '${PACKAGE_DIR}/offsetgen' \"$@\"\n")
  file(CHMOD "${wrapper}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
       WORLD_READ WORLD_EXECUTE)
  run("${CMAKE_COMMAND}" "-DOFFSETGEN_EXECUTABLE=${wrapper}" "${build}")
  run("${CMAKE_COMMAND}" --build "${build}")
  if(NOT EXISTS "${log}")
    message(FATAL_ERROR "OFFSETGEN_EXECUTABLE was set, but the build did not run it")
  endif()
  file(STRINGS "${log}" runs)
  # At configure time the tool was asked for its catalog (SURFACE is validated against it).
  if(NOT runs MATCHES "list --json")
    message(FATAL_ERROR "configure did not ask OFFSETGEN_EXECUTABLE for its catalog:\n${runs}")
  endif()
  list(FILTER runs INCLUDE REGEX "^generate ")
  list(LENGTH runs count)
  if(NOT count EQUAL 3)  # gyroid orders 1 and 2, wave order 2
    message(FATAL_ERROR "OFFSETGEN_EXECUTABLE ran ${count} times, expected 3:\n${runs}")
  endif()
  run("${CMAKE_COMMAND}" --build "${build}")
  if(output MATCHES "offsetgen: generating")
    message(FATAL_ERROR "a second build with OFFSETGEN_EXECUTABLE set ran it again")
  endif()
endif()
message(STATUS "offsetgen_generate() through the build tree's package: all files generated")
