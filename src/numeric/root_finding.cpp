#include "numeric/root_finding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace offsetgen::numeric {

double brent_root(const ScalarFunction& f, double a, double b, double fa, double fb, int max_iterations) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    if ((fb > 0) == (fc > 0)) {  // keep the root between b and c
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::fabs(fc) < std::fabs(fb)) {  // b is the best estimate
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2 * eps * std::fabs(b) + std::numeric_limits<double>::min();
    const double m = 0.5 * (c - b);
    if (std::fabs(m) <= tol || fb == 0) return b;
    if (std::fabs(e) >= tol && std::fabs(fa) > std::fabs(fb)) {
      double p, q, r;
      const double s = fb / fa;
      if (a == c) {  // secant
        p = 2 * m * s;
        q = 1 - s;
      } else {  // inverse quadratic interpolation
        q = fa / fc;
        r = fb / fc;
        p = s * (2 * m * q * (q - r) - (b - a) * (r - 1));
        q = (q - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) {
        q = -q;
      } else {
        p = -p;
      }
      if (2 * p < std::min(3 * m * q - std::fabs(tol * q), std::fabs(e * q))) {
        e = d;
        d = p / q;
      } else {  // interpolation would leave the bracket or converge too slowly: bisect
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::fabs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

std::vector<double> roots_in_interval(const ScalarFunction& f, double lo, double hi, int intervals) {
  std::vector<double> roots;
  if (intervals < 1) intervals = 1;
  double x0 = lo, f0 = f(lo);
  if (f0 == 0) roots.push_back(lo);
  for (int i = 1; i <= intervals; ++i) {
    const double x1 = i == intervals ? hi : lo + (hi - lo) * i / intervals;
    const double f1 = f(x1);
    if (f1 == 0) {
      roots.push_back(x1);
    } else if (f0 != 0 && (f0 > 0) != (f1 > 0) && std::isfinite(f0) && std::isfinite(f1)) {
      roots.push_back(brent_root(f, x0, x1, f0, f1));
    }
    x0 = x1;
    f0 = f1;
  }
  return roots;
}

std::optional<double> root_near(const ScalarFunction& f, double expected, double reach) {
  const double f0 = f(expected);
  if (f0 == 0) return expected;
  if (!std::isfinite(f0) || !(reach > 0)) return std::nullopt;
  static constexpr std::array<double, 14> kWindows = {1e-8, 1e-6, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2,
                                                      0.06, 0.1,  0.2,  0.35, 0.5,  0.75, 1.0};
  for (double w : kWindows) {
    const double lo = expected - w * reach, hi = expected + w * reach;
    const double flo = f(lo), fhi = f(hi);
    std::optional<double> best;
    auto consider = [&](double r) {
      if (!best || std::fabs(r - expected) < std::fabs(*best - expected)) best = r;
    };
    if (std::isfinite(flo) && (flo == 0 || (flo > 0) != (f0 > 0))) consider(brent_root(f, lo, expected, flo, f0));
    if (std::isfinite(fhi) && (fhi == 0 || (fhi > 0) != (f0 > 0))) consider(brent_root(f, expected, hi, f0, fhi));
    if (best) return best;
  }
  return std::nullopt;
}

}  // namespace offsetgen::numeric
