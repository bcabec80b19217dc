#include "emit/emitted_api.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace offsetgen {

std::vector<EmittedFunction> emitted_functions(const SurfacePrograms& programs, int dims, const MethodFacts& method) {
  const std::string coords = dims == 3 ? "x, y, z" : "x, y";
  std::vector<EmittedFunction> functions = {
      {"field", &programs.field, "", false, "F, the field; the surface is F = 0.", "(" + coords + ")"},
      {"offset", &programs.offset, "h", false,
       "phi(p, h) of order " + std::to_string(method.order) + ": zero on the surface moved by h along +grad F.",
       "(" + coords + ", h)"},
      {"shell", &programs.shell, "t", false,
       "phi(p, t/2) * phi(p, -t/2): negative inside the wall of total thickness t.", "(" + coords + ", t)"},
  };
  if (!programs.normal.outputs().empty())
    functions.push_back({"normal", &programs.normal, "h", true, method.normal, "(" + coords + ", h" + ")"});
  if (programs.graded) {
    functions.push_back({"graded", &*programs.graded, "", false,
                         "the shell with the --thickness t(p) baked in: negative inside the graded wall.",
                         "(" + coords + ")"});
  }
  return functions;
}

// Distinct prefixes must give distinct guards (foo and FOO, too). An all-lowercase prefix gives the
// usual OFFSETGEN_FOO_H; one with capitals keeps its case and ends in a lowercase extension
// (OFFSETGEN_FOO_h), which no all-lowercase prefix produces.
std::string guard_name(const std::string& prefix, const std::string& extension) {
  const bool has_capitals =
      std::any_of(prefix.begin(), prefix.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); });
  std::string guard = "OFFSETGEN_";
  for (char c : prefix) {
    const auto u = static_cast<unsigned char>(c);
    guard += std::isalnum(u) ? static_cast<char>(has_capitals ? c : std::toupper(u)) : '_';
  }
  guard += "_";
  for (char c : extension)
    guard += static_cast<char>(has_capitals ? std::tolower(static_cast<unsigned char>(c)) : std::toupper(static_cast<unsigned char>(c)));
  return guard;
}

std::string wrap_paragraph(const std::string& text, const std::string& first, const std::string& rest, size_t width) {
  std::istringstream words(text);
  std::string out, line = first, word;
  bool empty = true;
  while (words >> word) {
    if (!empty && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line = rest;
      empty = true;
    }
    line += (empty ? "" : " ") + word;
    empty = false;
  }
  return out + line;
}

}  // namespace offsetgen
