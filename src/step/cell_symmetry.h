// The 48 symmetries of a cubic cell [0, 1]^3 that map the Schwarz P sheet onto itself: a permutation
// of the coordinates, then a mirror x -> 1 - x on some of them. Applied to control points they are
// exact on the mirror planes (a permutation moves numbers, 1 - 1/2 = 1/2), so the images of a patch
// meet their neighbours' images on bitwise equal boundary curves.
#pragma once

#include "step/bspline_fit.h"

#include <array>
#include <vector>

namespace offsetgen::step {

struct CellImage {
  std::array<int, 3> from{0, 1, 2};  // coordinate a of the image is coordinate from[a] of the original
  std::array<bool, 3> mirror{};      // then a -> 1 - a
  Point apply(const Point& p) const;
  // Whether the orientation is reversed (an odd number of transpositions and mirrors).
  bool reverses() const;
  // The axis and the side (0 or 1) of the cell face that the plane z = 0 goes to.
  int face_axis() const;
  int face_side() const;
};

// All 48, in a fixed order.
const std::vector<CellImage>& cell_images();

}  // namespace offsetgen::step
