#include "mesh/tiles.h"

#include "surfaces/input_error.h"
#include "validate/share_range.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace offsetgen::mesh {

std::vector<Tile> make_tiles(const VoxelBox& range, int size) {
  std::array<int, 3> step{};
  for (size_t a = 0; a < 3; ++a) step[a] = size > 0 ? size : range[1][a] - range[0][a];
  std::vector<Tile> tiles;
  for (int i = range[0][0]; i < range[1][0]; i += step[0])
    for (int j = range[0][1]; j < range[1][1]; j += step[1])
      for (int l = range[0][2]; l < range[1][2]; l += step[2]) {
        Tile t;
        const std::array<int, 3> lo{i, j, l};
        for (size_t a = 0; a < 3; ++a) {
          t.owned[0][a] = lo[a];
          t.owned[1][a] = std::min(lo[a] + step[a], range[1][a]);
          t.blocks[0][a] = std::max(t.owned[0][a] - kBlock, range[0][a]);
          t.blocks[1][a] = std::min(t.owned[1][a] + kBlock, range[1][a]);
        }
        tiles.push_back(t);
      }
  return tiles;
}

std::array<std::array<long, 2>, 3> tile_neighbours(const std::vector<Tile>& tiles, size_t t) {
  std::array<std::array<long, 2>, 3> across{};
  for (size_t a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      across[a][static_cast<size_t>(side)] = -1;
      for (size_t u = 0; u < tiles.size(); ++u) {
        bool meets = true;
        for (size_t b = 0; b < 3 && meets; ++b)
          meets = b == a ? (side == 0 ? tiles[u].owned[1][b] == tiles[t].owned[0][b]
                                      : tiles[u].owned[0][b] == tiles[t].owned[1][b])
                         : tiles[u].owned[0][b] == tiles[t].owned[0][b];
        if (meets) across[a][static_cast<size_t>(side)] = static_cast<long>(u);
      }
    }
  return across;
}

std::pair<int, int> parse_tile_range(const std::string& text) { return parse_share(text, "--tile-range"); }

std::pair<size_t, size_t> tile_share(size_t tiles, int index, int count) { return share_of(tiles, index, count); }

}  // namespace offsetgen::mesh
