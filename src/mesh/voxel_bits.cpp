#include "mesh/voxel_bits.h"

namespace offsetgen::mesh {

VoxelBits::VoxelBits(const VoxelBox& box, bool value) : box_(box) {
  for (size_t a = 0; a < 3; ++a) size_[a] = uint64_t(std::max(0, box[1][a] - box[0][a]));
  words_.assign((count() + 63) / 64, value ? ~uint64_t(0) : 0);
}

std::array<int, 3> VoxelBits::point(uint64_t i) const {
  const auto z = int(i % size_[2]);
  i /= size_[2];
  const auto y = int(i % size_[1]);
  const auto x = int(i / size_[1]);
  return {x + box_[0][0], y + box_[0][1], z + box_[0][2]};
}

void record_material(const SampledBand& band, VoxelBits& void_bits) {
  for (const BandBlock& block : band.blocks)
    for (int x = 0; x < kBlock; ++x)
      for (int y = 0; y < kBlock; ++y)
        for (int z = 0; z < kBlock; ++z) {
          const int px = block.origin[0] + x, py = block.origin[1] + y, pz = block.origin[2] + z;
          if (!void_bits.contains(px, py, pz)) continue;
          const bool material = block.solid || block.values[size_t(block_offset(x, y, z))] < 0;
          if (material) void_bits.set(void_bits.index(px, py, pz), false);
        }
}

}  // namespace offsetgen::mesh
