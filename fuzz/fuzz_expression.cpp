// libFuzzer target: the expression front end as `offsetgen generate --expr` runs it. Parse, validate,
// build the offset model at order 2, lower, and print C (double and float) and GLSL.
//
// Input: line 1 is F(x, y[, z]); line 2, if present and not empty, a --thickness expression; further
// lines are --param NAME=VALUE entries. Bad input must come back as InputError (exit 2); any other
// exception is an internal error on user input, which is a finding. Accepted input must print no
// non-finite literal (`inf`, `nan`), which would not compile.
#include "pipeline/generate.h"
#include "surfaces/expression_input.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>

namespace {

// Longer inputs add no new paths; they only slow the fuzzer down.
constexpr size_t kMaxInput = 512;

// The code without its /* */ and // comments (a loop: std::regex recurses per character).
std::string without_comments(const std::string& code) {
  std::string out;
  for (std::size_t i = 0; i < code.size();) {
    if (code.compare(i, 2, "/*") == 0) {
      const std::size_t end = code.find("*/", i + 2);
      i = end == std::string::npos ? code.size() : end + 2;
      out += ' ';
    } else if (code.compare(i, 2, "//") == 0) {
      i = code.find('\n', i);
      if (i == std::string::npos) i = code.size();
    } else {
      out += code[i++];
    }
  }
  return out;
}

// Comments may say "inf" (the batch helpers document what sqrt returns for +inf); code may not.
bool prints_a_non_finite_literal(const std::string& code) {
  static const std::regex literal(R"((^|[^A-Za-z0-9_])(inf|nan)f?([^A-Za-z0-9_]|$))");
  const std::string stripped = without_comments(code);
  std::istringstream lines(stripped);
  for (std::string line; std::getline(lines, line);)
    if (std::regex_search(line, literal)) return true;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > kMaxInput) return 0;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  offsetgen::GenerationRequest request;
  std::getline(lines, request.expression);
  std::string line;
  if (std::getline(lines, line) && !line.empty()) request.thickness = line;
  try {
    while (std::getline(lines, line)) {
      auto [name, value] = offsetgen::split_param(line);
      if (request.params.count(name)) return 0;
      request.params[name] = value;
    }
    request.name = "fuzz";
    request.order = 2;
    request.languages = {"c", "glsl"};
    request.precisions = {offsetgen::Precision::Double, offsetgen::Precision::Float};
    const offsetgen::Generation g = offsetgen::generate(request);
    for (const std::string* code : {&g.c_header(), &g.glsl_snippet()}) {
      if (prints_a_non_finite_literal(*code)) {
        std::fprintf(stderr, "accepted input printed a non-finite literal:\n%s\n", code->c_str());
        std::abort();
      }
    }
  } catch (const offsetgen::InputError&) {
    // a clear input error: what bad input should get
  }
  return 0;
}
