// How one target language spells types, literals and math functions. Precision is dialect state,
// as in SymEngine's printers: the float C dialect gets `f` literals and sinf-style names.
#pragma once

#include "lowering/program.h"

#include <string>

namespace offsetgen {

enum class Language { C, Glsl };
enum class Precision { Double, Float };

struct Dialect {
  Language language = Language::C;
  Precision precision = Precision::Double;

  std::string real_type() const;   // "double", "float", "highp float"
  std::string local_decl() const;  // "const double", "highp float" (GLSL const needs constant initialisers)
  std::string bool_decl() const;   // "const int", "bool"
  std::string literal(double value) const;
  std::string function(Fn fn) const;  // "sin", "sinf"
  std::string sqrt_name() const;
  std::string abs_name() const;
  std::string pow_name() const;
  std::string suffix() const;  // appended to function names: "" or "f"
};

}  // namespace offsetgen
