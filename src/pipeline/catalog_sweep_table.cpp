#include "pipeline/catalog_sweep_table.h"

#include "field/atom_table.h"
#include "field/field_atoms.h"
#include "lowering/cell_bounds.h"
#include "surfaces/catalog.h"
#include "validate/cell_domain.h"

#include <fmt/format.h>

namespace offsetgen {

std::vector<CatalogSweeps> sweep_catalog() {
  std::vector<CatalogSweeps> entries;
  for (const CatalogEntry& entry : catalog()) {
    const Surface surface = catalog_surface(entry.name);
    require_defined_on_cell(surface);
    AtomTable atoms;
    const FieldAtoms field = define_field_atoms(surface, 2, atoms);  // second derivatives, as projection's
    CatalogSweeps sweeps{entry.name, entry.formula, swept_cell_bounds(surface, atoms, field), {}};
    const double scale = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
    const std::vector<double> minima =
        min_gradient_in_bands(surface, atoms, field, sweeps.bounds, lipschitz_band_levels(sweeps.bounds, scale));
    std::copy(minima.begin(), minima.end(), sweeps.band_minima.begin());
    entries.push_back(sweeps);
  }
  return entries;
}

std::string catalog_sweeps_source(const std::vector<CatalogSweeps>& entries) {
  std::string text =
      "// Written by offsetgen_catalog_sweeps (tools/update_golden.sh runs it); do not edit by hand.\n"
      "// {name, formula, {M, H}, {least |grad F| in the bands of kLipschitzHalfThicknesses}}\n";
  for (const CatalogSweeps& e : entries) {
    std::string minima, minima_hex;
    for (double g : e.band_minima) {
      minima += fmt::format("{}{:.17g}", minima.empty() ? "" : ", ", g);
      minima_hex += fmt::format("{}{:a}", minima_hex.empty() ? "" : ", ", g);
    }
    text += fmt::format("// {}: M = {:.17g}, H = {:.17g}; band minima {}\n", e.name, e.bounds.gradient,
                        e.bounds.hessian, minima);
    text += fmt::format("{{\"{}\", \"{}\", {{{:a}, {:a}}}, {{{}}}}},\n", e.name, e.formula, e.bounds.gradient,
                        e.bounds.hessian, minima_hex);
  }
  return text;
}

}  // namespace offsetgen
