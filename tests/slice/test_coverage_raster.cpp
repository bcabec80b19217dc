// slice/coverage_raster.h: exact pixel coverage of polygons (a square on fractional coordinates, an
// annulus-like square with a square hole, a triangle's area) against areas computed by hand.
#include "slice/coverage_raster.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace offsetgen::slice {
namespace {

using P = std::array<double, 2>;

void add_loop(CoverageRaster& r, const std::vector<P>& loop) {
  for (size_t k = 0; k < loop.size(); ++k) r.add_edge(loop[k], loop[(k + 1) % loop.size()]);
}

// Counter-clockwise in (u, v) with v up counts negative in the running sum: sign -1 is inside.
TEST(CoverageRaster, SquareOnFractionalCoordinatesCoversItsExactArea) {
  CoverageRaster r(10, 10);
  add_loop(r, {{1.25, 2.5}, {6.75, 2.5}, {6.75, 7.25}, {1.25, 7.25}});
  EXPECT_NEAR(r.area(-1), 5.5 * 4.75, 1e-9);
  std::vector<uint8_t> row;
  r.row(2, -1, row);  // half of row 2 covered in v
  EXPECT_EQ(row[0], 0);
  EXPECT_EQ(row[1], 96);  // 3/4 x 1/2 = 0.375 -> 95.6
  EXPECT_EQ(row[3], 128);
  r.row(4, -1, row);
  EXPECT_EQ(row[3], 255);
  EXPECT_EQ(row[6], 191);  // 3/4
  EXPECT_EQ(row[7], 0);
}

TEST(CoverageRaster, HoleClockwiseIsSubtracted) {
  CoverageRaster r(12, 12);
  add_loop(r, {{1, 1}, {11, 1}, {11, 11}, {1, 11}});
  add_loop(r, {{3.5, 3.5}, {3.5, 8.5}, {8.5, 8.5}, {8.5, 3.5}});  // clockwise
  EXPECT_NEAR(r.area(-1), 100 - 25, 1e-9);
  std::vector<uint8_t> row;
  r.row(5, -1, row);
  EXPECT_EQ(row[2], 255);
  EXPECT_EQ(row[3], 128);
  EXPECT_EQ(row[5], 0);
}

TEST(CoverageRaster, SlantedTriangleAreaIsExact) {
  CoverageRaster r(20, 20);
  add_loop(r, {{0.3, 0.7}, {17.9, 4.1}, {6.2, 15.35}});
  const double area = 0.5 * ((17.9 - 0.3) * (15.35 - 0.7) - (6.2 - 0.3) * (4.1 - 0.7));
  EXPECT_NEAR(r.area(-1), area, 1e-9);
}

}  // namespace
}  // namespace offsetgen::slice
