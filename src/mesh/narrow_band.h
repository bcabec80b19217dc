// Sampling the solid's level set in a narrow band around its surface, in blocks of 8^3 voxels (the
// leaf size of OpenVDB's trees). Voxel i of an axis sits at (i + 0.5) * voxel, so no sample lies on
// a face of the box [0, N] (cells).
#pragma once

#include "mesh/domain.h"
#include "wall/wall_field.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace offsetgen::mesh {

inline constexpr int kBlock = 8;
inline constexpr int kBlockVoxels = kBlock * kBlock * kBlock;
// Voxels of a block are stored x-major: (x * 8 + y) * 8 + z, as in an OpenVDB leaf.
inline constexpr int block_offset(int x, int y, int z) { return (x * kBlock + y) * kBlock + z; }

// Voxel indices [first, last) on each axis.
using VoxelBox = std::array<std::array<int, 3>, 2>;

// Voxel i of an axis is centred at (i + 0.5) * voxel (cell units) from the lattice's origin.
struct VoxelGrid {
  int resolution = 32;    // voxels per cell
  double voxel_size = 0;  // cell units; 0: 1 / resolution (a --voxel that need not divide the cell)
  double voxel() const { return voxel_size > 0 ? voxel_size : 1.0 / resolution; }
};

// The sampled band. Values are in voxel units (roughly the distance to the solid's surface), negative
// inside the solid: the part of domain.h (max(w, box) for a block, so the box caps the walls with flat
// faces); clamped to +-background.
// Active voxels are those within 2 voxels of the surface; the others hold their value (or
// `background` where the walls were not evaluated: outside, at least 2 voxels from the surface).
// A block that is solid throughout, with no voxel near the surface (inside a thick skin or strut),
// is kept as `solid` without values: left out, it would read as the background, which is outside.
struct BandBlock {
  std::array<int, 3> origin{};  // index coordinates of the block's first voxel
  std::vector<float> values;    // kBlockVoxels; empty when solid
  std::vector<uint8_t> active;  // kBlockVoxels; empty when solid
  bool solid = false;           // every voxel at least 2 voxels inside: -background throughout
};

// Volumes counted voxel by voxel (in voxels), over the blocks a tile owns: the domain (the body or
// the box), the core (inside the skin; the domain without one), and the core's voxels where the
// lattice alone is solid, a quadrature of the lattice's share of the core that needs no mesh.
struct VoxelTally {
  double body = 0, core = 0;
  double core_voxels = 0, core_solid_voxels = 0;
  VoxelTally& operator+=(const VoxelTally& o) {
    body += o.body;
    core += o.core;
    core_voxels += o.core_voxels;
    core_solid_voxels += o.core_solid_voxels;
    return *this;
  }
};

struct SampledBand {
  std::vector<BandBlock> blocks;  // those with an active voxel, and the solid ones, in a fixed order
  float background = 3.0f;
  size_t blocks_tested = 0;   // blocks of the padded box
  size_t wall_samples = 0;    // voxels where the walls were evaluated
  size_t skipped_voxels = 0;  // voxels ruled out by F at the centre of their block or sub-block
  size_t deep_blocks = 0;     // blocks inside the core, beyond the skin: the lattice alone
  VoxelTally tally;
};

// Samples the band of the part that `domain` bounds with `threads` threads; `progress(fraction)` is
// called from the calling thread. With use_field_bound, blocks whose F value rules out any wall nearby
// are not evaluated; that needs the header's bound M on |grad F| to hold in the whole block (periodic
// surfaces, or a single cell). `reach`: how far from F = 0 the solid's surface gets (wall::WallExtent).
SampledBand sample_band(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
                        bool use_field_bound, int threads, const std::function<void(double)>& progress);
// The same over the blocks whose first voxel lies in `blocks` (multiples of kBlock): one tile, which
// owns the blocks in `owned` (the tally counts those).
SampledBand sample_band(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
                        bool use_field_bound, int threads, const std::function<void(double)>& progress,
                        const VoxelBox& blocks, const VoxelBox& owned);

}  // namespace offsetgen::mesh
