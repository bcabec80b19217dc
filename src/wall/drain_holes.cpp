#include "wall/drain_holes.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::wall {
namespace {

double segment_distance(const DrainHole& h, const Point3& p) {
  Point3 axis{}, rel{};
  double length2 = 0, along = 0;
  for (size_t a = 0; a < 3; ++a) {
    axis[a] = h.to[a] - h.from[a];
    rel[a] = p[a] - h.from[a];
    length2 += axis[a] * axis[a];
    along += axis[a] * rel[a];
  }
  const double t = length2 > 0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0;
  double d2 = 0;
  for (size_t a = 0; a < 3; ++a) d2 += (rel[a] - t * axis[a]) * (rel[a] - t * axis[a]);
  return std::sqrt(d2);
}

}  // namespace

double hole_distance(const std::vector<DrainHole>& holes, const Point3& p) {
  double nearest = HUGE_VAL;
  for (const DrainHole& h : holes) nearest = std::min(nearest, segment_distance(h, p) - h.radius);
  return nearest;
}

double drained_part_value(double part, double hole) { return std::max(part, -hole); }

bool holes_near_box(const std::vector<DrainHole>& holes, const Point3& lo, const Point3& hi, double margin) {
  for (const DrainHole& h : holes) {
    bool near = true;
    for (size_t a = 0; a < 3 && near; ++a) {
      const double reach = h.radius + margin;
      near = std::min(h.from[a], h.to[a]) - reach <= hi[a] && std::max(h.from[a], h.to[a]) + reach >= lo[a];
    }
    if (near) return true;
  }
  return false;
}

}  // namespace offsetgen::wall
