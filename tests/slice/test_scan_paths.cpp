// --hatch and --beam-offset's geometry (slice/scan_paths.h) on shapes whose answers are known: a
// square with a square hole hatched to its exact area, lines parallel and SPACING apart, every endpoint on
// a loop and every midpoint inside, a vertex on a scan line counted once; circles and an annulus offset
// to the exact radii (Clipper), a strip thinner than twice the offset gone; the --hatch text parsed or
// refused.
#include "plane_geometry.h"
#include "slice/scan_paths.h"
#include "surfaces/input_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace offsetgen::slice {
namespace {

using test::distance_to_rings;
using test::inside_rings;
using test::Ring;

const double kPi = std::acos(-1.0);

Loop loop_of(const std::vector<Point2>& points) {
  Loop l;
  l.points = points;
  l.area = test::ring_area(points);
  return l;
}

Loop circle(double cx, double cy, double r, int n, bool hole) {
  std::vector<Point2> p;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n * (hole ? -1 : 1);
    p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return loop_of(p);
}

std::vector<Ring> rings_of(const std::vector<Loop>& loops) {
  std::vector<Ring> rings;
  for (const Loop& l : loops) rings.push_back(l.points);
  return rings;
}

double total_length(const std::vector<Hatch>& hatches) {
  double s = 0;
  for (const Hatch& h : hatches) s += std::hypot(h.end[0] - h.start[0], h.end[1] - h.start[1]);
  return s;
}

// [0, 10]^2 counter-clockwise less the hole [3, 7]^2 clockwise: 84 mm^2.
std::vector<Loop> square_with_hole() {
  return {loop_of({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), loop_of({{3, 3}, {3, 7}, {7, 7}, {7, 3}})};
}

TEST(HatchLoops, SquareWithAHoleAtZeroDegreesIsCoveredToItsExactArea) {
  const std::vector<Loop> loops = square_with_hole();
  const std::vector<Hatch> h = hatch_loops(loops, 1.0, 0);
  // Lines at y = 0.5 ... 9.5: six whole ones, four cut in two by the hole.
  EXPECT_EQ(h.size(), 6u + 2 * 4u);
  EXPECT_NEAR(total_length(h) * 1.0, 84.0, 1e-12);
  for (const Hatch& s : h) {
    EXPECT_EQ(s.start[1], s.end[1]);
    EXPECT_NEAR(std::fmod(s.start[1], 1.0), 0.5, 1e-12);
  }
}

TEST(HatchLoops, LinesRunBackAndForthInOrderOfTheirOffset) {
  const std::vector<Hatch> h = hatch_loops({loop_of({{0, 0}, {10, 0}, {10, 4}, {0, 4}})}, 1.0, 0);
  ASSERT_EQ(h.size(), 4u);
  for (size_t k = 0; k < h.size(); ++k) {
    EXPECT_DOUBLE_EQ(h[k].start[1], 0.5 + double(k));
    // Line j = 0 left to right, j = 1 right to left, ...
    EXPECT_EQ(h[k].start[0], k % 2 == 0 ? 0.0 : 10.0);
    EXPECT_EQ(h[k].end[0], k % 2 == 0 ? 10.0 : 0.0);
  }
}

class HatchAngle : public ::testing::TestWithParam<double> {};

TEST_P(HatchAngle, AnnulusHatchesAreParallelSpacingApartEndOnTheLoopsAndCoverTheArea) {
  const double angle = GetParam(), spacing = 0.05;
  const std::vector<Loop> loops = {circle(1, 2, 5, 720, false), circle(1.5, 2, 2, 360, true)};
  const std::vector<Ring> rings = rings_of(loops);
  const std::vector<Hatch> h = hatch_loops(loops, spacing, angle);
  ASSERT_GT(h.size(), 100u);
  const double a = angle * kPi / 180, dx = std::cos(a), dy = std::sin(a);
  double area = 0;
  for (const Loop& l : loops) area += l.area;
  for (const Hatch& s : h) {
    const double len = std::hypot(s.end[0] - s.start[0], s.end[1] - s.start[1]);
    ASSERT_GT(len, 0);
    // Parallel to the hatch direction: the cross product with it vanishes.
    EXPECT_NEAR(((s.end[0] - s.start[0]) * dy - (s.end[1] - s.start[1]) * dx) / len, 0, 1e-9);
    // On a line p . n = (j + 1/2) spacing.
    const double t = (-s.start[0] * dy + s.start[1] * dx) / spacing - 0.5;
    EXPECT_NEAR(t, std::round(t), 1e-9);
    EXPECT_LT(distance_to_rings(s.start, rings), 1e-12);
    EXPECT_LT(distance_to_rings(s.end, rings), 1e-12);
    EXPECT_TRUE(inside_rings({0.5 * (s.start[0] + s.end[0]), 0.5 * (s.start[1] + s.end[1])}, rings));
  }
  // Length times spacing is the area, to the lines' sampling of it.
  EXPECT_NEAR(total_length(h) * spacing / area, 1.0, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Degrees, HatchAngle, ::testing::Values(0.0, 30.0, 66.67, 90.0, 133.34, 179.9));

TEST(HatchLoops, AVertexOnAScanLineIsCountedOnce) {
  // Lines 0.5 apart lie at y = (j + 1/2) 0.5: ..., -0.75, -0.25, 0.25, 0.75, 1.25. The left vertex
  // (0, 0.25) of this triangle lies on one: that line's hatch must still run from it to the right side.
  const std::vector<Hatch> left = hatch_loops({loop_of({{0, 0.25}, {2, -1}, {2, 1.5}})}, 0.5, 0);
  ASSERT_EQ(left.size(), 5u);
  for (const Hatch& h : left) {
    const double y = h.start[1];
    EXPECT_NEAR(std::abs(h.end[0] - h.start[0]), 2 - 2 * std::abs(y - 0.25) / 1.25, 1e-12) << "y = " << y;
  }
  EXPECT_DOUBLE_EQ(left[2].start[1], 0.25);
  // The apex (1, 0.75) touches the line y = 0.75: no hatch there, one at y = 0.25.
  const std::vector<Hatch> apex = hatch_loops({loop_of({{0, 0}, {2, 0}, {1, 0.75}})}, 0.5, 0);
  ASSERT_EQ(apex.size(), 1u);
  EXPECT_DOUBLE_EQ(apex[0].start[1], 0.25);
  EXPECT_NEAR(std::abs(apex[0].end[0] - apex[0].start[0]), 4.0 / 3.0, 1e-12);
}

TEST(HatchPattern, AngleTurnsByTheRotationEachLayerWithinZeroTo180) {
  const HatchPattern h{0.1, 10, 66.67};
  EXPECT_DOUBLE_EQ(h.angle_of_layer(0), 10);
  EXPECT_NEAR(h.angle_of_layer(1), 76.67, 1e-12);
  EXPECT_NEAR(h.angle_of_layer(3), std::fmod(10 + 3 * 66.67, 180), 1e-12);
  const HatchPattern back{0.1, 0, -90};
  EXPECT_DOUBLE_EQ(back.angle_of_layer(1), 90);
  for (size_t k = 0; k < 1000; ++k) {
    const double a = HatchPattern{0.1, -400, -66.67}.angle_of_layer(k);
    EXPECT_GE(a, 0);
    EXPECT_LT(a, 180);
  }
}

TEST(HatchPattern, ParsesSpacingAngleRotationAndRefusesTheRest) {
  const HatchPattern d = parse_hatch("0.1");
  EXPECT_EQ(d.spacing, 0.1);
  EXPECT_EQ(d.angle, 0);
  EXPECT_EQ(d.rotation, 66.67);
  const HatchPattern all = parse_hatch("0.08,45,90");
  EXPECT_EQ(all.spacing, 0.08);
  EXPECT_EQ(all.angle, 45);
  EXPECT_EQ(all.rotation, 90);
  for (const char* bad : {"", "0", "-0.1", "abc", "0.1,", "0.1,x", "0.1,1,2,3", "nan", "inf", "0.1,inf", "0.1mm"})
    EXPECT_THROW(parse_hatch(bad), InputError) << "'" << bad << "'";
}

TEST(OffsetInward, CircleShrinksToTheSmallerRadiusWithinTheArcTolerance) {
  const double r = 5, d = 1, tol = 1e-3;
  const std::vector<Loop> out = offset_inward({circle(0, 0, r, 2000, false)}, d, tol, 0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_GT(out[0].area, 0) << "still counter-clockwise";
  // The polygon's chords sit up to r (1 - cos(pi/2000)) = 6e-6 inside the circle.
  for (const Point2& p : out[0].points) EXPECT_NEAR(std::hypot(p[0], p[1]), r - d, tol + 1e-5);
  EXPECT_NEAR(out[0].area, kPi * (r - d) * (r - d), 1e-3 * kPi * (r - d) * (r - d));
}

TEST(OffsetInward, AnnulusOuterShrinksHoleGrowsOrientationsKept) {
  const std::vector<Loop> out =
      offset_inward({circle(0, 0, 5, 1000, false), circle(0, 0, 2, 1000, true)}, 0.5, 1e-4, 0);
  ASSERT_EQ(out.size(), 2u);
  size_t outer = 0, hole = 0;
  for (const Loop& l : out) {
    const double radius = l.area > 0 ? 4.5 : 2.5;
    (l.area > 0 ? outer : hole)++;
    for (const Point2& p : l.points) EXPECT_NEAR(std::hypot(p[0], p[1]), radius, 1e-3);
  }
  EXPECT_EQ(outer, 1u);
  EXPECT_EQ(hole, 1u);
}

TEST(OffsetInward, EveryVertexOfAnOffsetSquareWithAHoleIsTheOffsetFromTheOriginal) {
  const std::vector<Loop> loops = square_with_hole();
  const std::vector<Loop> out = offset_inward(loops, 0.4, 1e-4, 0);
  const std::vector<Ring> before = rings_of(loops);
  double area = 0;
  for (const Loop& l : out) {
    area += l.area;
    for (const Point2& p : l.points) {
      EXPECT_NEAR(distance_to_rings(p, before), 0.4, 1e-4 + 1e-6);
      EXPECT_TRUE(inside_rings(p, before));
    }
  }
  // 9.2^2 less (4.8^2 with its corners rounded: 4 (1 - pi/4) 0.4^2 less).
  EXPECT_NEAR(area, 9.2 * 9.2 - (4.8 * 4.8 - 4 * (1 - kPi / 4) * 0.16), 1e-3);
}

TEST(OffsetInward, AStripThinnerThanTwiceTheOffsetVanishes) {
  const std::vector<Loop> strip = {loop_of({{0, 0}, {10, 0}, {10, 0.5}, {0, 0.5}})};
  EXPECT_TRUE(offset_inward(strip, 0.3, 1e-4, 0).empty());
  EXPECT_EQ(offset_inward(strip, 0.2, 1e-4, 0).size(), 1u);
  // A loop left with less than min_area is dropped.
  EXPECT_TRUE(offset_inward(strip, 0.2, 1e-4, 1.0).empty());
}

TEST(ScanLayer, OffsetThenHatchesInsideTheOffsetLoopsAndVerticesRecounted) {
  LayerContours c;
  c.loops = square_with_hole();
  c.vertices = 8;
  ScanSetup s;
  s.hatch = HatchPattern{0.25, 0, 90};
  s.beam_offset = 0.5;
  s.tolerance = 1e-3;
  const std::vector<Hatch> h = scan_layer(s, 1, c);  // layer 1: 90 degrees
  size_t vertices = 0;
  for (const Loop& l : c.loops) vertices += l.points.size();
  EXPECT_EQ(c.vertices, vertices);
  EXPECT_GT(vertices, 8u);  // the hole's corners became arcs
  const std::vector<Ring> rings = rings_of(c.loops);
  ASSERT_FALSE(h.empty());
  for (const Hatch& line : h) {
    EXPECT_NEAR(line.start[0], line.end[0], 1e-12) << "vertical at 90 degrees";
    EXPECT_LT(distance_to_rings(line.start, rings), 1e-9);
    EXPECT_LT(distance_to_rings(line.end, rings), 1e-9);
  }
}

}  // namespace
}  // namespace offsetgen::slice
