#include "surfaces/catalog.h"

#include "surfaces/expression_input.h"

#include <fmt/format.h>

namespace offsetgen {

// Formulas in natural coordinates X = 2*pi*x (cell length 1). gyroid, schwarzp, diamond and
// neovius are exactly the forms of METHOD.md / the paper; the others are the standard nodal
// approximations, with their usual constants written as exact rationals.
const std::vector<CatalogEntry>& catalog() {
  static const std::vector<CatalogEntry> entries = {
      {"gyroid", "Schoen gyroid (G)", "sin(X)*cos(Y) + sin(Y)*cos(Z) + sin(Z)*cos(X)",
       "Schoen 1970, NASA TN D-5541; nodal form: von Schnering & Nesper, Z. Phys. B 83 (1991) 407"},
      {"schwarzp", "Schwarz primitive (P)", "cos(X) + cos(Y) + cos(Z)",
       "Schwarz 1890; nodal form: von Schnering & Nesper, Z. Phys. B 83 (1991) 407"},
      {"diamond", "Schwarz diamond (D)",
       "sin(X)*sin(Y)*sin(Z) + sin(X)*cos(Y)*cos(Z) + cos(X)*sin(Y)*cos(Z) + cos(X)*cos(Y)*sin(Z)",
       "Schwarz 1890; nodal form: von Schnering & Nesper, Z. Phys. B 83 (1991) 407"},
      {"neovius", "Neovius (C(P))", "3*(cos(X) + cos(Y) + cos(Z)) + 4*cos(X)*cos(Y)*cos(Z)",
       "Neovius 1883; nodal form: von Schnering & Nesper, Z. Phys. B 83 (1991) 407"},
      {"iwp", "Schoen I-WP",
       "2*(cos(X)*cos(Y) + cos(Y)*cos(Z) + cos(Z)*cos(X)) - (cos(2*X) + cos(2*Y) + cos(2*Z))",
       "Schoen 1970; nodal form: von Schnering & Nesper, Z. Phys. B 83 (1991) 407"},
      {"fischerkoch", "Fischer-Koch S",
       "cos(2*X)*sin(Y)*cos(Z) + cos(X)*cos(2*Y)*sin(Z) + sin(X)*cos(Y)*cos(2*Z)",
       "Fischer & Koch, Z. Kristallogr. 179 (1987) 31; nodal form: Wohlgemuth et al., "
       "Macromolecules 34 (2001) 6083"},
      {"lidinoid", "Lidinoid",
       "1/2*(sin(2*X)*cos(Y)*sin(Z) + sin(2*Y)*cos(Z)*sin(X) + sin(2*Z)*cos(X)*sin(Y))"
       " - 1/2*(cos(2*X)*cos(2*Y) + cos(2*Y)*cos(2*Z) + cos(2*Z)*cos(2*X)) + 3/20",
       "Lidin & Larsson, J. Chem. Soc. Faraday Trans. 86 (1990) 769; nodal form: Wohlgemuth et al., "
       "Macromolecules 34 (2001) 6083"},
      {"splitp", "Split P",
       "11/10*(sin(2*X)*sin(Z)*cos(Y) + sin(2*Y)*sin(X)*cos(Z) + sin(2*Z)*sin(Y)*cos(X))"
       " - 1/5*(cos(2*X)*cos(2*Y) + cos(2*Y)*cos(2*Z) + cos(2*Z)*cos(2*X))"
       " - 2/5*(cos(2*X) + cos(2*Y) + cos(2*Z))",
       "Fogden & Hyde, Acta Cryst. A 48 (1992) 575; nodal form: Wohlgemuth et al., "
       "Macromolecules 34 (2001) 6083"},
      {"frd", "Schoen F-RD",
       "4*cos(X)*cos(Y)*cos(Z) - (cos(2*X)*cos(2*Y) + cos(2*Y)*cos(2*Z) + cos(2*Z)*cos(2*X))",
       "Schoen 1970; nodal form: von Schnering & Nesper, Z. Phys. B 83 (1991) 407"},
  };
  return entries;
}

Surface catalog_surface(const std::string& name) {
  for (const auto& entry : catalog()) {
    if (name != entry.name) continue;
    Surface surface = parse_natural_expression(entry.formula);
    surface.name = entry.name;
    surface.title = entry.title;
    surface.citation = entry.citation;
    surface.from_catalog = true;
    return surface;
  }
  std::string known;
  for (const auto& entry : catalog()) known += fmt::format("{}{}", known.empty() ? "" : ", ", entry.name);
  throw InputError(fmt::format("unknown surface '{}'; known surfaces: {}", name, known));
}

}  // namespace offsetgen
