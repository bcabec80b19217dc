#include "surfaces/expression_input.h"

#include "surfaces/expression_syntax.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>

namespace offsetgen {
namespace {

const std::set<std::string>& smooth_functions() {
  static const std::set<std::string> names = {"sin",  "cos",  "tan",  "exp",  "log", "sqrt",
                                              "sinh", "cosh", "tanh", "atan", "asin", "acos"};
  return names;
}

const std::set<std::string>& non_smooth_functions() {
  static const std::set<std::string> names = {"abs",   "fabs", "floor", "ceil", "round", "trunc", "step",
                                              "sign",  "csgn", "heaviside", "min", "max", "fmin",
                                              "fmax",  "mod",  "fmod",  "frac"};
  return names;
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Decimal literal -> "(p/q)" so GiNaC keeps it exact. Integers are left alone.
std::string exact_decimal(const std::string& literal) {
  std::string mantissa = literal;
  long exponent = 0;
  if (auto e = mantissa.find_first_of("eE"); e != std::string::npos) {
    exponent = std::stol(mantissa.substr(e + 1));
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
  std::string rewritten;               // decimals replaced by exact rationals
  std::set<std::string> identifiers;   // names not followed by '('
};

// One pass over the text: rejects unsupported and non-smooth functions with their column, and
// collects free identifiers so unknown parameters can be named before GiNaC sees the text.
Scan scan_expression(const std::string& text, const std::string& what) {
  // GiNaC's own parse errors say "line 0, column 0"; this pass points at the column.
  if (auto problem = find_syntax_problem(text))
    throw InputError(fmt::format("cannot parse {}: {} at column {}:\n{}", what, problem->message, problem->column,
                                 caret_line(text, problem->column, 4)));
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
          throw InputError(fmt::format(
              "{} uses the non-smooth function '{}' at column {}: offsets of order m need continuous "
              "derivatives of order m+1",
              what, ident, start + 1));
        }
        if (!smooth_functions().count(ident)) {
          std::string known;
          for (const auto& f : smooth_functions()) known += (known.empty() ? "" : ", ") + f;
          throw InputError(fmt::format("{} calls unknown function '{}' at column {}; supported: {}", what,
                                       ident, start + 1, known));
        }
      } else {
        scan.identifiers.insert(ident);
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
        throw InputError(fmt::format("{}: malformed number '{}' at column {}", what, literal, start + 1));
      }
      scan.rewritten += decimal ? exact_decimal(literal) : literal;
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

// GiNaC appends "[function(file:line)]" to its messages: the user needs neither.
std::string without_source_location(const std::string& message) {
  std::string out = message.substr(0, message.find("\n["));
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  return out;
}

// `original` is the text as the user gave it (for messages), `rewritten` what GiNaC reads.
GiNaC::ex parse_with(const std::string& original, const std::string& rewritten, const GiNaC::symtab& table,
                     const std::string& what) {
  try {
    GiNaC::parser reader(table, true);
    return reader(rewritten);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("cannot parse {} '{}': {}", what, original, without_source_location(e.what())));
  }
}

GiNaC::ex parse_constant(const std::string& name, const std::string& text) {
  Scan scan = scan_expression(text, fmt::format("parameter {}", name));
  GiNaC::symtab table;
  table["Pi"] = GiNaC::Pi;
  table["pi"] = GiNaC::Pi;
  for (const auto& ident : scan.identifiers) {
    if (!table.count(ident)) {
      throw InputError(fmt::format("parameter {}={} must be a constant, but uses '{}'", name, text, ident));
    }
  }
  return parse_with(text, scan.rewritten, table, fmt::format("parameter {}", name));
}

// Functions beyond the parser's reach (built by GiNaC itself, e.g. abs from sqrt(x^2)) are caught here.
void require_smooth(const GiNaC::ex& e, const std::string& what) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::function>(*it)) continue;
    std::string name = GiNaC::ex_to<GiNaC::function>(*it).get_name();
    if (!smooth_functions().count(name)) {
      throw InputError(fmt::format("{} contains the non-smooth function '{}'", what, name));
    }
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
  table["pi"] = GiNaC::Pi;
  std::set<std::string> unused;
  for (const auto& [name, value] : params) {
    if (table.count(name)) throw InputError(fmt::format("parameter name '{}' is reserved", name));
    table[name] = parse_constant(name, value);
    unused.insert(name);
  }
  for (const auto& ident : scan.identifiers) {
    unused.erase(ident);
    if (!table.count(ident)) {
      auto col = text.find(ident);
      throw InputError(fmt::format("{} uses unknown parameter '{}' at column {}; give it a value with --param {}=VALUE",
                                   what, ident, col == std::string::npos ? 0 : col + 1, ident));
    }
  }
  if (unused_params) *unused_params = unused;
  GiNaC::ex e = parse_with(text, scan.rewritten, table, what);
  require_smooth(e, what);
  return e;
}

}  // namespace

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

Surface parse_natural_expression(const std::string& text) {
  const Symbols& sym = Symbols::get();
  GiNaC::symtab table;
  table["X"] = sym.X;
  table["Y"] = sym.Y;
  table["Z"] = sym.Z;
  Surface surface;
  surface.field = parse_with(text, text, table, "catalog formula");
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
    throw InputError(fmt::format("expression '{}' does not depend on x, y or z", text));
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
  GiNaC::ex natural =
      cell.subs(GiNaC::lst{sym.x == sym.X / two_pi, sym.y == sym.Y / two_pi, sym.z == sym.Z / two_pi});
  if (cell.has(GiNaC::Pi) && !natural.has(GiNaC::Pi)) {
    surface.scale = two_pi;
  } else {
    surface.scale = 1;
    natural = cell.subs(GiNaC::lst{sym.x == sym.X, sym.y == sym.Y, sym.z == sym.Z});
  }
  surface.field = natural;
  return surface;
}

GiNaC::ex parse_thickness_expression(const std::string& text, const std::map<std::string, std::string>& params,
                                     int dims) {
  const Symbols& sym = Symbols::get();
  GiNaC::ex t = parse_in_cell_coordinates(text, params, "thickness expression", nullptr);
  if (dims == 2 && t.has(sym.z)) throw InputError("thickness expression uses z, but the surface is 2D");
  return t;
}

}  // namespace offsetgen
