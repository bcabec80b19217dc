// Prints a straight-line Program as a function body: `const T _tK = ...;` temporaries for every
// node used more than once, single-use nodes inlined, then one expression per output.
#pragma once

#include "emit/dialect.h"
#include "lowering/program.h"

#include <string>
#include <vector>

namespace offsetgen {

struct PrintedBody {
  std::vector<std::string> temporaries;  // complete statements, without indentation
  std::vector<std::string> outputs;      // one expression per program output
};

// `input_names` spells each program input in the target (e.g. "x" in C, "p.x" in GLSL).
PrintedBody print_program(const Program& program, const Dialect& dialect, const std::vector<std::string>& input_names);

}  // namespace offsetgen
