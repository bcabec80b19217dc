// Linked into test and benchmark executables only, never into `offsetgen`: they call the generator in
// process, from build directories where no share/offsetgen sits beside them, so they read templates
// and tools from the source tree. The installed tool knows no source path (emit/templates.cpp,
// check/plot.cpp look this hook up as a weak symbol).
#ifndef OFFSETGEN_SOURCE_DIR
#error "OFFSETGEN_SOURCE_DIR must name the source tree"
#endif

extern "C" const char* offsetgen_source_dir() { return OFFSETGEN_SOURCE_DIR; }
