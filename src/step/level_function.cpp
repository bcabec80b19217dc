#include "step/level_function.h"

#include <vector>

namespace offsetgen::step {

std::vector<std::vector<double>> segment_roots(const LevelFunction& g, const std::vector<Segment>& segments,
                                               int steps) {
  const size_t n = segments.size(), per = static_cast<size_t>(steps) + 1;
  std::vector<double> x(n * per), y(n * per), z(n * per), value(n * per);
  auto point = [&](const Segment& s, double t, size_t k) {
    x[k] = s.a[0] + t * (s.b[0] - s.a[0]);
    y[k] = s.a[1] + t * (s.b[1] - s.a[1]);
    z[k] = s.a[2] + t * (s.b[2] - s.a[2]);
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k < per; ++k) point(segments[i], double(k) / steps, i * per + k);
  g(n * per, x.data(), y.data(), z.data(), value.data());

  // Brackets [lo, hi] with a sign change, refined together: each pass evaluates every midpoint.
  struct Bracket {
    size_t segment;
    double lo, hi;
    bool lo_negative;
  };
  std::vector<Bracket> brackets;
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k + 1 < per; ++k) {
      const double v0 = value[i * per + k], v1 = value[i * per + k + 1];
      if ((v0 < 0) != (v1 < 0)) brackets.push_back({i, double(k) / steps, double(k + 1) / steps, v0 < 0});
    }
  const size_t nb = brackets.size();
  x.resize(nb);
  y.resize(nb);
  z.resize(nb);
  value.resize(nb);
  for (int pass = 0; pass < 60; ++pass) {
    for (size_t b = 0; b < nb; ++b) point(segments[brackets[b].segment], 0.5 * (brackets[b].lo + brackets[b].hi), b);
    g(nb, x.data(), y.data(), z.data(), value.data());
    for (size_t b = 0; b < nb; ++b) {
      const double mid = 0.5 * (brackets[b].lo + brackets[b].hi);
      if ((value[b] < 0) == brackets[b].lo_negative)
        brackets[b].lo = mid;
      else
        brackets[b].hi = mid;
    }
  }
  std::vector<std::vector<double>> roots(n);
  for (const Bracket& b : brackets) roots[b.segment].push_back(0.5 * (b.lo + b.hi));
  return roots;
}

}  // namespace offsetgen::step
