// A backend at one precision: what the body printer asks (emit/printer.cpp). Precision is dialect
// state, as in SymEngine's printers: the float C dialect gets `f` literals and sinf-style names.
#pragma once

#include "emit/backend.h"
#include "lowering/program.h"

#include <string>

namespace offsetgen {

struct Dialect {
  const Backend* backend = nullptr;
  Precision precision = Precision::Double;

  Dialect(const Backend& b, Precision p) : backend(&b), precision(p) {}
  Dialect(const std::string& language, Precision p) : Dialect(offsetgen::backend(language), p) {}

  std::string real_type() const { return backend->real_type(precision); }
  std::string local_decl() const { return backend->local_decl(precision); }
  std::string bool_decl() const { return backend->bool_decl(); }
  std::string literal(double value) const { return backend->literal(value, precision); }
  std::string function(Fn fn) const { return backend->function(fn, precision); }
  std::string sqrt_name() const { return backend->sqrt_name(precision); }
  std::string abs_name() const { return backend->abs_name(precision); }
  std::string pow_name() const { return backend->pow_name(precision); }
  std::string atan2_name() const { return backend->atan2_name(precision); }
  std::string suffix() const { return backend->suffix(precision); }
};

}  // namespace offsetgen
