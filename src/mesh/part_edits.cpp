#include "mesh/part_edits.h"

#include <algorithm>

namespace offsetgen::mesh {
namespace {

bool block_has_filled(const VoxelBits& filled, const std::array<int, 3>& origin) {
  for (int x = 0; x < kBlock; ++x)
    for (int y = 0; y < kBlock; ++y)
      for (int z = 0; z < kBlock; ++z) {
        const int px = origin[0] + x, py = origin[1] + y, pz = origin[2] + z;
        if (filled.contains(px, py, pz) && filled.get(filled.index(px, py, pz))) return true;
      }
  return false;
}

}  // namespace

bool apply_part_edits(const PartEdits& edits, const std::array<int, 3>& origin, float background,
                      std::vector<float>& values) {
  const wall::Point3 lo{double(origin[0]), double(origin[1]), double(origin[2])};
  const wall::Point3 hi{lo[0] + kBlock - 1, lo[1] + kBlock - 1, lo[2] + kBlock - 1};
  // Within the band's reach of a hole's wall, the values change.
  const bool holes = wall::holes_near_box(edits.holes, lo, hi, double(background) + 1);
  const bool fill = edits.filled && block_has_filled(*edits.filled, origin);
  if (!holes && !fill) return false;
  if (values.empty()) values.assign(kBlockVoxels, background);
  for (int x = 0; x < kBlock; ++x)
    for (int y = 0; y < kBlock; ++y)
      for (int z = 0; z < kBlock; ++z) {
        float& v = values[size_t(block_offset(x, y, z))];
        const int px = origin[0] + x, py = origin[1] + y, pz = origin[2] + z;
        if (fill && edits.filled->contains(px, py, pz) && edits.filled->get(edits.filled->index(px, py, pz)))
          v = kFilledValue;
        if (holes) {
          const double hole = wall::hole_distance(edits.holes, {double(px), double(py), double(pz)});
          v = static_cast<float>(
              std::clamp(wall::drained_part_value(v, hole), -double(background), double(background)));
        }
      }
  return true;
}

}  // namespace offsetgen::mesh
