#include "validate/block_checks.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <cmath>

namespace offsetgen {

bool positive_length(double x) { return x > 0 && std::isfinite(x); }

void check_block(const std::array<int, 3>& cells, double cell_size) {
  for (int n : cells)
    if (n < 1) throw InputError(fmt::format("--cells: {} is not a positive number of cells", n));
  if (!positive_length(cell_size))
    throw InputError(fmt::format("--cell-size {} is not a positive length (mm)", cell_size));
}

void check_cell_size(const std::array<double, 3>& cell_size) {
  for (double side : cell_size)
    if (!positive_length(side)) throw InputError(fmt::format("--cell-size {} is not a positive length (mm)", side));
}

void check_block(const std::array<int, 3>& cells, const std::array<double, 3>& cell_size) {
  check_block(cells, cell_size[0]);
  check_cell_size(cell_size);
}

bool cube_cell(const std::array<double, 3>& cell_size) {
  return cell_size[0] == cell_size[1] && cell_size[1] == cell_size[2];
}

}  // namespace offsetgen
