// One bit per voxel over a box of voxel indices: the part's void (mesh/void_regions.h) or the voxels
// of pockets to fill. A part-wide grid at the mesh voxel costs 1/8 byte a voxel (the 54 mm bunny at
// 0.12 mm voxels: 11 MB), which is why it is bits and not labels.
#pragma once

#include "mesh/narrow_band.h"

#include <cstdint>
#include <vector>

namespace offsetgen::mesh {

class VoxelBits {
 public:
  VoxelBits() = default;
  VoxelBits(const VoxelBox& box, bool value);

  const VoxelBox& box() const { return box_; }
  const std::array<uint64_t, 3>& size() const { return size_; }
  uint64_t count() const { return size_[0] * size_[1] * size_[2]; }
  size_t memory_bytes() const { return words_.size() * sizeof(uint64_t); }

  // Linear index, z fastest; the point must lie in the box.
  uint64_t index(int x, int y, int z) const {
    return (uint64_t(x - box_[0][0]) * size_[1] + uint64_t(y - box_[0][1])) * size_[2] + uint64_t(z - box_[0][2]);
  }
  bool contains(int x, int y, int z) const {
    return x >= box_[0][0] && x < box_[1][0] && y >= box_[0][1] && y < box_[1][1] && z >= box_[0][2] && z < box_[1][2];
  }
  bool get(uint64_t i) const { return (words_[i >> 6] >> (i & 63)) & 1u; }
  void set(uint64_t i, bool value) {
    if (value)
      words_[i >> 6] |= uint64_t(1) << (i & 63);
    else
      words_[i >> 6] &= ~(uint64_t(1) << (i & 63));
  }
  std::array<int, 3> point(uint64_t i) const;

 private:
  VoxelBox box_{};
  std::array<uint64_t, 3> size_{};
  std::vector<uint64_t> words_;
};

// Marks the voxels of a tile's sampled band that are material (value < 0) as not void; voxels of
// blocks the band left out are void (outside the body, or far from every wall), solid blocks material.
void record_material(const SampledBand& band, VoxelBits& void_bits);

}  // namespace offsetgen::mesh
