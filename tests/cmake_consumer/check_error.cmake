# Configures errors/ with one CASE and checks that configuring stops with a FATAL_ERROR from
# offsetgen_generate() whose message matches EXPECT (and so names the argument at fault).
#   cmake -DCASE=<case> -DEXPECT=<regex> -DPACKAGE_DIR=<dir with offsetgenConfig.cmake>
#         -DWORK_DIR=<scratch> -P check_error.cmake
cmake_minimum_required(VERSION 3.25)
foreach(variable CASE EXPECT PACKAGE_DIR WORK_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "check_error.cmake: -D${variable}=... is required")
  endif()
endforeach()

set(build "${WORK_DIR}/${CASE}")
file(REMOVE_RECURSE "${build}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -S "${CMAKE_CURRENT_LIST_DIR}/errors" -B "${build}"
          "-Doffsetgen_DIR=${PACKAGE_DIR}" "-DCASE=${CASE}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(rc EQUAL 0)
  message(FATAL_ERROR "case ${CASE}: configuring succeeded, but offsetgen_generate() should have stopped it")
endif()
if(NOT output MATCHES "CMake Error at [^\n]*offsetgenGenerate\\.cmake")
  message(FATAL_ERROR "case ${CASE}: the error does not come from offsetgen_generate()")
endif()
# message() wraps and re-spaces the text: compare with whitespace runs folded to one space.
string(REGEX REPLACE "[ \t\r\n]+" " " flat "${output}")
if(NOT flat MATCHES "${EXPECT}")
  message(FATAL_ERROR "case ${CASE}: the message does not match '${EXPECT}'")
endif()
message(STATUS "case ${CASE}: stopped at configure time with the expected message")
