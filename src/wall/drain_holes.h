// Drain holes (issue 43): round holes cut through a part's skin so that resin or powder trapped in
// the lattice's voids can leave. A hole is the capsule of radius r around a segment from inside a void
// out past the body's surface; cutting it into the part's signed value keeps one closed solid:
//   part' = max(part, -(r - distance to the segment))
// in any one length unit (mesh uses voxel index coordinates, slice millimetres).
#pragma once

#include <array>
#include <vector>

namespace offsetgen::wall {

using Point3 = std::array<double, 3>;

struct DrainHole {
  Point3 from{}, to{};  // the axis: from inside the void to past the body's surface
  double radius = 0;
};

// The signed distance to the nearest hole: negative inside one; +inf without holes.
double hole_distance(const std::vector<DrainHole>& holes, const Point3& p);
// The part with the holes cut into it: max(part, -hole_distance).
double drained_part_value(double part, double hole_distance);
// True when some hole comes within `margin` of the box [lo, hi].
bool holes_near_box(const std::vector<DrainHole>& holes, const Point3& lo, const Point3& hi, double margin);

}  // namespace offsetgen::wall
