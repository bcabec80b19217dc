// Exact anti-aliasing: the area of a set of closed polygons inside each pixel (polygon ∩ pixel), from
// their edges alone. Each edge is cut at every pixel row and column; a piece inside pixel (c, r) with
// a signed height dv adds dv (1 - m) to that pixel and dv m to the next one in its row (m: the piece's
// mean position across the pixel), and a running sum along each row turns those into the signed
// covered area. Outer loops counter-clockwise and holes clockwise (in image coordinates with v up) add
// up to the coverage of the part, in [0, 1].
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace offsetgen::slice {

class CoverageRaster {
 public:
  // Pixel (c, r) covers [c, c + 1] x [r, r + 1] in (u, v).
  CoverageRaster(int width, int height);
  void add_edge(std::array<double, 2> a, std::array<double, 2> b);
  // Row r's coverage as 0..255 (rounded), after every edge is in. `sign` +1 or -1: which orientation
  // counts as inside.
  void row(int r, double sign, std::vector<uint8_t>& out) const;
  // The covered area, in pixels.
  double area(double sign) const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  std::vector<double> acc_;  // (width + 2) per row
};

}  // namespace offsetgen::slice
