// Running external programs (compilers, glslangValidator, the plot script) without a shell.
#pragma once

#include "support/interrupt_cleanup.h"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace offsetgen::run {

struct ProcessResult {
  bool started = false;  // false when the program could not be executed at all
  int exit_code = -1;    // exit status, or 128 + signal number
  std::string output;    // stdout and stderr together, verbatim
};

// Runs argv[0] (looked up on PATH when it has no '/') with the given arguments and waits.
ProcessResult run_process(const std::vector<std::string>& argv);

// Absolute path of an executable named `name` on PATH, or "" when there is none. A name with a
// '/' is returned as is when it is executable.
std::string find_on_path(const std::string& name);

// The Python interpreter: $OFFSETGEN_PYTHON, else /usr/bin/python3 (Debian's, with NumPy and
// matplotlib), else python3 on PATH.
std::string find_python();

// A fresh directory under the system's temporary directory, removed with everything in it when this
// goes out of scope (kept when $OFFSETGEN_CHECK_KEEP is set, for debugging). Throws std::runtime_error
// when it cannot be created. A SIGINT or SIGTERM removes it too, where the executable installed
// install_interrupt_cleanup.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& stem = "offsetgen-check");
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  RemovedOnInterrupt tracked_;  // released after the destructor's removal
};

// Runs `command` followed by two file names: one holding `inputs` as float64, 4 per point, and one the
// program writes, `count` float64 values; returns them. Throws std::runtime_error with the program's
// output when it fails or writes another amount. The files live in `dir`.
std::vector<double> run_on_points(std::vector<std::string> command, const std::filesystem::path& dir,
                                  const std::vector<std::array<double, 4>>& inputs, size_t count);

// Splits a command such as $CC="ccache gcc -m64" into words (whitespace separated, no quoting).
std::vector<std::string> split_words(const std::string& text);

}  // namespace offsetgen::run
