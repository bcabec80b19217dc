#include "emit/call_rewrites.h"

#include <fmt/format.h>

#include <cctype>
#include <map>
#include <regex>
#include <vector>

namespace offsetgen {
namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `name(` starts at `at` as a call (not the tail of a longer identifier such as asin).
bool call_at(const std::string& text, size_t at, const std::string& name) {
  return text.compare(at, name.size(), name) == 0 && (at == 0 || !identifier_char(text[at - 1])) &&
         at + name.size() < text.size() && text[at + name.size()] == '(';
}

// The argument of the call whose '(' is at `open`, up to its matching ')'; npos-free: the printer
// balances every parenthesis.
std::string argument_at(const std::string& text, size_t open) {
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')' && --depth == 0) return text.substr(open + 1, i - open - 1);
  }
  return text.substr(open + 1);
}

// Every call of `name` in `text` -> its argument, in order of appearance.
std::vector<std::string> arguments_of(const std::string& text, const std::string& name) {
  std::vector<std::string> found;
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
    if (call_at(text, at, name)) found.push_back(argument_at(text, at + name.size()));
  return found;
}

// `text` with every call `name(argument)` replaced by `replacement`; `first` is lowered to the
// position of the earliest one.
std::string replace_call(const std::string& text, const std::string& name, const std::string& argument,
                         const std::string& replacement, size_t& first) {
  const std::string call = name + "(" + argument + ")";
  std::string out;
  size_t from = 0;
  for (size_t at = text.find(call); at != std::string::npos; at = text.find(call, at + 1)) {
    if (at > 0 && identifier_char(text[at - 1])) continue;
    if (at < from) continue;
    first = std::min(first, out.size() + (at - from));
    out.append(text, from, at - from);
    out += replacement;
    from = at + call.size();
  }
  out.append(text, from, std::string::npos);
  return out;
}

}  // namespace

std::string fuse_sincos(const std::string& body, const std::string& sin_name, const std::string& cos_name,
                        const SincosDeclaration& declare, const std::string& stem) {
  std::string text = body;
  for (int k = 0;; ++k) {
    // The first argument that both functions take, innermost first: one without calls of either.
    std::string shared;
    bool found = false;
    const std::vector<std::string> cos_arguments = arguments_of(text, cos_name);
    for (const auto& argument : arguments_of(text, sin_name)) {
      if (!arguments_of(argument, sin_name).empty() || !arguments_of(argument, cos_name).empty()) continue;
      for (const auto& other : cos_arguments)
        if (other == argument) found = true;
      if (found) {
        shared = argument;
        break;
      }
    }
    if (!found) return text;
    const std::string sin_var = fmt::format("_s{}{}", stem, k), cos_var = fmt::format("_c{}{}", stem, k);
    size_t first = std::string::npos;
    text = replace_call(text, sin_name, shared, sin_var, first);
    text = replace_call(text, cos_name, shared, cos_var, first);
    const size_t line_start = text.rfind('\n', first);
    const size_t insert_at = line_start == std::string::npos ? 0 : line_start + 1;
    text.insert(insert_at, declare(shared, sin_var, cos_var));
  }
}

namespace {

// "const T _tB = 1.0 / _tA;" where "const T _tA = sqrt(e);" -> "const T _tB = rsqrt(e);": the square
// root stays for _tA's other uses, the division goes.
std::string reciprocal_temporaries(const std::string& body, const std::string& sqrt_name,
                                   const std::string& rsqrt_name) {
  static const std::regex reciprocal(R"((const (?:double|float) _t\d+ = )1\.0f? / (_t\d+);)");
  std::string out;
  auto from = body.cbegin();
  for (std::sregex_iterator it(body.begin(), body.end(), reciprocal), end; it != end; ++it) {
    const std::string definition = " " + (*it)[2].str() + " = " + sqrt_name + "(";
    const size_t at = body.find(definition);
    if (at == std::string::npos || static_cast<long>(at) > it->position()) continue;
    const size_t open = at + definition.size() - 1;
    const std::string argument = argument_at(body, open);
    if (body.compare(open + argument.size() + 1, 2, ");") != 0) continue;  // sqrt(e) is the whole definition
    out.append(from, (*it)[0].first);
    out += (*it)[1].str() + rsqrt_name + "(" + argument + ");";
    from = (*it)[0].second;
  }
  out.append(from, body.cend());
  return out;
}

}  // namespace

std::string use_rsqrt(const std::string& input, const std::string& sqrt_name, const std::string& rsqrt_name) {
  const std::string body = reciprocal_temporaries(input, sqrt_name, rsqrt_name);
  const std::string divide = " / " + sqrt_name + "(";
  std::string out;
  size_t from = 0;
  for (size_t at = body.find(divide); at != std::string::npos; at = body.find(divide, at + 1)) {
    // A dividend of exactly 1 ("1.0", "1.0f") after a space or a parenthesis disappears.
    size_t start = at;
    while (start > from && (std::isalnum(static_cast<unsigned char>(body[start - 1])) || body[start - 1] == '.'))
      --start;
    const std::string dividend = body.substr(start, at - start);
    const bool one =
        (dividend == "1.0" || dividend == "1.0f") && start > 0 && (body[start - 1] == ' ' || body[start - 1] == '(');
    out.append(body, from, (one ? start : at) - from);
    out += one ? rsqrt_name + "(" : " * " + rsqrt_name + "(";
    from = at + divide.size();
  }
  out.append(body, from, std::string::npos);
  return out;
}

}  // namespace offsetgen
