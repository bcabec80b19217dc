// slice/layer_contours.h on layers of a gyroid block (density 0.2, 8 mm cells): every vertex off the
// box's sides on the wall's zero set (distance estimate |w| / |grad w| within 1e-6 mm), the solid on
// the left of every edge (outer loops counter-clockwise, holes clockwise), each chord within the
// tolerance of the contour at its midpoint (a sign change of G across the chord within the
// tolerance, checked here), and the same loops on 1 and 2 sampling threads.
#include "slice/layer_contours.h"
#include "slice_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace offsetgen::slice {
namespace {

LayerSetup setup_at(double z_mm, double tolerance = 0.005) {
  const wall::WallField& field = test::gyroid_field();
  LayerSetup s;
  s.cells = {2, 2};
  s.cell_size = 8;
  s.z = z_mm / s.cell_size;
  const auto extent = field.extent(field.thickness_range(std::array<int, 3>{2, 2, 2}));
  s.pixels_per_cell = static_cast<int>(std::ceil(4 / extent.thinnest));
  s.reach = extent.reach;
  s.tolerance = tolerance;
  s.threads = 2;
  return s;
}

class GyroidLayer : public ::testing::TestWithParam<double> {};

TEST_P(GyroidLayer, VerticesOnTheWallSolidOnTheLeftChordsWithinTolerance) {
  const wall::WallField& field = test::gyroid_field();
  const double z = GetParam();
  const LayerSetup s = setup_at(z);
  const LayerContours c = layer_contours(field, s);
  ASSERT_GT(c.loops.size(), 2u);
  EXPECT_EQ(c.unverified_chords, 0u);
  EXPECT_LE(c.max_deviation, s.tolerance);
  std::vector<std::array<double, 2>> wall_points, left, mids_lo, mids_hi;
  // Beyond the chord's own deviation from the contour (up to the tolerance) to the left of its midpoint.
  const double step = 2.5 * s.tolerance;
  double area = 0;
  for (const Loop& loop : c.loops) {
    ASSERT_GE(loop.points.size(), 3u);
    area += loop.area;
    for (size_t k = 0; k < loop.points.size(); ++k) {
      const Point2& a = loop.points[k];
      const Point2& b = loop.points[(k + 1) % loop.points.size()];
      if (!on_box_side(s, a, 1e-9)) wall_points.push_back(a);
      const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
      ASSERT_GT(len, 0);
      const double nx = -(b[1] - a[1]) / len, ny = (b[0] - a[0]) / len;  // the left normal
      const Point2 m{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
      // Within tolerance: G changes sign across the chord within `tolerance` of its midpoint.
      const double t = s.tolerance * (1 + 1e-9);
      mids_lo.push_back({m[0] - t * nx, m[1] - t * ny});
      mids_hi.push_back({m[0] + t * nx, m[1] + t * ny});
      if (len > 4 * step) left.push_back({m[0] + step * nx, m[1] + step * ny});
    }
  }
  EXPECT_GT(area, 0) << "outer loops are counter-clockwise, so the layer's signed area is its area";
  // No two edges cross (edges that share a vertex aside).
  struct Edge {
    Point2 a, b;
  };
  std::vector<Edge> edges;
  for (const Loop& loop : c.loops)
    for (size_t k = 0; k < loop.points.size(); ++k)
      edges.push_back({loop.points[k], loop.points[(k + 1) % loop.points.size()]});
  auto cross = [](const Point2& o, const Point2& a, const Point2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  size_t crossings = 0;
  for (size_t i = 0; i < edges.size(); ++i)
    for (size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &e = edges[i], &f = edges[j];
      if (e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b) continue;
      const double d1 = cross(e.a, e.b, f.a), d2 = cross(e.a, e.b, f.b), d3 = cross(f.a, f.b, e.a),
                   d4 = cross(f.a, f.b, e.b);
      crossings += ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
    }
  EXPECT_EQ(crossings, 0u) << "edges that cross";
  const std::vector<double> d = test::wall_distances(field, wall_points, z, s.cell_size);
  double worst = 0;
  for (double v : d) worst = std::max(worst, v);
  EXPECT_LT(worst, 1e-6) << "a vertex is " << worst << " mm off the wall";
  const std::vector<double> lo = test::level(field, mids_lo, z, s.cell_size, s.cells);
  const std::vector<double> hi = test::level(field, mids_hi, z, s.cell_size, s.cells);
  size_t beyond = 0;
  for (size_t k = 0; k < lo.size(); ++k) beyond += (lo[k] < 0) == (hi[k] < 0);
  EXPECT_EQ(beyond, 0u) << "chords whose midpoint is more than the tolerance off the contour";
  const std::vector<double> g = test::level(field, left, z, s.cell_size, s.cells);
  size_t outside = 0;
  for (double v : g) outside += v >= 0;
  // Just left of a chord is inside, except where a chord cuts across a bend of the contour by less
  // than the tolerance.
  EXPECT_LT(double(outside), 0.01 * double(g.size())) << outside << " of " << g.size();
}

INSTANTIATE_TEST_SUITE_P(Heights, GyroidLayer, ::testing::Values(0.3, 0.525, 2.0, 5.55, 8.0, 13.1));

TEST(GyroidLayerThreads, OneAndTwoSamplingThreadsGiveTheSameLoops) {
  const wall::WallField& field = test::gyroid_field();
  LayerSetup s = setup_at(3.3);
  const LayerContours two = layer_contours(field, s);
  s.threads = 1;
  const LayerContours one = layer_contours(field, s);
  ASSERT_EQ(one.loops.size(), two.loops.size());
  for (size_t k = 0; k < one.loops.size(); ++k) EXPECT_EQ(one.loops[k].points, two.loops[k].points);
}

TEST(GyroidLayerTolerance, AFinerToleranceGivesMoreVerticesAndStillHoldsIt) {
  const wall::WallField& field = test::gyroid_field();
  const LayerContours coarse = layer_contours(field, setup_at(4.4, 0.02));
  const LayerContours fine = layer_contours(field, setup_at(4.4, 0.001));
  EXPECT_GT(fine.vertices, coarse.vertices);
  EXPECT_LE(fine.max_deviation, 0.001);
  EXPECT_LE(coarse.max_deviation, 0.02);
  EXPECT_EQ(fine.unverified_chords, 0u);
}

}  // namespace
}  // namespace offsetgen::slice
