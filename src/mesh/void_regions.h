// Enclosed voids (issue 43): the connected components (6-neighbours) of a part's void voxels that do
// not reach the border of the sampled box, which lies outside the body: resin or powder trapped there
// cannot leave. Found by flood fill on the part-wide void bits (voxel_bits.h): first from the border
// (the outside), then from each void voxel not yet reached, in scan order, so the regions and their
// order do not depend on threads or tiles.
#pragma once

#include "mesh/voxel_bits.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace offsetgen::mesh {

// Regions of at least this volume must drain (--drain); smaller ones are listed apart.
inline constexpr double kDrainRegionMm3 = 1.0;

struct VoidRegion {
  uint64_t voxels = 0;
  double volume = 0;          // mm^3, voxels times the voxel's volume
  std::array<int, 3> seed{};  // its first voxel in scan order
  // The voxels where it reaches furthest, [axis][0 low, 1 high], in voxel indices: the first met.
  std::array<std::array<std::array<int, 3>, 2>, 3> extreme{};
};

struct VoidReport {
  bool analysed = false;
  std::vector<VoidRegion> regions;  // the enclosed ones, in scan order of their seeds
  double total = 0, largest = 0;    // mm^3
  size_t large = 0;                 // regions of kDrainRegionMm3 or more
  double large_volume = 0;          // their volume, mm^3
  double voxel = 0;                 // mm: the analysis voxel
  double seconds = 0;
  size_t bytes = 0;  // the bits held
};

// The enclosed regions of `void_bits` (voxels of `voxel_mm`). The bits serve as the flood's marks:
// every void voxel is cleared once reached, so the analysis holds one bit a voxel.
VoidReport find_enclosed_voids(VoxelBits& void_bits, double voxel_mm);
// Regions this close to kDrainRegionMm3 are measured again from the part's values: a region of a
// few hundred voxels counted whole is off by several percent, which decides which side of 1 mm^3 it
// falls.
inline constexpr double kRefineBelowMm3 = 4.0, kRefineAboveMm3 = 0.25;
// Samples the part's band over the blocks whose first voxels lie in the box (narrow_band.h).
using BandSampler = std::function<SampledBand(const VoxelBox& blocks)>;
// Re-measures the regions between kRefineAboveMm3 and kRefineBelowMm3 as the mesh encloses them: the
// part's values sampled again around each, and the surface volumeToMesh builds from them (a point in
// each cell at the average of its edges' zero crossings, a quad across each edge that changes sign)
// taken to enclose the region; then the totals again.
void refine_small_regions(VoidReport& report, const BandSampler& sample);

// The voxels of the enclosed regions under `below_mm3`, to fill solid (--fill-pockets), from the void
// bits as recorded (before find_enclosed_voids cleared them); sets `filled` to their volume (mm^3).
VoxelBits pockets_to_fill(const VoxelBits& void_bits, const VoidReport& report, double below_mm3, double& filled);

}  // namespace offsetgen::mesh
