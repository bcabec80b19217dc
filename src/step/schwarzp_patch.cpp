#include "step/schwarzp_patch.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace offsetgen::step {
namespace {

// Scan points per line: the surface crosses each line once, and a second crossing closer than
// 1/(2 * kSteps) of the cell would be a fold far beyond the curvature limit.
constexpr int kSteps = 64;

Segment line(double u, double v) {
  Segment s{};
  s.a[0] = 0.5;
  s.a[1] = 0.5;
  s.a[2] = v * 0.5;
  s.b[0] = 0.5 - 0.5 * (1 - u);
  s.b[1] = 0;
  s.b[2] = 0;
  return s;
}

}  // namespace

std::vector<Point> schwarzp_patch_points(const LevelFunction& g, const std::vector<std::array<double, 2>>& uv) {
  std::vector<Segment> segments;
  segments.reserve(uv.size());
  for (const auto& [u, v] : uv) segments.push_back(line(u, v));
  const std::vector<std::vector<double>> roots = segment_roots(g, segments, kSteps);
  std::vector<Point> points(uv.size());
  for (size_t i = 0; i < uv.size(); ++i) {
    if (roots[i].size() != 1)
      throw InputError(fmt::format(
          "the offset surface crosses the line of the Schwarz P symmetry patch at (u, v) = ({:.3f}, {:.3f}) {} "
          "times, not once: at this thickness the wall is not the graph the patch layout needs (reduce "
          "--thickness)",
          uv[i][0], uv[i][1], roots[i].size()));
    const Segment& s = segments[i];
    const double t = roots[i][0];
    for (size_t a = 0; a < 3; ++a) points[i][a] = s.a[a] + t * (s.b[a] - s.a[a]);
  }
  return points;
}

std::vector<Point> schwarzp_patch_points(const LevelFunction& g, int m) {
  std::vector<std::array<double, 2>> uv;
  uv.reserve(static_cast<size_t>(m * m));
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) uv.push_back({double(i) / (m - 1), double(j) / (m - 1)});
  return schwarzp_patch_points(g, uv);
}

void snap_schwarzp_boundary(CubicPatch& patch) {
  const int n = patch.n;
  for (int k = 0; k < n; ++k) {
    patch.at(n - 1, k)[0] = 0.5;  // u = 1: x = 1/2
    if (patch.at(0, k)[0] != patch.at(0, k)[1] || patch.at(k, 0)[2] != 0 ||
        patch.at(k, n - 1)[1] != patch.at(k, n - 1)[2])
      throw std::logic_error("Schwarz P patch: a boundary control point is off its mirror plane");
  }
}

double schwarzp_normal_jump(const CubicPatch& patch, int samples) {
  constexpr double kStep = 1e-6;
  auto normal_at = [&patch](double u, double v) {
    auto d = [&patch](double u0, double v0, double u1, double v1) {
      const Point a = patch.evaluate(u0, v0), b = patch.evaluate(u1, v1);
      return Point{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    };
    const double u0 = std::max(0.0, u - kStep), u1 = std::min(1.0, u + kStep);
    const double v0 = std::max(0.0, v - kStep), v1 = std::min(1.0, v + kStep);
    const Point du = d(u0, v, u1, v), dv = d(u, v0, u, v1);
    Point n{du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    const double length = std::hypot(n[0], n[1], n[2]);
    for (double& c : n) c /= length;
    return n;
  };
  const double r = 1 / std::sqrt(2.0);
  // The planes' normals: u = 0 on x = y, u = 1 on x = 1/2, v = 0 on z = 0, v = 1 on y = z.
  const std::array<Point, 4> plane{Point{r, -r, 0}, Point{1, 0, 0}, Point{0, 0, 1}, Point{0, r, -r}};
  double worst = 0;
  for (int k = 0; k <= samples; ++k) {
    const double t = double(k) / samples;
    const std::array<std::array<double, 2>, 4> at{{{0, t}, {1, t}, {t, 0}, {t, 1}}};
    for (size_t e = 0; e < 4; ++e) {
      const Point n = normal_at(at[e][0], at[e][1]);
      const double sine = std::fabs(n[0] * plane[e][0] + n[1] * plane[e][1] + n[2] * plane[e][2]);
      worst = std::max(worst, 2 * std::asin(std::min(1.0, sine)));
    }
  }
  return worst;
}

}  // namespace offsetgen::step
