# lib3mf (Debian lib3mf-dev), for 3MF bodies (src/body) and 3MF output (src/mesh). Its pkg-config file
# names -lzip, which only libzip-dev provides, so the library is found directly.
#   offsetgen_use_lib3mf(<target> <source> <what>)
# links <target> to lib3mf and defines OFFSETGEN_HAVE_LIB3MF on <source> (in the calling directory),
# or says that <what> is off.
find_path(OFFSETGEN_LIB3MF_INCLUDE_DIR Model/COM/NMR_DLLInterfaces.h PATH_SUFFIXES lib3mf)
find_library(OFFSETGEN_LIB3MF_LIBRARY NAMES 3MF lib3MF)

function(offsetgen_use_lib3mf target source what)
  if(OFFSETGEN_LIB3MF_INCLUDE_DIR AND OFFSETGEN_LIB3MF_LIBRARY)
    message(STATUS "offsetgen: ${what} on (${OFFSETGEN_LIB3MF_LIBRARY})")
    target_include_directories(${target} SYSTEM PRIVATE ${OFFSETGEN_LIB3MF_INCLUDE_DIR})
    target_link_libraries(${target} PRIVATE ${OFFSETGEN_LIB3MF_LIBRARY})
    set_source_files_properties(${source} PROPERTIES COMPILE_DEFINITIONS OFFSETGEN_HAVE_LIB3MF)
  else()
    message(STATUS "offsetgen: ${what} off, lib3mf not found (apt-get install lib3mf-dev)")
  endif()
endfunction()
