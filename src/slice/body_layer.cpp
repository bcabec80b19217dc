#include "slice/body_layer.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::slice {
namespace {

// The body's points in pixel index coordinates: pixel k's centre is index k.
std::vector<body::Vec3> index_points(const body::BodyMesh& mesh, const std::array<double, 3>& origin, double pixel) {
  std::vector<body::Vec3> points;
  points.reserve(mesh.points.size());
  for (const auto& p : mesh.points)
    points.push_back(
        {(p[0] - origin[0]) / pixel - 0.5, (p[1] - origin[1]) / pixel - 0.5, (p[2] - origin[2]) / pixel - 0.5});
  return points;
}

}  // namespace

BodyLayer::BodyLayer(const body::BodyMesh& mesh, const std::array<double, 3>& origin, double cell_size,
                     int pixels_per_cell, double skin, double fillet)
    : per_cell_(pixels_per_cell),
      skin_(skin / cell_size),
      fillet_(fillet / cell_size),
      // Deep enough inside for the core's surface (d = -skin), its fillet and the band; any depth in the
      // middle of the skin will do (the part is solid there), as for mesh (mesh/body_domain.cpp).
      distance_(index_points(mesh, origin, cell_size / pixels_per_cell), mesh.triangles,
                (skin + fillet) / cell_size * pixels_per_cell + kMargin + 1, kMargin,
                {kMargin + 1, (skin - fillet) / cell_size * pixels_per_cell - kMargin - 1}) {
  const auto box = body::bounding_box(mesh);
  const double pixel = cell_size / pixels_per_cell;
  for (size_t a = 0; a < 2; ++a) {
    const int lo = static_cast<int>(std::floor((box[0][a] - origin[a]) / pixel)) - 4;
    const int hi = static_cast<int>(std::ceil((box[1][a] - origin[a]) / pixel)) + 4;
    first_pixel_[a] = lo;
    pixels_[a] = hi - lo;
  }
}

BodyLayer::Place BodyLayer::block(const std::array<int, 2>& pixel, double z, double* d, Query& q) const {
  const double zi = z * per_cell_ - 0.5;
  if (!distance_.plane_block(pixel, zi, d, q.query))
    return distance_.inside({double(pixel[0]), double(pixel[1]), zi}, q.query) ? Place::Deep : Place::Outside;
  const double nearest = *std::min_element(d, d + body::kDistanceBlock * body::kDistanceBlock);
  return nearest >= kMargin ? Place::Outside : Place::Mixed;
}

void BodyLayer::distances(const std::vector<std::array<double, 2>>& points, double z, double* d, Query& q) const {
  q.points.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    q.points[i] = {points[i][0] * per_cell_ - 0.5, points[i][1] * per_cell_ - 0.5, z * per_cell_ - 0.5};
  q.values.resize(points.size());
  distance_.distances(q.points, q.values.data(), q.query);
  for (size_t i = 0; i < points.size(); ++i) d[i] = q.values[i] / per_cell_;
}

}  // namespace offsetgen::slice
