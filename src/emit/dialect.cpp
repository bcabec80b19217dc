#include "emit/dialect.h"

#include <fmt/format.h>

#include <cmath>

namespace offsetgen {
namespace {

// Makes sure a printed number reads as a floating literal in C and GLSL ES: "2" -> "2.0",
// "1e-05" -> "1.0e-05" (GLSL ES has no implicit int -> float conversion).
std::string floating_form(std::string text) {
  if (text.find_first_of(".ni") != std::string::npos) return text;  // has a point, or inf/nan
  auto e = text.find_first_of("eE");
  if (e == std::string::npos) return text + ".0";
  return text.substr(0, e) + ".0" + text.substr(e);
}

}  // namespace

std::string Dialect::real_type() const {
  if (language == Language::Glsl) return "highp float";
  return precision == Precision::Double ? "double" : "float";
}

std::string Dialect::local_decl() const {
  if (language == Language::Glsl) return "highp float";
  return "const " + real_type();
}

std::string Dialect::bool_decl() const { return language == Language::Glsl ? "bool" : "const int"; }

std::string Dialect::suffix() const { return language == Language::C && precision == Precision::Float ? "f" : ""; }

std::string Dialect::literal(double value) const {
  // A quiet NaN: only the density relations return one, out of their range.
  if (std::isnan(value)) {
    if (language == Language::Glsl) return "intBitsToFloat(0x7fc00000)";
    return precision == Precision::Double ? "nan(\"\")" : "nanf(\"\")";
  }
  std::string text;
  if (language == Language::C && precision == Precision::Double) {
    text = floating_form(fmt::format("{:.17g}", value));
  } else {
    // 9 significant digits round-trip every float.
    text = floating_form(fmt::format("{:.9g}", static_cast<double>(static_cast<float>(value))));
    if (language == Language::C) text += "f";
  }
  return value < 0 ? "(" + text + ")" : text;
}

std::string Dialect::function(Fn fn) const { return function_name(fn) + suffix(); }
std::string Dialect::sqrt_name() const { return "sqrt" + suffix(); }
std::string Dialect::abs_name() const { return language == Language::Glsl ? "abs" : "fabs" + suffix(); }
std::string Dialect::pow_name() const { return "pow" + suffix(); }

}  // namespace offsetgen
