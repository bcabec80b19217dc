// Linked into test and benchmark executables only, never into `offsetgen`: they call the generator in
// process, from build directories where no share/offsetgen sits beside them, so they read the plot
// script from the source tree. The installed tool knows no source path (check/plot.cpp looks this
// hook up as a weak symbol; the templates are compiled in).
#ifndef OFFSETGEN_SOURCE_DIR
#error "OFFSETGEN_SOURCE_DIR must name the source tree"
#endif

extern "C" const char* offsetgen_source_dir() { return OFFSETGEN_SOURCE_DIR; }
