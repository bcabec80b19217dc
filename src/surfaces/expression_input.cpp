#include "surfaces/expression_input.h"

#include "surfaces/expression_syntax.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace offsetgen {
namespace {

const std::set<std::string>& smooth_functions() {
  static const std::set<std::string> names(accepted_functions().begin(), accepted_functions().end());
  return names;
}

// Integer exponents beyond this are refused: x^n is lowered to about 2 log2(n) multiplications, but
// such powers only overflow or underflow in the cell, and GiNaC's int conversion has a limit.
constexpr long kMaxIntegerExponent = 10000;
// Decimal exponents beyond this are refused before the exact rational is spelled out: 1e400 already
// exceeds double, and 1e99999999 would be a hundred million digits.
constexpr long kMaxDecimalExponent = 1000;

std::string to_text(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

// Names people write for constants that the parser spells differently.
std::optional<std::string> constant_hint(const std::string& name) {
  if (name == "pi" || name == "PI") return "write Pi for the constant pi";
  if (name == "e" || name == "E") return "write exp(1) for Euler's number";
  if (name == "I" || name == "i") return "offsetgen works with real functions only";
  return std::nullopt;
}

const std::set<std::string>& non_smooth_functions() {
  static const std::set<std::string> names = {"abs",  "fabs", "floor", "ceil",      "round", "trunc",
                                              "step", "sign", "csgn",  "heaviside", "min",   "max",
                                              "fmin", "fmax", "mod",   "fmod",      "frac"};
  return names;
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Decimal literal -> "(p/q)" so GiNaC keeps it exact. Integers are left alone.
std::string exact_decimal(const std::string& literal, const std::string& what, int column) {
  std::string mantissa = literal;
  long exponent = 0;
  if (auto e = mantissa.find_first_of("eE"); e != std::string::npos) {
    const std::string digits = mantissa.substr(e + 1);
    const bool negative = digits[0] == '-';
    const size_t first = digits.find_first_not_of("+-0");
    const std::string magnitude = first == std::string::npos ? "0" : digits.substr(first);
    if (magnitude.size() > 6 || std::stol(magnitude) > kMaxDecimalExponent)
      throw InputError(fmt::format("{}: the number '{}' at column {} is out of range (exponents from -{} to {})", what,
                                   literal, column, kMaxDecimalExponent, kMaxDecimalExponent));
    exponent = negative ? -std::stol(magnitude) : std::stol(magnitude);
    mantissa = mantissa.substr(0, e);
  }
  std::string digits;
  long fraction_digits = 0;
  bool after_point = false;
  for (char c : mantissa) {
    if (c == '.') {
      after_point = true;
    } else {
      digits += c;
      if (after_point) ++fraction_digits;
    }
  }
  long ten_power = exponent - fraction_digits;
  std::string numerator = digits.empty() ? "0" : digits;
  std::string denominator = "1";
  if (ten_power >= 0) {
    numerator += std::string(static_cast<size_t>(ten_power), '0');
  } else {
    denominator += std::string(static_cast<size_t>(-ten_power), '0');
  }
  return fmt::format("({}/{})", numerator, denominator);
}

struct Scan {
  std::string rewritten;                    // decimals replaced by exact rationals
  std::set<std::string> identifiers;        // names not followed by '('
  std::map<std::string, int> first_column;  // where each identifier first appears
};

// One pass over the text: rejects unsupported and non-smooth functions with their column, and
// collects free identifiers so unknown parameters can be named before GiNaC sees the text.
Scan scan_expression(const std::string& text, const std::string& what) {
  // GiNaC's own parse errors say "line 0, column 0"; this pass points at the column.
  if (auto problem = find_syntax_problem(text))
    throw InputError(fmt::format("cannot parse {}: {} at column {}:\n{}", what, problem->message, problem->column,
                                 caret_line(text, problem->column, 4)));
  if (text.find('\0') != std::string::npos) throw InputError(fmt::format("{} contains a NUL byte", what));
  Scan scan;
  size_t i = 0;
  while (i < text.size()) {
    char c = text[i];
    if (is_ident_start(c)) {
      size_t start = i;
      while (i < text.size() && is_ident_char(text[i])) ++i;
      std::string ident = text.substr(start, i - start);
      size_t next = i;
      while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
      bool is_call = next < text.size() && text[next] == '(';
      if (is_call) {
        if (non_smooth_functions().count(ident)) {
          throw InputError(
              fmt::format("{} uses the non-smooth function '{}' at column {}: offsets of order m need continuous "
                          "derivatives of order m+1",
                          what, ident, column_of(text, start)));
        }
        if (!smooth_functions().count(ident)) {
          throw InputError(fmt::format("{} calls unknown function '{}' at column {}; accepted: {}", what, ident,
                                       column_of(text, start), accepted_syntax_summary()));
        }
      } else {
        if (auto hint = constant_hint(ident))
          throw InputError(fmt::format("{} uses the unknown name '{}' at column {}: {}", what, ident,
                                       column_of(text, start), *hint));
        scan.identifiers.insert(ident);
        scan.first_column.emplace(ident, column_of(text, start));
      }
      scan.rewritten += ident;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
      size_t start = i;
      bool decimal = false;
      while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) {
        decimal |= text[i] == '.';
        ++i;
      }
      if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        size_t e = i + 1;
        if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
        if (e < text.size() && std::isdigit(static_cast<unsigned char>(text[e]))) {
          decimal = true;
          i = e;
          while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        }
      }
      std::string literal = text.substr(start, i - start);
      if (std::count(literal.begin(), literal.end(), '.') > 1) {
        throw InputError(fmt::format("{}: malformed number '{}' at column {}", what, literal, column_of(text, start)));
      }
      scan.rewritten += decimal ? exact_decimal(literal, what, column_of(text, start)) : literal;
    } else {
      if (c == '*' && i + 1 < text.size() && text[i + 1] == '*') {  // accept Python's ** too
        scan.rewritten += '^';
        i += 2;
        continue;
      }
      scan.rewritten += c;
      ++i;
    }
  }
  return scan;
}

// GiNaC appends "[function(file:line)]" to its messages and starts some with "power::eval(): ":
// the user needs neither.
std::string without_source_location(const std::string& message) {
  std::string out = message.substr(0, message.find("\n["));
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  if (auto colon = out.find("(): "); colon != std::string::npos && out.find(' ') > colon) out = out.substr(colon + 4);
  return out;
}

// A power of two numbers is computed exactly by GiNaC: beyond this many bits it would take minutes and
// gigabytes (33333^33333333332 did, found by fuzzing), and no such constant fits a double anyway.
constexpr long kMaxConstantBits = 100000;

// b^e, refusing exponents beyond kMaxIntegerExponent and exact numbers beyond kMaxConstantBits, and
// 0 to a negative power before GiNaC throws from inside its evaluation (where it leaks the object).
GiNaC::ex checked_power(const GiNaC::ex& base, const GiNaC::ex& exponent, const std::string& what) {
  if (base.is_zero() && GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_real() &&
      !GiNaC::ex_to<GiNaC::numeric>(exponent).is_positive())
    throw std::domain_error(exponent.is_zero() ? std::string("0^0 is undefined")
                                               : fmt::format("division by zero (0^{})", to_text(exponent)));
  if (GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_rational()) {
    const auto& e = GiNaC::ex_to<GiNaC::numeric>(exponent);
    const GiNaC::numeric limit(kMaxIntegerExponent);
    if (GiNaC::abs(e.numer()) > limit || e.denom() > limit)
      throw InputError(fmt::format("{}: the exponent {} is too large (at most {} in magnitude)", what, to_text(e),
                                   kMaxIntegerExponent));
    if (GiNaC::is_a<GiNaC::numeric>(base) && GiNaC::ex_to<GiNaC::numeric>(base).is_rational()) {
      const auto& b = GiNaC::ex_to<GiNaC::numeric>(base);
      const long bits = std::max(b.numer().int_length(), b.denom().int_length());
      if (static_cast<double>(bits) * GiNaC::abs(e.numer()).to_double() > static_cast<double>(kMaxConstantBits))
        throw InputError(
            fmt::format("{}: the number {}^{} is too large to compute exactly", what, to_text(b), to_text(e)));
    }
  }
  return GiNaC::pow(base, exponent);
}

// Builds the expression from text that find_syntax_problem accepted and scan_expression rewrote
// (decimals as (p/q), ** as ^): the same grammar, with every power checked before GiNaC computes it.
class ExpressionBuilder {
 public:
  ExpressionBuilder(const std::string& text, const GiNaC::symtab& table, const std::string& what)
      : s_(text), table_(table), what_(what) {}
  GiNaC::ex build() { return expression(); }

