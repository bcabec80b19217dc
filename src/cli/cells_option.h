// --cells NX[xNY[xNZ]] and --cell-size MM or X,Y,Z, shared by `offsetgen mesh`, `step` and `slice`.
#pragma once

#include <array>
#include <string>

namespace offsetgen {

// "3" -> {3, 3, 3}; "4x2" -> {4, 2, 2}; "2x3x4" -> {2, 3, 4}. Throws InputError.
std::array<int, 3> parse_cells(const std::string& text);

// "10" -> {10, 10, 10} (a cube cell); "10,10,15" -> {10, 10, 15} (a box cell, "distorted cells": the
// lattice u = x/X, v = y/Y, w = z/Z). Throws InputError for a wrong count, a non-number, or a size that
// is not a positive length (validate/block_checks.h).
std::array<double, 3> parse_cell_size(const std::string& text);

}  // namespace offsetgen
