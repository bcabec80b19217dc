// `offsetgen check` measures the Lipschitz bounds a file's method documents (MethodFacts::
// lipschitz_bounds): the largest |grad phi| by central differences of the compiled offset, over grid
// points in the band |F(p)| <= M |h| that holds the zero set, against the bound.
#pragma once

#include "check/thickness.h"
#include "offset/method.h"

#include <vector>

namespace offsetgen::check {

struct LipschitzRow {
  double h = 0;         // cell units
  double bound = 0;     // documented, cell units
  double measured = 0;  // max |grad phi| over the band points
  int points = 0;       // grid points in the band
  bool pass = true;
};

// `gradient_bound` is M (natural units) and `scale` k of X = k x; `grid` points per axis.
std::vector<LipschitzRow> measure_lipschitz(const Probe& probe, const std::vector<MethodFacts::LipschitzBound>& bounds,
                                            double gradient_bound, double scale, int grid = 17);

}  // namespace offsetgen::check