 private:
  char peek() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  GiNaC::ex expression() {
    GiNaC::ex acc = term();
    for (char c = peek(); c == '+' || c == '-'; c = peek()) {
      ++i_;
      const GiNaC::ex t = term();
      acc = c == '+' ? acc + t : acc - t;
    }
    return acc;
  }
  GiNaC::ex term() {
    GiNaC::ex acc = unary();
    for (char c = peek(); c == '*' || c == '/'; c = peek()) {
      ++i_;
      const GiNaC::ex u = unary();
      if (c == '/' && u.is_zero()) throw std::domain_error("division by zero");
      acc = c == '*' ? acc * u : acc / u;
    }
    return acc;
  }
  GiNaC::ex unary() {
    const char c = peek();
    if (c == '+' || c == '-') {
      ++i_;
      const GiNaC::ex u = unary();
      return c == '+' ? u : -u;
    }
    return power();
  }
  GiNaC::ex power() {
    const GiNaC::ex base = primary();
    if (peek() != '^') return base;
    ++i_;
    return checked_power(base, unary(), what_);
  }
  GiNaC::ex primary() {
    const char c = peek();
    if (c == '(') {
      ++i_;
      const GiNaC::ex e = expression();
      peek();
      ++i_;  // ')'
      return e;
    }
    const size_t start = i_;
    if (std::isdigit(static_cast<unsigned char>(c))) {
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
      return GiNaC::numeric(s_.substr(start, i_ - start).c_str());
    }
    while (i_ < s_.size() && is_ident_char(s_[i_])) ++i_;
    const std::string name = s_.substr(start, i_ - start);
    if (peek() != '(') return table_.at(name);
    ++i_;
    std::vector<GiNaC::ex> args = {expression()};
    while (peek() == ',') {
      ++i_;
      args.push_back(expression());
    }
    peek();
    ++i_;  // ')'
    if (name == "atan2") {
      if (args.size() != 2)
        throw InputError(
            fmt::format("{}: atan2() takes two arguments, atan2(y, x): the angle of the point (x, y)", what_));
      return GiNaC::atan2(args[0], args[1]);
    }
    if (args.size() != 1) throw InputError(fmt::format("{}: {}() takes one argument", what_, name));
    return call(name, args[0]);
  }
  static GiNaC::ex call(const std::string& name, const GiNaC::ex& a) {
    if (name == "sin") return GiNaC::sin(a);
    if (name == "cos") return GiNaC::cos(a);
    if (name == "tan") return GiNaC::tan(a);
    if (name == "exp") return GiNaC::exp(a);
    if (name == "log") return GiNaC::log(a);
    if (name == "sqrt") return GiNaC::sqrt(a);
    if (name == "sinh") return GiNaC::sinh(a);
    if (name == "cosh") return GiNaC::cosh(a);
    if (name == "tanh") return GiNaC::tanh(a);
    if (name == "atan") return GiNaC::atan(a);
    if (name == "asin") return GiNaC::asin(a);
    if (name == "acos") return GiNaC::acos(a);
    throw std::logic_error("ExpressionBuilder: function '" + name + "' passed the scan");
  }

