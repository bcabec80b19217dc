// The exact volume of a wall, for the tests that hold a file against it (mesh, step): column quadrature
// (numeric/volume_fraction.h) of this process's own wall functions (wall/wall_field.h), not the tool's
// measurement, with a seed of its own.
#pragma once

#include "wall/wall_field.h"

#include <array>
#include <string>

namespace offsetgen::test_support {

struct ExactWallVolume {
  double volume = 0;          // mm^3
  double standard_error = 0;  // mm^3, of the quadrature
};

// The uniform wall of `surface` (order 4, total thickness `thickness` in cell units) in a block of whole
// periodic cells of `cell_size` mm: one cell's volume fraction times the cells. `grid`: the columns per
// side of each shift, more where the wall is thin and curved.
ExactWallVolume exact_wall_volume(const std::string& surface, const std::string& thickness,
                                  const std::array<int, 3>& cells, double cell_size, int grid = 40);

}  // namespace offsetgen::test_support
