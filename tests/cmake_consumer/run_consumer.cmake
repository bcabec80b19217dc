# Configures, builds and runs the example consumer (consumer/) in a scratch build tree, then checks
# with the build tool's own dry run that a second build with nothing changed would neither run
# offsetgen nor compile anything, and that changed arguments regenerate what they must and no more.
#
#   cmake -DMODE=package|subdirectory -DWORK_DIR=<scratch> -DGENERATOR=<"Unix Makefiles"|Ninja>
#         [-DMAKE_PROGRAM=<make or ninja>] -DBUILD_TYPE=<type> -DC_COMPILER=<cc> [-DCXX_COMPILER=<c++>]
#         [-DPREFIX=<installed offsetgen> (package)] [-DOFFSETGEN_SOURCE_DIR=<src> (subdirectory)]
#         [-DJOBS=2] -P run_consumer.cmake
#
# package:      find_package(offsetgen CONFIG REQUIRED) against a copy of PREFIX (so that touching its
#               executable here disturbs no other test);
# subdirectory: add_subdirectory() of a snapshot of OFFSETGEN_SOURCE_DIR, which builds offsetgen
#               inside the consumer.
cmake_minimum_required(VERSION 3.25)
foreach(variable MODE WORK_DIR GENERATOR BUILD_TYPE C_COMPILER)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "run_consumer.cmake: -D${variable}=... is required")
  endif()
endforeach()
if(NOT DEFINED JOBS)
  set(JOBS 2)
endif()
# Keep the nested builds to themselves when ctest itself runs under make or with these set.
foreach(variable MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES CMAKE_BUILD_PARALLEL_LEVEL CMAKE_GENERATOR
                 CMAKE_PREFIX_PATH DESTDIR)
  unset(ENV{${variable}})
endforeach()

set(consumer_source "${CMAKE_CURRENT_LIST_DIR}/consumer")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${build}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Runs a command; stops on failure; leaves stdout+stderr in `output`.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${command}\n${output}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