  const std::string& s_;
  const GiNaC::symtab& table_;
  const std::string& what_;
  size_t i_ = 0;
};

// `original` is the text as the user gave it (for messages), `rewritten` what the builder reads.
GiNaC::ex parse_with(const std::string& original, const std::string& rewritten, const GiNaC::symtab& table,
                     const std::string& what) {
  try {
    return ExpressionBuilder(rewritten, table, what).build();
  } catch (const InputError&) {
    throw;
  } catch (const GiNaC::pole_error& e) {  // log(0), tan(Pi/2)
    throw InputError(
        fmt::format("cannot evaluate {} '{}': a function meets a pole at a constant argument, where its "
                    "value is infinite ({})",
                    what, printable(original), without_source_location(e.what())));
  } catch (const std::exception& e) {  // GiNaC's own, e.g. power::eval(): division by zero
    throw InputError(
        fmt::format("cannot parse {} '{}': {}", what, printable(original), without_source_location(e.what())));
  }
}

void require_real(const GiNaC::ex& e, const std::string& what);

GiNaC::ex parse_constant(const std::string& name, const std::string& text) {
  Scan scan = scan_expression(text, fmt::format("parameter {}", name));
  GiNaC::symtab table;
  table["Pi"] = GiNaC::Pi;
  for (const auto& ident : scan.identifiers) {
    if (!table.count(ident)) {
      throw InputError(fmt::format("parameter {}={} must be a constant, but uses '{}'", name, printable(text), ident));
    }
  }
  GiNaC::ex value = parse_with(text, scan.rewritten, table, fmt::format("parameter {}", name));
  require_real(value, fmt::format("parameter {}={}", name, printable(text)));
  const GiNaC::ex number = GiNaC::evalf(value);
  if (!GiNaC::is_a<GiNaC::numeric>(number) || !std::isfinite(GiNaC::ex_to<GiNaC::numeric>(number).to_double()))
    throw InputError(
        fmt::format("parameter {}={} is beyond the range of double precision (about 1.8e308)", name, printable(text)));
  return value;
}

// Functions beyond the parser's reach (built by GiNaC itself, e.g. abs from sqrt(x^2)) are caught here.
// (Defined below; also used for parameter values.)
void require_smooth(const GiNaC::ex& e, const std::string& what) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::function>(*it)) continue;
    std::string name = GiNaC::ex_to<GiNaC::function>(*it).get_name();
    if (!smooth_functions().count(name)) {
      throw InputError(fmt::format("{} contains the non-smooth function '{}'", what, name));
    }
  }
}

