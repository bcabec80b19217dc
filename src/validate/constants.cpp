#include "validate/constants.h"

#include "emit/emitted_api.h"

#include <fmt/format.h>

#include <cfloat>
#include <cmath>

namespace offsetgen {

void require_representable_constants(const SurfacePrograms& programs, const OffsetConstruction& construction, int dims,
                                     bool need_float) {
  const double hessian_bound = construction.bounds().hessian;
  for (const auto& f : emitted_functions(programs, dims, construction.facts())) {
    for (NodeId id : schedule(*f.program)) {
      const Node& n = f.program->node(id);
      if (n.op != Op::Const) continue;
      if (!std::isfinite(n.value))
        throw InputError(fmt::format(
            "the function _{} would need a constant that is {} in double precision (a value of the expression "
            "beyond 1.8e308, or a division by zero among its constants); it would not compile",
            f.suffix, std::isnan(n.value) ? "not a number" : "infinite"));
      if (need_float && std::fabs(n.value) > double(FLT_MAX))
        throw InputError(fmt::format(
            "the float functions (--precision float, and GLSL) would need the constant {:.6g} in _{}, beyond the "
            "float range (3.4e38){}. Generate double precision only (--precision double --lang c), or change F",
            n.value, f.suffix,
            std::fabs(n.value) >= hessian_bound && hessian_bound > double(FLT_MAX) / 10
                ? fmt::format(": the safeguard's Hessian bound of F over the cell is {:.3g}, so F has a pole or a "
                              "very steep region in the cell",
                              hessian_bound)
                : std::string()));
    }
  }
}

}  // namespace offsetgen
