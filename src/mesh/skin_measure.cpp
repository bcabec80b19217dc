#include "mesh/skin_measure.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::mesh {

SkinReport measure_skin(const TriangleMesh& mesh, const std::vector<double>& depth_voxels, double voxel_mm) {
  SkinReport report;
  const std::vector<uint32_t> piece = point_pieces(mesh);
  const std::vector<double> volume = piece_volumes(mesh, piece);
  for (size_t i = 0; i < volume.size(); ++i)
    if (piece[i] == i && volume[i] < 0) ++report.cavities;
  double thinnest = HUGE_VAL, outer_deepest = 0;
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    const double depth = -depth_voxels[i] * voxel_mm;
    if (volume[piece[i]] < 0) {
      thinnest = std::min(thinnest, depth);
    } else if (volume[piece[i]] > 0) {
      outer_deepest = std::max(outer_deepest, depth);
    }
  }
  report.thinnest = report.cavities > 0 ? thinnest : 0;
  report.outer_deepest = outer_deepest;
  return report;
}

void measure_skin_by_depth(const std::vector<double>& depth_voxels, double voxel_mm, SkinReport& report) {
  if (report.by_pieces) {
    report = SkinReport{};
    report.by_pieces = false;
    report.thinnest = HUGE_VAL;
  }
  for (double d : depth_voxels) {
    const double depth = -d * voxel_mm;
    if (-d > kOuterSurfaceDepth) {
      report.thinnest = std::min(report.thinnest, depth);
    } else {
      report.outer_deepest = std::max(report.outer_deepest, depth);
    }
  }
}

}  // namespace offsetgen::mesh
