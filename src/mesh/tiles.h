// Tiles: the domain's voxels cut into cubes of `size` voxels a side (a multiple of kBlock), meshed one
// at a time so that memory stays bounded whatever the part's size. A tile owns the polygons of its
// voxels (vdb_surface.h) and samples one block more on every side, so the polygons along a seam come
// from the same samples on both sides: the tiles together give exactly the untiled mesh (adaptivity
// 0), seams watertight, no polygon lost or doubled. Their order is fixed (x outermost), so the parts
// of a split run (--tile-range I/N) join in order.
#pragma once

#include "mesh/narrow_band.h"

#include <string>
#include <utility>
#include <vector>

namespace offsetgen::mesh {

struct Tile {
  VoxelBox owned;   // voxels whose polygons this tile writes
  VoxelBox blocks;  // block origins it samples: owned and one block around it, within the domain
};

// `range`: the domain's block range; size 0: one tile, the whole range.
std::vector<Tile> make_tiles(const VoxelBox& range, int size);
// The tiles across each face of tile `t`: [axis][0] below, [axis][1] above; -1 where the domain ends.
std::array<std::array<long, 2>, 3> tile_neighbours(const std::vector<Tile>& tiles, size_t t);

// "I/N" (--tile-range): share I (0-based) of N. Throws InputError.
std::pair<int, int> parse_tile_range(const std::string& text);
// The tiles [first, last) of share `index` of `count`: contiguous, as equal as whole tiles allow.
std::pair<size_t, size_t> tile_share(size_t tiles, int index, int count);

}  // namespace offsetgen::mesh