function(require_match text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected to match '${regex}' in:\n${text}")
  endif()
endfunction()

function(forbid_match text regex what)
  if(text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: '${CMAKE_MATCH_0}' should not be there, in:\n${text}")
  endif()
endfunction()

set(generator_args -G "${GENERATOR}")
if(MAKE_PROGRAM)
  list(APPEND generator_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
list(APPEND generator_args "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" "-DCMAKE_C_COMPILER=${C_COMPILER}")

set(mode_args "")
if(MODE STREQUAL "package")
  if(NOT DEFINED PREFIX)
    message(FATAL_ERROR "run_consumer.cmake: MODE=package needs -DPREFIX=...")
  endif()
  set(own_prefix "${WORK_DIR}/prefix")
  file(REMOVE_RECURSE "${own_prefix}")
  file(COPY "${PREFIX}/" DESTINATION "${own_prefix}")
  list(APPEND mode_args "-DCMAKE_PREFIX_PATH=${own_prefix}" --warn-uninitialized)
elseif(MODE STREQUAL "subdirectory")
  if(NOT DEFINED OFFSETGEN_SOURCE_DIR)
    message(FATAL_ERROR "run_consumer.cmake: MODE=subdirectory needs -DOFFSETGEN_SOURCE_DIR=...")
  endif()
  # A snapshot of the source tree, so that edits made to it while this test builds (minutes) do
  # not show up as work in the no-op checks. Build trees and version control stay behind.
  set(snapshot "${WORK_DIR}/offsetgen-source")
  file(REMOVE_RECURSE "${snapshot}")
  file(MAKE_DIRECTORY "${snapshot}")
  file(GLOB entries RELATIVE "${OFFSETGEN_SOURCE_DIR}" "${OFFSETGEN_SOURCE_DIR}/*")
  foreach(entry IN LISTS entries)
    if(entry MATCHES "^(\\.|build|out$|generated$)" OR EXISTS "${OFFSETGEN_SOURCE_DIR}/${entry}/CMakeCache.txt")
      continue()
    endif()
    file(COPY "${OFFSETGEN_SOURCE_DIR}/${entry}" DESTINATION "${snapshot}")
  endforeach()
  # OFFSETGEN_BUILD_TESTS is left to its default, which must be OFF below a parent project.
  list(APPEND mode_args "-DOFFSETGEN_SOURCE_DIR=${snapshot}" -DOFFSETGEN_BUILD_BENCHMARKS=OFF)
  if(DEFINED CXX_COMPILER)
    list(APPEND mode_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
  endif()
else()
  message(FATAL_ERROR "run_consumer.cmake: unknown MODE '${MODE}'")
endif()

function(configure)
  run("${CMAKE_COMMAND}" -S "${consumer_source}" -B "${build}" ${generator_args} ${mode_args} ${ARGN})
  forbid_match("${output}" "CMake (Deprecation )?Warning[^\n]*" "configure")
endfunction()

function(build step)
  run("${CMAKE_COMMAND}" --build "${build}" --parallel ${JOBS})
  file(WRITE "${WORK_DIR}/${step}.build.txt" "${output}")
  message("--- build (${step}):\n${output}")
  set(output "${output}" PARENT_SCOPE)
endfunction()

# The build tool's own dry run. Makefiles: `make -n` may print only the bookkeeping of CMake's
# recursive make (every line on the allow-list below); Ninja: `ninja -n -d explain` must say
# "no work to do".
function(require_nothing_to_do step)
  if(GENERATOR MATCHES "Ninja")
    run("${CMAKE_COMMAND}" --build "${build}" -- -n -d explain)
    set(dry_run "${output}")
    require_match("${dry_run}" "ninja: no work to do" "ninja -n -d explain (${step})")
  else()
    run("${CMAKE_COMMAND}" --build "${build}" -- -n)
    set(dry_run "${output}")
    string(REPLACE "\n" ";" lines "${dry_run}")
    foreach(line IN LISTS lines)
      if(line STREQUAL "" OR line MATCHES "--check-build-system|cmake_progress_start|-f CMakeFiles/Makefile2 |build\\.make [^ ]*/(depend|build)$|cmake_depends |cmake_echo_color .*\"Built target [^\"]*\"$|VerifyGlobs\\.cmake$")
        continue()
      endif()
      message(FATAL_ERROR "make -n (${step}) would run a command that is not CMake's bookkeeping:\n  ${line}\nwhole output:\n${dry_run}")
    endforeach()
  endif()
  file(WRITE "${WORK_DIR}/${step}.dry-run.txt" "${dry_run}")
  message("--- dry run (${step}), nothing to do:\n${dry_run}")
endfunction()

# The other way round, to show that the dry run does see pending work: it must announce offsetgen.
function(require_generation_pending step)
  if(GENERATOR MATCHES "Ninja")
    run("${CMAKE_COMMAND}" --build "${build}" -- -n -d explain)
    require_match("${output}" "offsetgen: generating gyroid_o4" "ninja -n -d explain (${step})")
  else()
    run("${CMAKE_COMMAND}" --build "${build}" -- -n)
    require_match("${output}" "offsetgen[^\n]* generate --surface gyroid --order 4" "make -n (${step})")
  endif()
  file(WRITE "${WORK_DIR}/${step}.dry-run.txt" "${output}")
endfunction()

# A build that must do nothing: no generation, no compilation, no link.
function(require_noop_build step)
  build(${step}-again)
  forbid_match("${output}" "offsetgen: generating[^\n]*|Building [A-Z]+ object[^\n]*|Linking [^\n]*" "no-op build (${step})")
endfunction()

function(check_app)
  set(glsl "${build}/gen/gyroid_o4.glsl")
  set(copy "${WORK_DIR}/gyroid_o4_glsl_string.glsl")
  file(REMOVE "${copy}")
  run("${build}/consumer_app" "${copy}")
  message("--- consumer_app:\n${output}")
  foreach(point_expectation
          "0\\.000, 0\\.000, 0\\.000\\): shell = -[0-9.e+-]+ -> inside the wall"
          "0\\.030, 0\\.000, 0\\.000\\): shell = -[0-9.e+-]+ -> inside the wall"
          "0\\.500, 0\\.500, 0\\.500\\): shell = -[0-9.e+-]+ -> inside the wall"
          "0\\.250, 0\\.000, 0\\.000\\): shell = \\+[0-9.e+-]+ -> outside the wall"
          "0\\.125, 0\\.125, 0\\.125\\): shell = \\+[0-9.e+-]+ -> outside the wall")
    require_match("${output}" "gyroid_o4 t=0\\.10 \\(${point_expectation}" "consumer_app output")
  endforeach()
  forbid_match("${output}" "float disagrees[^\n]*" "consumer_app output")
  file(SIZE "${glsl}" glsl_size)
  require_match("${output}" "gyroid_o4_glsl: ${glsl_size} bytes\n" "consumer_app output (the string's size is the .glsl file's)")
  run("${CMAKE_COMMAND}" -E compare_files "${copy}" "${glsl}")
endfunction()

# --- 1. Configure, build, run --------------------------------------------------------------------
configure()
if(MODE STREQUAL "package")
  file(STRINGS "${build}/CMakeCache.txt" package_dir REGEX "^offsetgen_DIR:")
  require_match("${package_dir}" "=${own_prefix}/" "find_package(offsetgen) found the package")
else()
  file(STRINGS "${build}/CMakeCache.txt" tests_option REGEX "^OFFSETGEN_BUILD_TESTS:")
  require_match("${tests_option}" "=OFF$" "OFFSETGEN_BUILD_TESTS defaults to OFF below a parent project")
endif()
build(first)
require_match("${output}" "offsetgen: generating gyroid_o2 \\(c, glsl_string\\)" "first build")
require_match("${output}" "offsetgen: generating gyroid_o4 \\(c, glsl_string\\)" "first build")
require_match("${output}" "Building C object CMakeFiles/consumer_app.dir/main.c" "first build")
file(READ "${build}/offsetgen_outputs.txt" lists)
foreach(expected
        "headers=${build}/gen/gyroid_o2.h;${build}/gen/gyroid_o4.h\n"
        "glsl=${build}/gen/gyroid_o2.glsl;${build}/gen/gyroid_o4.glsl\n"
        "glsl_string=${build}/gen/gyroid_o2_glsl.h;${build}/gen/gyroid_o4_glsl.h\n"
        "glsl_property=${build}/gen/gyroid_o2.glsl;${build}/gen/gyroid_o4.glsl\n")
  string(FIND "${lists}" "${expected}" at)
  if(at LESS 0)
    message(FATAL_ERROR "offsetgen_generate() lists: '${expected}' not in:\n${lists}")
  endif()
endforeach()
check_app()

# --- 2. Nothing changed: nothing to do -----------------------------------------------------------
require_nothing_to_do(second)
require_noop_build(second)

# --- 3. A newer generator (package mode: touch the installed executable) reruns offsetgen, which
#        leaves the unchanged files alone, so the app is not recompiled; then nothing to do again.
if(MODE STREQUAL "package")
  file(TOUCH "${own_prefix}/bin/offsetgen")
  require_generation_pending(generator-touched-before)
  build(generator-touched)
  require_match("${output}" "offsetgen: generating gyroid_o4" "build after the generator changed")
  forbid_match("${output}" "Building C object[^\n]*" "build after the generator changed (same content)")
  require_nothing_to_do(generator-touched)
endif()

# --- 4. A changed argument: one more order generates that order only ------------------------------
configure(-DCONSUMER_ORDERS=2,4,6)
build(orders-changed)
require_match("${output}" "offsetgen: generating gyroid_o6" "build after ORDERS 2 4 -> 2 4 6")
forbid_match("${output}" "offsetgen: generating gyroid_o[24][^\n]*|Building C object[^\n]*" "build after ORDERS 2 4 -> 2 4 6")
if(NOT EXISTS "${build}/gen/gyroid_o6.h" OR NOT EXISTS "${build}/gen/gyroid_o6_glsl.h")
  message(FATAL_ERROR "gyroid_o6.h / gyroid_o6_glsl.h were not generated")
endif()
require_nothing_to_do(orders-changed)

# --- 5. A changed argument that changes every file: all orders regenerate, the app recompiles ----
if(MODE STREQUAL "package")
  configure(-DCONSUMER_THICKNESS=0.05+0.02*x)
  build(thickness-changed)
  foreach(order 2 4 6)
    require_match("${output}" "offsetgen: generating gyroid_o${order}" "build after THICKNESS was added")
  endforeach()
  require_match("${output}" "Building C object CMakeFiles/consumer_app.dir/main.c" "build after THICKNESS was added")
  file(READ "${build}/gen/gyroid_o4.h" header)
  require_match("${header}" "gyroid_o4_graded\\(" "gyroid_o4.h after THICKNESS was added")
  check_app()
  require_nothing_to_do(thickness-changed)
  require_noop_build(thickness-changed)
endif()

message(STATUS "consumer (${MODE}, ${GENERATOR}): generated, built, ran; no-op rebuilds and argument changes behave")
