#include "validate/cost_guard.h"

#include "emit/emitted_api.h"
#include "offset/surface_programs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace offsetgen {
namespace {

constexpr double kSecondsPerOp = 25e-6;      // measured: sin^20 at order 4, gyroid at order 10
constexpr double kAnnounceAboveSeconds = 3;  // quieter runs need no estimate

struct Counts {
  long long largest = 0, total = 0;
};

Counts count(const OffsetMethod& method, const Surface& surface, int order) {
  const std::unique_ptr<OffsetConstruction> construction = method.build(surface, order);
  const SurfacePrograms programs = lower_surface(surface, *construction, {});
  Counts c;
  for (const auto& f : emitted_functions(programs, surface.dims, construction->facts())) {
    const long long ops = count_ops(*f.program);
    c.largest = std::max(c.largest, ops);
    c.total += ops;
  }
  return c;
}

// Depth of nested non-polynomial operations (calls, non-integer powers) below `e`, and its node count.
void measure(const GiNaC::ex& e, int depth, int& max_depth, long long& nodes) {
  ++nodes;
  if (nodes > kMaxExpressionNodes) return;
  const bool deepens = GiNaC::is_a<GiNaC::function>(e) ||
                       (GiNaC::is_a<GiNaC::power>(e) &&
                        !(GiNaC::is_a<GiNaC::numeric>(e.op(1)) && GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()));
  depth += deepens ? 1 : 0;
  max_depth = std::max(max_depth, depth);
  for (size_t i = 0; i < e.nops() && nodes <= kMaxExpressionNodes; ++i) measure(e.op(i), depth, max_depth, nodes);
}

}  // namespace

void require_within_size_limits(const GiNaC::ex& e, const std::string& what) {
  int depth = 0;
  long long nodes = 0;
  measure(e, 0, depth, nodes);
  if (nodes > kMaxExpressionNodes)
    throw InputError(
        fmt::format("{} is too large: more than {} terms and operations (the limit keeps generation "
                    "time and code size bounded)",
                    what, kMaxExpressionNodes));
  if (depth > kMaxNestingDepth)
    throw InputError(
        fmt::format("{} nests functions {} deep; the limit is {}: the derivatives of order m+1 grow "
                    "like depth^(m+1), which makes the code explode",
                    what, depth, kMaxNestingDepth));
}

namespace {

// Orders 1 and 2 counted once; any order extrapolated from them.
class Extrapolation {
 public:
  Extrapolation(const OffsetMethod& method, const Surface& surface)
      : one_(count(method, surface, 1)), two_(count(method, surface, 2)) {}
  CostEstimate at(int order) const {
    CostEstimate e;
    if (order <= 2) {
      const Counts& c = order == 1 ? one_ : two_;
      e.largest_ops = c.largest;
      e.total_ops = c.total;
    } else {
      e.largest_ops = grow(one_.largest, two_.largest, order);
      e.total_ops = grow(one_.total, two_.total, order);
    }
    e.seconds = double(e.total_ops) * kSecondsPerOp;
    return e;
  }

 private:
  static long long grow(long long at_one, long long at_two, int order) {
    const double ratio = std::max(1.0, double(at_two) / double(std::max(1LL, at_one)));
    const double value = double(at_two) * std::pow(ratio, order - 2);
    return value > 9e18 ? static_cast<long long>(9e18) : std::llround(value);
  }
  Counts one_, two_;
};

}  // namespace

void require_affordable(const OffsetMethod& method, const Surface& surface, int order,
                        const std::function<void(const std::string&)>& notice) {
  if (surface.from_catalog || order <= 2) return;
  const Extrapolation extrapolation(method, surface);
  const CostEstimate estimate = extrapolation.at(order);
  if (estimate.largest_ops > kMaxFunctionOps) {
    int highest = 0;
    for (int m = 1; m < order; ++m)
      if (extrapolation.at(m).largest_ops <= kMaxFunctionOps) highest = m;
    throw InputError(fmt::format(
        "order {} of this expression would produce about {:.2g} ops in its largest function (estimated from orders "
        "1 and 2); the limit is {:.2g}. {}",
        order, double(estimate.largest_ops), double(kMaxFunctionOps),
        highest > 0 ? fmt::format("Orders up to {} stay within it.", highest)
                    : std::string("Simplify the expression (less nesting).")));
  }
  if (notice && estimate.seconds > kAnnounceAboveSeconds)
    notice(fmt::format("order {}: about {:.2g} ops in the largest function; estimated {:.0f} s", order,
                       double(estimate.largest_ops), estimate.seconds));
}

void require_within_op_limit(const std::string& function, long long ops) {
  if (ops > kMaxFunctionOps)
    throw InputError(
        fmt::format("the generated _{} has {} ops, above the limit of {}: lower the order or simplify "
                    "the expression",
                    function, ops, kMaxFunctionOps));
}

}  // namespace offsetgen
