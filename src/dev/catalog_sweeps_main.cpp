// offsetgen_catalog_sweeps FILE: sweeps every catalog surface and writes the table that spares
// `offsetgen generate` those sweeps (lowering/catalog_sweeps.h) to FILE, normally
// src/lowering/catalog_sweeps.inc. tools/update_golden.sh runs it; rebuild after it changes the file.
#include "pipeline/catalog_sweep_table.h"

#include <cstdio>
#include <exception>
#include <fstream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s path/to/catalog_sweeps.inc\n", argv[0]);
    return 2;
  }
  try {
    const std::string text = offsetgen::catalog_sweeps_source(offsetgen::sweep_catalog());
    std::ofstream out(argv[1], std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::fprintf(stderr, "offsetgen_catalog_sweeps: cannot write %s\n", argv[1]);
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "offsetgen_catalog_sweeps: %s\n", e.what());
    return 1;
  }
  return 0;
}
