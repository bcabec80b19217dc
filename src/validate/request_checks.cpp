#include "validate/request_checks.h"

#include "emit/emitted_api.h"
#include "lowering/catalog_sweeps.h"
#include "validate/cell_domain.h"
#include "validate/constants.h"
#include "validate/cost_guard.h"
#include "validate/map_checks.h"
#include "validate/names.h"

namespace offsetgen {

void check_before_build(const RequestFacts& facts) {
  const Surface& surface = *facts.surface;
  require_usable_prefix(facts.prefix, facts.languages);
  require_within_size_limits(surface.field, surface.from_catalog ? "the catalog formula" : "the expression");
  require_regular_map(surface);  // before sampling: a singular point would read as undefined
  // A catalog formula's sweep passed when its table entry was written (lowering/catalog_sweeps.h).
  if (!catalog_sweeps(surface)) require_defined_on_cell(surface);
  if (facts.thickness && *facts.thickness) {
    require_within_size_limits(**facts.thickness, "the thickness expression");
    require_positive_thickness(**facts.thickness, surface.dims, facts.thickness_text);
  }
  if (facts.method && facts.method->cost_grows_geometrically())
    require_affordable(*facts.method, surface, facts.order, facts.notice);
}

void check_after_build(const RequestFacts& facts, const OffsetConstruction& construction,
                       const SurfacePrograms& programs) {
  for (const auto& f : emitted_functions(programs, facts.surface->dims, construction.facts()))
    require_within_op_limit(f.suffix, count_ops(*f.program));
  require_representable_constants(programs, construction, facts.surface->dims, facts.float_precision);
}

}  // namespace offsetgen
