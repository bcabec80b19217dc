// Evaluates the symbolic offset model directly with CLN numbers, without any lowering: the
// reference the emitted code is checked against. Exact rationals stay exact (sqrt of a perfect
// square included), everything else is carried at `digits` significant digits.
#pragma once

#include "offset/offset_model.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <unordered_map>
#include <vector>

namespace offsetgen {

class HighPrecisionEvaluator {
 public:
  // `bounds` are the safeguard's (offset_model.h); bounds.gradient <= 0 evaluates the raw formulas.
  HighPrecisionEvaluator(const Surface& surface, const OffsetModel& model, SafeguardBounds bounds, int digits = 40);

  GiNaC::numeric field(const std::vector<GiNaC::numeric>& x_cell);
  std::vector<GiNaC::numeric> field_gradient(const std::vector<GiNaC::numeric>& x_cell);  // d F / d x_cell
  GiNaC::numeric offset(const std::vector<GiNaC::numeric>& x_cell, const GiNaC::numeric& h_cell);
  GiNaC::numeric shell(const std::vector<GiNaC::numeric>& x_cell, const GiNaC::numeric& t_cell);
  // G of phi = F - h G, unclamped (natural units).
  GiNaC::numeric weighted_norms(const std::vector<GiNaC::numeric>& x_cell, const GiNaC::numeric& h_cell);

 private:
  struct Scope {
    std::vector<std::pair<GiNaC::ex, GiNaC::numeric>> bindings;
    std::unordered_map<GiNaC::ex, GiNaC::numeric> memo;
  };
  GiNaC::numeric eval(const GiNaC::ex& e, Scope& scope, Scope& shared);
  GiNaC::numeric eval_sum(const ChainSum& sum, const std::vector<GiNaC::numeric>& x_cell, const GiNaC::numeric& h_natural);
  Scope coordinates(const std::vector<GiNaC::numeric>& x_cell);

  const Surface& surface_;
  const OffsetModel& model_;
  GiNaC::numeric bound_, hessian_bound_;
  bool clamp_;
  int digits_;
  GiNaC::numeric scale_;
};

}  // namespace offsetgen
