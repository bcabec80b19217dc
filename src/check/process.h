// Running external programs (compilers, glslangValidator, the plot script) without a shell.
#pragma once

#include <string>
#include <vector>

namespace offsetgen::check {

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

// Splits a command such as $CC="ccache gcc -m64" into words (whitespace separated, no quoting).
std::vector<std::string> split_words(const std::string& text);

}  // namespace offsetgen::check
