// Writes the catalog's sweep table (lowering/catalog_sweeps.h) with the sweep code itself, so that
// the table is what a run without it would compute.
#pragma once

#include "lowering/catalog_sweeps.h"

#include <string>
#include <vector>

namespace offsetgen {

// Sweeps every catalog surface as a run without the table does: require_defined_on_cell (throws
// InputError if a formula is not defined on the cell), swept_cell_bounds and min_gradient_in_bands.
std::vector<CatalogSweeps> sweep_catalog();

// The text of lowering/catalog_sweeps.inc for `entries`: exact hexadecimal floats, %.17g beside them.
std::string catalog_sweeps_source(const std::vector<CatalogSweeps>& entries);

}  // namespace offsetgen
