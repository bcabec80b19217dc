// What the generation-time sweeps over the cell find for a catalog surface never changes: its
// bounds M and H (cell_bounds.h), that F and its derivatives are defined on the cell
// (validate/cell_domain.h), and projection's Lipschitz band minima. Sweeping them again costs most
// of a catalog run's time, so they are kept in a committed table (catalog_sweeps.inc) that the sweep
// code itself writes: offsetgen_catalog_sweeps (pipeline/catalog_sweep_table.h), run by
// tools/update_golden.sh. tests/core/test_catalog_sweeps.cpp sweeps again and requires the same bits.
#pragma once

#include "lowering/cell_bounds.h"
#include "surfaces/surface.h"

#include <array>
#include <vector>

namespace offsetgen {

struct CatalogSweeps {
  const char* name;     // the catalog name, for people reading the table
  const char* formula;  // CatalogEntry::formula: the values belong to this F
  // cell_bounds with second derivatives; an entry exists only where F, grad F and Hess F are defined
  // on the cell (require_defined_on_cell passed).
  CellBounds bounds;
  // min_gradient_in_bands at lipschitz_band_levels(bounds, 2 pi), one per kLipschitzHalfThicknesses.
  std::array<double, kLipschitzHalfThicknesses.size()> band_minima;
};

// The committed table, in catalog order.
const std::vector<CatalogSweeps>& catalog_sweeps_table();

// The entry of an unmapped catalog surface whose formula the table holds; nullptr for expressions,
// mapped surfaces and anything else, which are swept.
const CatalogSweeps* catalog_sweeps(const Surface& surface);

}  // namespace offsetgen
