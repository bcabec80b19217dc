#include "lowering/catalog_sweeps.h"

#include <string>

namespace offsetgen {

const std::vector<CatalogSweeps>& catalog_sweeps_table() {
  static const std::vector<CatalogSweeps> table = {
#include "lowering/catalog_sweeps.inc"
  };
  return table;
}

const CatalogSweeps* catalog_sweeps(const Surface& surface) {
  // A mapped surface is F composed with a map over a domain: nothing swept over the cell holds.
  if (!surface.from_catalog || surface.mapped()) return nullptr;
  for (const CatalogSweeps& entry : catalog_sweeps_table())
    if (surface.source_expr == entry.formula) return &entry;
  return nullptr;
}

}  // namespace offsetgen
