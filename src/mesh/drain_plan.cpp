#include "mesh/drain_plan.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace offsetgen::mesh {
namespace {

using P = std::array<double, 3>;

P sub(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P add_scaled(const P& a, const P& b, double s) { return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}; }
double dot(const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double distance(const P& a, const P& b) { return std::sqrt(dot(sub(a, b), sub(a, b))); }

// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
P nearest_on_triangle(const P& p, const P& a, const P& b, const P& c) {
  const P ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const P bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return add_scaled(a, ab, d1 / (d1 - d3));
  const P cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return add_scaled(a, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return add_scaled(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1 / (va + vb + vc);
  return add_scaled(add_scaled(a, ab, vb * denom), ac, vc * denom);
}

// The body's surface point nearest to p: every facet (a few holes, so no index is needed).
P nearest_on_body(const body::BodyMesh& body, const P& p) {
  P best = p;
  double best_distance = HUGE_VAL;
  for (const auto& t : body.triangles) {
    const P q = nearest_on_triangle(p, body.points[t[0]], body.points[t[1]], body.points[t[2]]);
    const double d = distance(p, q);
    if (d < best_distance) {
      best_distance = d;
      best = q;
    }
  }
  return best;
}

// A hole from `at` (inside) out through the nearest point of the surface and `beyond` mm past it.
PlannedHole hole_from(const body::BodyMesh& body, const P& at, double diameter, double beyond,
                      const std::string& role) {
  PlannedHole hole;
  hole.at = at;
  hole.diameter = diameter;
  hole.role = role;
  const P exit = nearest_on_body(body, at);
  const double depth = distance(at, exit);
  hole.direction =
      depth > 0 ? P{(exit[0] - at[0]) / depth, (exit[1] - at[1]) / depth, (exit[2] - at[2]) / depth} : P{0, 0, 1};
  hole.length = depth + beyond;
  return hole;
}

}  // namespace

std::vector<PlannedHole> plan_drain_holes(const VoidReport& voids, const body::BodyMesh& body, const VoxelFrame& frame,
                                          const DrainRequest& request) {
  std::vector<PlannedHole> holes;
  if (request.diameter <= 0) return holes;
  // Past the surface by a diameter and two voxels: the hole's rim leaves a curved or slanted surface too.
  const double beyond = request.diameter + 2 * frame.voxel;
  if (!request.at.empty()) {
    for (const auto& p : request.at) holes.push_back(hole_from(body, p, request.diameter, beyond, "by hand"));
    return holes;
  }
  const size_t up = size_t(request.up);
  auto mm = [&](const std::array<int, 3>& v) { return frame.centre_mm({double(v[0]), double(v[1]), double(v[2])}); };
  for (const VoidRegion& region : voids.regions) {
    if (region.volume < kDrainRegionMm3 || region.volume < request.fill_below) continue;
    const P low = mm(region.extreme[up][0]);
    P high = mm(region.extreme[up][1]);
    if (distance(low, high) < 2 * request.diameter) {
      // A flat region: the extreme furthest from the lowest voxel, first in axis order on ties.
      for (const auto& axis : region.extreme)
        for (const auto& e : axis)
          if (distance(low, mm(e)) > distance(low, high)) high = mm(e);
    }
    holes.push_back(hole_from(body, low, request.diameter, beyond, "drain"));
    holes.push_back(hole_from(body, high, request.diameter, beyond, "air"));
  }
  return holes;
}

std::vector<wall::DrainHole> holes_in_voxels(const std::vector<PlannedHole>& holes, const VoxelFrame& frame) {
  std::vector<wall::DrainHole> out;
  for (const PlannedHole& h : holes) {
    wall::DrainHole d;
    for (size_t a = 0; a < 3; ++a) {
      d.from[a] = (h.at[a] - frame.origin[a]) / frame.voxel - 0.5;
      d.to[a] = (h.at[a] + h.length * h.direction[a] - frame.origin[a]) / frame.voxel - 0.5;
    }
    d.radius = h.diameter / 2 / frame.voxel;
    out.push_back(d);
  }
  return out;
}

void check_drain_diameter(const DrainRequest& request, double voxel, const std::array<std::array<double, 3>, 2>& box) {
  if (request.diameter <= 0) return;
  if (request.diameter < 2 * voxel)
    throw InputError(fmt::format(
        "--drain {:g} mm spans {:.3g} voxels of {:.4g} mm: a hole needs at least 2 across; use a larger --drain or "
        "--voxel {:g} or less",
        request.diameter, request.diameter / voxel, voxel, request.diameter / 2));
  double smallest = HUGE_VAL;
  for (size_t a = 0; a < 3; ++a) smallest = std::min(smallest, box[1][a] - box[0][a]);
  if (request.diameter >= smallest / 2)
    throw InputError(fmt::format(
        "--drain {:g} mm is at least half the body's smallest extent ({:.4g} mm): holes that wide would cut "
        "the part apart; use a smaller diameter",
        request.diameter, smallest));
}

int parse_up_axis(const std::string& text) {
  if (text == "X" || text == "x") return 0;
  if (text == "Y" || text == "y") return 1;
  if (text == "Z" || text == "z") return 2;
  throw InputError(fmt::format("--up '{}': expected X, Y or Z", text));
}

}  // namespace offsetgen::mesh
