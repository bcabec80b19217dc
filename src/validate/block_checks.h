// The block of cells mesh, step and slice make: a positive number of cells on each axis and a positive,
// finite cell size. Checked here only, for every command and library caller alike.
#pragma once

#include <array>

namespace offsetgen {

// Throws InputError naming --cells or --cell-size.
void check_block(const std::array<int, 3>& cells, double cell_size);

// A positive, finite length (mm).
bool positive_length(double x);

}  // namespace offsetgen