// A complex constant (GiNaC reads sqrt(-1) as I and log(-1) as I*Pi) means F is not real.
void require_real(const GiNaC::ex& e, const std::string& what) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::numeric>(*it) && !GiNaC::ex_to<GiNaC::numeric>(*it).is_real())
      throw InputError(
          fmt::format("{} is not real: it contains the complex number {} (a square root, logarithm or "
                      "power of a negative constant, such as sqrt(-1) = I)",
                      what, to_text(*it)));
  }
}

// b^e with a varying exponent is exp(e log b): it needs b > 0. A constant base <= 0 never has it (the
// cell check catches varying bases that turn negative). Integer exponents have a size limit.
void require_sound_powers(const GiNaC::ex& e, const std::string& what) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::power>(*it)) continue;
    const GiNaC::ex base = it->op(0), exponent = it->op(1);
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
      const auto& n = GiNaC::ex_to<GiNaC::numeric>(exponent);
      const GiNaC::numeric limit(kMaxIntegerExponent);
      if (n.is_rational() && (GiNaC::abs(n.numer()) > limit || n.denom() > limit))
        throw InputError(fmt::format("{}: the exponent {} in {} is too large (at most {} in magnitude)", what,
                                     to_text(n), to_text(*it), kMaxIntegerExponent));
      continue;
    }
    const GiNaC::ex b = GiNaC::evalf(base);
    if (!GiNaC::is_a<GiNaC::numeric>(b)) continue;
    const auto& value = GiNaC::ex_to<GiNaC::numeric>(b);
    if (value.is_zero())
      throw InputError(
          fmt::format("{} has {}: zero to a varying power is 0 or undefined, and not smooth", what, to_text(*it)));
    if (value.is_real() && value.is_negative())
      throw InputError(fmt::format("{} has {}: a negative number to a varying power is not real", what, to_text(*it)));
  }
}

GiNaC::ex parse_in_cell_coordinates(const std::string& text, const std::map<std::string, std::string>& params,
                                    const std::string& what, std::set<std::string>* unused_params) {
  const Symbols& sym = Symbols::get();
  Scan scan = scan_expression(text, what);
  GiNaC::symtab table;
  table["x"] = sym.x;
  table["y"] = sym.y;
  table["z"] = sym.z;
  table["Pi"] = GiNaC::Pi;
  std::set<std::string> unused;
  for (const auto& [name, value] : params) {
    if (table.count(name) || smooth_functions().count(name) || constant_hint(name))
      throw InputError(
          fmt::format("parameter name '{}' is reserved (coordinates x, y, z, the constant Pi and the "
                      "function names cannot be parameters)",
                      name));
    table[name] = parse_constant(name, value);
    unused.insert(name);
  }
  for (const auto& ident : scan.identifiers) {
    unused.erase(ident);
    if (!table.count(ident)) {
      throw InputError(fmt::format("{} uses unknown parameter '{}' at column {}; give it a value with --param {}=VALUE",
                                   what, ident, scan.first_column.at(ident), ident));
    }
  }
  if (unused_params) *unused_params = unused;
  GiNaC::ex e = parse_with(text, scan.rewritten, table, what);
  require_smooth(e, what);
  require_real(e, what);
  require_sound_powers(e, what);
  return e;
}

}  // namespace

