// The body: a user's CAD part (`offsetgen mesh --body part.stl`), read by body_files.h and checked and
// repaired by body_topology.h before it becomes a level set. Coordinates are in millimetres, in double
// so that the floats of an STL and the doubles of a PLY or OBJ are held exactly.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace offsetgen::body {

struct BodyMesh {
  // Welded: one point per distinct position (exact equality), so the corners a file repeats per
  // facet (STL) become one index and shared edges can be found by index.
  std::vector<std::array<double, 3>> points;
  // Indices into points, counter-clockwise seen from outside when oriented.
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Volume enclosed by the triangles (divergence theorem), positive when they face outward.
inline double signed_volume(const BodyMesh& mesh) {
  double v = 0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.points[t[0]];
    const auto& b = mesh.points[t[1]];
    const auto& c = mesh.points[t[2]];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6.0;
}

// {min, max} over the points the triangles use; all zero for a mesh without triangles.
inline std::array<std::array<double, 3>, 2> bounding_box(const BodyMesh& mesh) {
  if (mesh.triangles.empty()) return {};
  std::array<std::array<double, 3>, 2> box{mesh.points[mesh.triangles[0][0]], mesh.points[mesh.triangles[0][0]]};
  for (const auto& t : mesh.triangles)
    for (uint32_t i : t)
      for (size_t k = 0; k < 3; ++k) {
        box[0][k] = std::min(box[0][k], mesh.points[i][k]);
        box[1][k] = std::max(box[1][k], mesh.points[i][k]);
      }
  return box;
}

}  // namespace offsetgen::body
