// Plane geometry the hatch and offset tests check with, written apart from slice/scan_paths.cpp: the
// distance from a point to a set of closed polylines, and whether a point is inside them (even-odd).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace offsetgen::slice::test {

using Pt = std::array<double, 2>;
using Ring = std::vector<Pt>;  // closed: the last point joins the first (a repeated first point is harmless)

inline double segment_distance(const Pt& p, const Pt& a, const Pt& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

inline double distance_to_rings(const Pt& p, const std::vector<Ring>& rings) {
  double d = std::numeric_limits<double>::infinity();
  for (const Ring& r : rings)
    for (size_t k = 0; k < r.size(); ++k) d = std::min(d, segment_distance(p, r[k], r[(k + 1) % r.size()]));
  return d;
}

// Even-odd: a ray towards +x crosses the rings an odd number of times.
inline bool inside_rings(const Pt& p, const std::vector<Ring>& rings) {
  bool in = false;
  for (const Ring& r : rings)
    for (size_t k = 0; k < r.size(); ++k) {
      const Pt& a = r[k];
      const Pt& b = r[(k + 1) % r.size()];
      if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])) in = !in;
    }
  return in;
}

inline double ring_area(const Ring& r) {
  double a = 0;
  for (size_t k = 0; k < r.size(); ++k) a += r[k][0] * r[(k + 1) % r.size()][1] - r[(k + 1) % r.size()][0] * r[k][1];
  return 0.5 * a;
}

}  // namespace offsetgen::slice::test
