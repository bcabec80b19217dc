// Helpers of the check tests: generate files into a scratch directory and compile them; running
// the CLI, scratch directories and files come from tests/support.
#pragma once

#include "check/thickness.h"
#include "offsetgen_test_support.h"
#include "pipeline/generate.h"
#include "run/c_library.h"
#include "run/metadata.h"

#include <memory>
#include <string>
#include <vector>

namespace offsetgen::check::testing {

using test_support::run_offsetgen;
using test_support::scratch_dir;
inline std::string read_text(const std::string& path) { return test_support::read_file(path); }
inline void write_text(const std::string& path, const std::string& text) { test_support::write_file(path, text); }

// Generates `surface` at `order` (optionally graded) and writes the C header (or the GLSL snippet)
// into `dir`; returns the path.
std::string write_header(const std::string& dir, const std::string& surface, int order,
                         const std::string& thickness = "", bool glsl = false,
                         const std::string& method = kDefaultMethod);

// A generated header compiled (strict C99, -O0 for speed) and loaded, with its metadata.
struct Compiled {
  std::string path;
  run::FileMetadata meta;
  run::CompileResult result;
  const run::LoadedFunctions& functions() const { return result.library->functions(); }
};
std::unique_ptr<Compiled> compile_catalog(const std::string& surface, int order, const std::string& thickness = "",
                                          const std::string& method = kDefaultMethod);

// The paper's measurement (section 5.2.1) at offsets h on a coarser grid than the paper's: grid 11
// (x, y step 0.1) by default, 21 for the paper's 0.05; 100 scan steps per ray.
ThicknessOptions thickness_options(std::vector<double> h, int grid = 11);

// One column of a sweep's table: the mean of `member` at each h.
std::vector<double> column(const ThicknessReport& r, ErrorStats SweepRow::*member);

}  // namespace offsetgen::check::testing
