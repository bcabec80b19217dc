// A guard against blow-ups: deep nesting such as sin(sin(sin(...))) makes the derivatives, and so the
// emitted code, grow like depth^(m+1). Before building order m of a user expression, orders 1 and 2
// are built (milliseconds) and the growth is extrapolated; above a limit the request is refused at
// once, below it a long run is announced with a time estimate.
#pragma once

#include "offset/method.h"
#include "surfaces/surface.h"

#include <functional>
#include <string>

namespace offsetgen {

// Largest emitted function allowed, in ops after CSE (estimated before, counted after the build).
// Orders 1-12 of every catalog surface stay below it; the limit is about 2 minutes of generation
// and 1-2 GB of memory on a 2-core machine.
constexpr long long kMaxFunctionOps = 3'000'000;

// Limits on the expression itself, checked before anything is built.
constexpr int kMaxNestingDepth = 32;       // nested function calls and non-integer powers
constexpr int kMaxExpressionNodes = 4000;  // GiNaC expression nodes

struct CostEstimate {
  long long largest_ops = 0;  // of the largest emitted function (usually _normal)
  long long total_ops = 0;    // of all of them
  double seconds = 0;         // generation time, from ~25 us per op measured on a 2-core machine
};

// Throws InputError when `e` is nested deeper or larger than the limits above.
void require_within_size_limits(const GiNaC::ex& e, const std::string& what);

// For user expressions (catalog surfaces are known to stay within the limit): throws InputError when
// the estimate exceeds kMaxFunctionOps, naming the estimate and the highest order within the limit;
// otherwise calls `notice` with a time estimate when the run will take more than a few seconds.
void require_affordable(const OffsetMethod& method, const Surface& surface, int order,
                        const std::function<void(const std::string&)>& notice);

// After the build: throws InputError when a function counted more than kMaxFunctionOps.
void require_within_op_limit(const std::string& function, long long ops);

}  // namespace offsetgen
