// Helpers of the check tests: generate files into a scratch directory, run the CLI.
#pragma once

#include "check/compile.h"
#include "check/metadata.h"
#include "pipeline/generate.h"

#include <memory>
#include <string>
#include <vector>

namespace offsetgen::check::testing {

// A fresh empty directory under the build tree, per test and process.
std::string scratch_dir(const std::string& name);

// Generates `surface` at `order` (optionally graded) and writes the C header (or the GLSL snippet)
// into `dir`; returns the path.
std::string write_header(const std::string& dir, const std::string& surface, int order,
                         const std::string& thickness = "", bool glsl = false,
                         const std::string& method = kDefaultMethod);

std::string read_text(const std::string& path);
void write_text(const std::string& path, const std::string& text);

// A generated header compiled (strict C99, -O0 for speed) and loaded, with its metadata.
struct Compiled {
  std::string path;
  FileMetadata meta;
  CompileResult result;
  const LoadedFunctions& functions() const { return result.library->functions(); }
};
std::unique_ptr<Compiled> compile_catalog(const std::string& surface, int order, const std::string& thickness = "",
                                          const std::string& method = kDefaultMethod);

struct CliResult {
  int exit_code = -1;
  std::string output;
};
// Runs the built offsetgen with `args` (no shell).
CliResult run_offsetgen(const std::vector<std::string>& args);

}  // namespace offsetgen::check::testing
