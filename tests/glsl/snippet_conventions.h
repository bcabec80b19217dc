// Static paste-safety checks of a GLSL snippet (issue 3, "Paste-safety conventions"): what a user
// relies on when pasting the file into an arbitrary host shader, checked on the text alone.
#pragma once

#include <string>
#include <vector>

namespace offsetgen::glsl_test {

struct Violation {
  std::string rule;     // "version", "precision", "guard", "define", "directive", "highp", "pow",
                        // "literal", "prefix", "header"
  std::string message;  // "snippet line N: <what is wrong>: <the line>"
};

// Every convention the snippet breaks; empty when it is paste-safe. `prefix` is the function
// prefix every top-level name must start with (followed by '_').
//   version    no "#version" line: the host owns it;
//   precision  no "precision ..." statement: the host owns it;
//   guard      the whole snippet sits inside "#ifndef G / #define G ... #endif", G naming the prefix;
//   define     no #define except the guard's (no global macros to collide with the host's);
//   directive  no other preprocessor directive (#extension, #pragma, #if, ...);
//   highp      every float/vecN/matN declaration says highp (a mediump host may run fp16);
//   pow        no pow() (undefined for a negative base; the catalog needs integer powers only);
//   literal    every number has a decimal point, "2.0" not "2" (GLSL ES has no int -> float
//              conversion, and the catalog snippets have no integer context at all);
//   prefix     every top-level name (function, global, struct) starts with "<prefix>_".
std::vector<Violation> convention_violations(const std::string& snippet, const std::string& prefix);

// The lygia-style header comment: description, use: with every function, inputs and outputs,
// sign convention, accuracy, targets, the generating command and "generated, do not edit".
std::vector<Violation> header_comment_violations(const std::string& snippet, const std::string& prefix);

// "rule: message" lines, one per violation, for test failure output.
std::string describe(const std::vector<Violation>& violations);

}  // namespace offsetgen::glsl_test