const std::vector<std::string>& accepted_functions() {
  static const std::vector<std::string> names = {"acos", "asin", "atan", "atan2", "cos", "cosh", "exp",
                                                 "log",  "sin",  "sinh", "sqrt",  "tan", "tanh"};
  return names;
}

std::string accepted_syntax_summary() {
  std::string list;
  for (const auto& f : accepted_functions()) list += (list.empty() ? "" : " ") + f;
  return list + "; the constant Pi; + - * / ^ (or **) and parentheses";
}

const Symbols& Symbols::get() {
  static const Symbols symbols;
  return symbols;
}

std::pair<std::string, std::string> split_param(const std::string& assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == assignment.size()) {
    throw InputError(fmt::format("malformed parameter '{}': expected NAME=VALUE", assignment));
  }
  std::string name = assignment.substr(0, eq);
  if (!is_ident_start(name[0]) || !std::all_of(name.begin(), name.end(), is_ident_char)) {
    throw InputError(fmt::format("malformed parameter name '{}'", name));
  }
  return {name, assignment.substr(eq + 1)};
}

std::map<std::string, std::string> parse_params(const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> params;
  for (const auto& a : assignments) {
    auto [name, value] = split_param(a);
    if (!params.emplace(name, value).second) throw InputError(fmt::format("parameter '{}' given twice", name));
  }
  return params;
}

Surface parse_natural_expression(const std::string& text) {
  const Symbols& sym = Symbols::get();
  GiNaC::symtab table;
  table["X"] = sym.X;
  table["Y"] = sym.Y;
  table["Z"] = sym.Z;
  Surface surface;
  GiNaC::parser reader(table, true);  // the catalog's own formulas
  surface.field = reader(text);
  surface.scale = 2 * GiNaC::Pi;
  surface.dims = surface.field.has(sym.Z) ? 3 : 2;
  surface.source_expr = text;
  surface.formula = text + "   with X = 2*pi*x, Y = 2*pi*y, Z = 2*pi*z";
  return surface;
}

Surface parse_user_expression(const std::string& text, const std::map<std::string, std::string>& params,
                              const std::string& name) {
  const Symbols& sym = Symbols::get();
  std::set<std::string> unused;
  GiNaC::ex cell = parse_in_cell_coordinates(text, params, "expression", &unused);
  if (!unused.empty()) {
    throw InputError(fmt::format("parameter '{}' is given but the expression does not use it", *unused.begin()));
  }
  if (!cell.has(sym.x) && !cell.has(sym.y) && !cell.has(sym.z)) {
    throw InputError(fmt::format("expression '{}' does not depend on x, y or z", printable(text)));
  }
  Surface surface;
  surface.name = name;
  surface.title = "user expression";
  surface.formula = text;
  surface.source_expr = text;
  surface.params = params;
  surface.citation = "user supplied";
  surface.dims = cell.has(sym.z) ? 3 : 2;

  // Absorb 2*pi into the coordinates when that removes every pi (METHOD.md, scaling identity):
  // derivatives then carry no 2*pi factors and the emitted code multiplies x by 2*pi once.
  GiNaC::ex two_pi = 2 * GiNaC::Pi;
  GiNaC::ex natural = cell.subs(GiNaC::lst{sym.x == sym.X / two_pi, sym.y == sym.Y / two_pi, sym.z == sym.Z / two_pi});
  if (cell.has(GiNaC::Pi) && !natural.has(GiNaC::Pi)) {
    surface.scale = two_pi;
  } else {
    surface.scale = 1;
    natural = cell.subs(GiNaC::lst{sym.x == sym.X, sym.y == sym.Y, sym.z == sym.Z});
  }
  surface.field = natural;
  return surface;
}

GiNaC::ex parse_coordinate_expression(const std::string& text, const std::map<std::string, std::string>& params,
                                      const std::string& what) {
  return parse_in_cell_coordinates(text, params, what, nullptr);
}

GiNaC::ex parse_thickness_expression(const std::string& text, const std::map<std::string, std::string>& params,
                                     int dims) {
  const Symbols& sym = Symbols::get();
  GiNaC::ex t = parse_in_cell_coordinates(text, params, "thickness expression", nullptr);
  if (dims == 2 && t.has(sym.z)) throw InputError("thickness expression uses z, but the surface is 2D");
  return t;
}

}  // namespace offsetgen
