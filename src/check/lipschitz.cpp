#include "check/lipschitz.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::check {

std::vector<LipschitzRow> measure_lipschitz(const Probe& probe, const std::vector<MethodFacts::LipschitzBound>& bounds,
                                            double gradient_bound, double scale, int grid) {
  std::vector<LipschitzRow> rows;
  const int dims = probe.dims;
  constexpr double kStep = 1e-6;
  for (const auto& b : bounds) {
    if (!(b.bound > 0)) continue;
    LipschitzRow row{b.h, b.bound, 0, 0, true};
    const int total = dims == 3 ? grid * grid * grid : grid * grid;
    for (int index = 0; index < total; ++index) {
      Point p{};
      int rest = index;
      for (int i = 0; i < dims; ++i) {
        p[static_cast<size_t>(i)] = (rest % grid + 0.5) / grid;
        rest /= grid;
      }
      if (std::fabs(probe.field(p.data())) > gradient_bound * scale * b.h) continue;  // outside the band
      ++row.points;
      for (double h : {b.h, -b.h}) {
        double g2 = 0;
        for (int i = 0; i < dims; ++i) {
          Point a = p, c = p;
          a[static_cast<size_t>(i)] += kStep;
          c[static_cast<size_t>(i)] -= kStep;
          const double d = (probe.offset(a.data(), h) - probe.offset(c.data(), h)) / (2 * kStep);
          g2 += d * d;
        }
        row.measured = std::max(row.measured, std::sqrt(g2));
      }
    }
    // Central differences carry about 1e-9 relative error here: a 1e-6 margin.
    row.pass = row.measured <= row.bound * (1 + 1e-6);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace offsetgen::check
