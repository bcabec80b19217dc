// Where an expression stops being well formed, for error messages that point at the column
// (GiNaC's parser reports line 0, column 0 for every syntax error).
#pragma once

#include <optional>
#include <string>

namespace offsetgen {

struct SyntaxProblem {
  int column = 0;  // 1-based column in the text as given, in characters (UTF-8 code points)
  std::string message;
};

// A recursive-descent pass over the usual grammar (numbers, names, calls, + - * / ^ **, parentheses).
// nullopt when the text is well formed; semantic problems (unknown names) are left to the core.
// A chained power such as x^y^z is refused: GiNaC cannot read it and the grouping is ambiguous.
std::optional<SyntaxProblem> find_syntax_problem(const std::string& text);

// "  0.1*x+*2\n         ^" style pointer under the offending column (of column_of).
std::string caret_line(const std::string& text, int column, int indent);

// The 1-based column, in characters, of the byte at `byte_index`: a multi-byte UTF-8 character
// counts once, so carets line up under what the user typed.
int column_of(const std::string& text, size_t byte_index);

// `text` safe to print: valid UTF-8 is kept whole, control characters and bytes that are not
// UTF-8 become \xNN escapes, so an error message never carries a broken byte.
std::string printable(const std::string& text);

}  // namespace offsetgen
