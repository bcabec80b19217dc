#include "mesh/void_regions.h"

#include <chrono>
#include <cmath>
#include <utility>

namespace offsetgen::mesh {
namespace {

// Breadth first over the open voxels from `seeds`, marking `visited`; calls visit(index) once per
// voxel. Two frontiers, so the memory held is the front, not the region.
template <typename Visit>
void flood(const VoxelBits& open, VoxelBits& visited, std::vector<uint64_t> front, const Visit& visit) {
  const auto& n = open.size();
  const uint64_t step[3] = {n[1] * n[2], n[2], 1};
  std::vector<uint64_t> next;
  while (!front.empty()) {
    next.clear();
    for (const uint64_t i : front) {
      visit(i);
      const uint64_t c[3] = {i / step[0], i / step[1] % n[1], i % n[2]};
      for (size_t a = 0; a < 3; ++a) {
        if (c[a] > 0 && open.get(i - step[a]) && !visited.get(i - step[a])) {
          visited.set(i - step[a], true);
          next.push_back(i - step[a]);
        }
        if (c[a] + 1 < n[a] && open.get(i + step[a]) && !visited.get(i + step[a])) {
          visited.set(i + step[a], true);
          next.push_back(i + step[a]);
        }
      }
    }
    std::swap(front, next);
  }
}

// The open voxels on the box's faces: the outside's seeds.
std::vector<uint64_t> border_seeds(const VoxelBits& open, VoxelBits& visited) {
  std::vector<uint64_t> seeds;
  const auto& n = open.size();
  for (uint64_t x = 0; x < n[0]; ++x)
    for (uint64_t y = 0; y < n[1]; ++y) {
      const bool face = x == 0 || y == 0 || x + 1 == n[0] || y + 1 == n[1];
      for (uint64_t z = 0; z < n[2]; z += face ? 1 : std::max<uint64_t>(1, n[2] - 1)) {
        const uint64_t i = (x * n[1] + y) * n[2] + z;
        if (open.get(i) && !visited.get(i)) {
          visited.set(i, true);
          seeds.push_back(i);
        }
      }
    }
  return seeds;
}

}  // namespace

VoidReport find_enclosed_voids(const VoxelBits& void_bits, double voxel_mm) {
  const auto start = std::chrono::steady_clock::now();
  VoidReport report;
  report.analysed = true;
  report.voxel = voxel_mm;
  if (void_bits.count() == 0) return report;
  VoxelBits visited(void_bits.box(), false);
  flood(void_bits, visited, border_seeds(void_bits, visited), [](uint64_t) {});
  const double voxel3 = std::pow(voxel_mm, 3);
  for (uint64_t i = 0; i < void_bits.count(); ++i) {
    if (!void_bits.get(i) || visited.get(i)) continue;
    VoidRegion region;
    region.seed = void_bits.point(i);
    for (auto& axis : region.extreme) axis = {region.seed, region.seed};
    visited.set(i, true);
    flood(void_bits, visited, {i}, [&](uint64_t j) {
      ++region.voxels;
      const auto p = void_bits.point(j);
      for (size_t a = 0; a < 3; ++a) {
        if (p[a] < region.extreme[a][0][a]) region.extreme[a][0] = p;
        if (p[a] > region.extreme[a][1][a]) region.extreme[a][1] = p;
      }
    });
    region.volume = double(region.voxels) * voxel3;
    report.total += region.volume;
    report.largest = std::max(report.largest, region.volume);
    if (region.volume >= kDrainRegionMm3) {
      ++report.large;
      report.large_volume += region.volume;
    }
    report.regions.push_back(region);
  }
  report.bytes = void_bits.memory_bytes() + visited.memory_bytes();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

VoxelBits pockets_to_fill(const VoxelBits& void_bits, const VoidReport& report, double below_mm3, double& filled) {
  VoxelBits fill(void_bits.box(), false);
  filled = 0;
  for (const VoidRegion& region : report.regions) {
    if (region.volume >= below_mm3) continue;
    const uint64_t i = void_bits.index(region.seed[0], region.seed[1], region.seed[2]);
    fill.set(i, true);
    flood(void_bits, fill, {i}, [](uint64_t) {});
    filled += region.volume;
  }
  return fill;
}

}  // namespace offsetgen::mesh
