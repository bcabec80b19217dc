// The block of cells mesh, step and slice make: a positive number of cells on each axis and a positive,
// finite cell size, the same on every axis (a cube cell) or not (a box cell: "distorted cells").
// Checked here only, for every command and library caller alike.
#pragma once

#include <array>

namespace offsetgen {

// Throws InputError naming --cells or --cell-size.
void check_block(const std::array<int, 3>& cells, double cell_size);
void check_block(const std::array<int, 3>& cells, const std::array<double, 3>& cell_size);

// Throws InputError naming --cell-size where a side is not a positive length.
void check_cell_size(const std::array<double, 3>& cell_size);

// Whether a cell's three sides are equal: a cube cell, the lattice in cell units as without a box cell.
bool cube_cell(const std::array<double, 3>& cell_size);

// A positive, finite length (mm).
bool positive_length(double x);

}  // namespace offsetgen
