#include "check/convergence.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace offsetgen::check {

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = x.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double dn = static_cast<double>(n);
  const double denominator = dn * sxx - sx * sx;
  return denominator == 0 ? 0 : (dn * sxy - sx * sy) / denominator;
}

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error) {
  OrderFit fit;
  std::vector<std::pair<double, double>> usable;
  double lo = INFINITY, hi = 0;
  int at_floor = 0;
  for (size_t i = 0; i < h.size() && i < error.size(); ++i) {
    if (!(h[i] > 0)) continue;
    lo = std::min(lo, h[i]);
    hi = std::max(hi, h[i]);
    if (std::isfinite(error[i]) && error[i] > kRoundoffFloor) {
      usable.emplace_back(h[i], error[i]);
    } else if (std::isfinite(error[i])) {
      ++at_floor;
    }
  }
  std::sort(usable.begin(), usable.end());
  if (usable.size() < 2) {
    fit.note = at_floor > 0 ? fmt::format("not fitted: {} of {} errors at the roundoff floor (< {:.0e})", at_floor,
                                          h.size(), kRoundoffFloor)
                            : "not fitted: fewer than 2 usable points";
    return fit;
  }
  const double split = std::sqrt(lo * hi);
  std::vector<std::pair<double, double>> chosen;
  for (const auto& p : usable)
    if (p.first <= split * (1 + 1e-12)) chosen.push_back(p);
  if (chosen.size() < 3)
    chosen.assign(usable.begin(), usable.begin() + static_cast<long>(std::min<size_t>(3, usable.size())));
  std::vector<double> xs, ys;
  for (const auto& [x, y] : chosen) {
    xs.push_back(x);
    ys.push_back(y);
  }
  fit.fitted = true;
  fit.slope = loglog_slope(xs, ys);
  fit.points = static_cast<int>(chosen.size());
  fit.h_min = xs.front();
  fit.h_max = xs.back();
  if (at_floor > 0) fit.note = fmt::format("{} point(s) at the roundoff floor left out", at_floor);
  return fit;
}

}  // namespace offsetgen::check
