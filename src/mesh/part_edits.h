// What --drain and --fill-pockets change in the part before it is meshed (issue 43), in the sampler's
// voxel index coordinates (voxel i centred at i): drain holes cut into the level set (wall/drain_holes.h)
// and enclosed pockets made solid. Applied to each sampled block (narrow_band.cpp), so the part stays
// one closed solid and the tiles' seams agree.
#pragma once

#include "mesh/voxel_bits.h"
#include "wall/drain_holes.h"

#include <vector>

namespace offsetgen::mesh {

struct PartEdits {
  std::vector<wall::DrainHole> holes;  // voxel index coordinates; radius in voxels
  const VoxelBits* filled = nullptr;   // voxels to make solid; null: none
};

// The value a pocket's voxel gets: inside, a voxel deep (the neighbours it touches are all material).
inline constexpr float kFilledValue = -1.0f;

// Applies the edits to the values of the block whose first voxel is `origin`; `values` empty means
// the block was left void (filled in with `background` if an edit reaches it). Returns false when no
// edit touches the block.
bool apply_part_edits(const PartEdits& edits, const std::array<int, 3>& origin, float background,
                      std::vector<float>& values);

}  // namespace offsetgen::mesh
