// What bounds the lattice: a block of cells (box_domain.h) or a body with a skin (body_domain.h). The
// sampler reads, block by block, the domain's signed distance d (voxels, negative inside) and builds
// the part from it and the lattice wall w (wall/part_value.h).
#pragma once

#include "wall/part_value.h"

#include <array>
#include <memory>

namespace offsetgen::mesh {

struct PartEdits;  // part_edits.h

// Where a block of voxels lies relative to the domain.
enum class BlockPlace {
  Outside,  // every voxel at least `margin` outside: nothing of the part there
  Deep,     // every voxel deeper inside than skin + fillet + margin: the part is the lattice alone
  Mixed,    // d was filled in
};

// Reads d for blocks; one per thread.
class DomainReader {
 public:
  virtual ~DomainReader() = default;
  // d of the kBlock^3 voxels of the block whose first voxel is `origin` (block order, narrow_band.h),
  // filled only for Mixed. `margin` is in voxels.
  virtual BlockPlace read_block(const std::array<int, 3>& origin, double margin, double* d) = 0;
};

class Domain {
 public:
  virtual ~Domain() = default;
  virtual std::unique_ptr<DomainReader> reader() const = 0;
  // The voxel indices [first, last) to sample on each axis, multiples of kBlock.
  virtual std::array<std::array<int, 3>, 2> block_range() const = 0;
  // Voxels with d above this are outside the part whatever the lattice does, so the walls are not
  // evaluated there (the box's faces lie halfway between voxels: one voxel suffices).
  virtual double lattice_margin() const = 0;
  double skin = 0;                   // voxels
  double fillet = 0;                 // voxels
  const PartEdits* edits = nullptr;  // drain holes and filled pockets (--drain, --fill-pockets)
};

using wall::part_value;
using wall::part_value_without_wall;
using wall::wall_matters;

}  // namespace offsetgen::mesh
