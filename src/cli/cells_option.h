// --cells NX[xNY[xNZ]], shared by `offsetgen mesh` and `offsetgen step`.
#pragma once

#include <array>
#include <string>

namespace offsetgen {

// "3" -> {3, 3, 3}; "4x2" -> {4, 2, 2}; "2x3x4" -> {2, 3, 4}. Throws InputError.
std::array<int, 3> parse_cells(const std::string& text);

}  // namespace offsetgen
