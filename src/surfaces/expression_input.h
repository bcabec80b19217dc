// Turning text (catalog formulas, --expr, --param, --thickness) into GiNaC expressions.
#pragma once

#include "surfaces/surface.h"

#include <map>
#include <string>
#include <vector>

namespace offsetgen {

// A catalog formula in natural coordinates X, Y, Z (= 2*pi*x, ...).
Surface parse_natural_expression(const std::string& text);

// A user surface in cell coordinates x, y[, z] with named constant parameters (name -> value text).
// Decimal literals are read as exact rationals, so 0.3 stays 3/10 and prints losslessly.
// Throws InputError naming the problem and, where it has one, the column.
Surface parse_user_expression(const std::string& text, const std::map<std::string, std::string>& params,
                              const std::string& name);

// A wall thickness t(x, y, z) in cell units, for graded walls.
GiNaC::ex parse_thickness_expression(const std::string& text, const std::map<std::string, std::string>& params,
                                     int dims);

// An expression of x, y, z with named constant parameters (a --map component); `what` names it in
// messages. Unused parameters are allowed.
GiNaC::ex parse_coordinate_expression(const std::string& text, const std::map<std::string, std::string>& params,
                                      const std::string& what);

// "a=0.3" -> {"a", "0.3"}; throws InputError on a malformed entry.
std::pair<std::string, std::string> split_param(const std::string& assignment);

// Repeated --param NAME=VALUE entries as a map; throws InputError for a malformed entry or a name given
// twice.
std::map<std::string, std::string> parse_params(const std::vector<std::string>& assignments);

// The functions --expr, --param and --thickness accept, in alphabetical order. Every other name
// followed by '(' is refused by name; the only constant is Pi.
const std::vector<std::string>& accepted_functions();

// "sin cos ... ; constant Pi; + - * / ^ (or **)": for --help and messages.
std::string accepted_syntax_summary();

}  // namespace offsetgen
