// Where an expression stops being well formed, for error messages that point at the column
// (GiNaC's parser reports line 0, column 0 for every syntax error).
#pragma once

#include <optional>
#include <string>

namespace offsetgen {

struct SyntaxProblem {
  int column = 0;  // 1-based column in the text as given
  std::string message;
};

// A recursive-descent pass over the usual grammar (numbers, names, calls, + - * / ^ **, parentheses).
// nullopt when the text is well formed; semantic problems (unknown names) are left to the core.
std::optional<SyntaxProblem> find_syntax_problem(const std::string& text);

// "  0.1*x+*2\n         ^" style pointer under the offending column.
std::string caret_line(const std::string& text, int column, int indent);

}  // namespace offsetgen
