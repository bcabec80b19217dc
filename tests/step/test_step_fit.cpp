// The parts of `offsetgen step` below the B-rep: the B-spline fit, the Schwarz P symmetry patch and
// the cell's symmetries.
#include "mesh/wall_field.h"
#include "step/bspline_fit.h"
#include "step/cell_symmetry.h"
#include "step/schwarzp_patch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace offsetgen::step {
namespace {

TEST(StepFit, ReproducesABicubicPolynomialSurfaceToRoundingError) {
  // Every coordinate a cubic in u times a cubic in v: in the span of any clamped cubic B-spline basis.
  auto f = [](double u, double v) {
    return Point{u + 0.3 * u * u * u, v - 0.2 * v * v + 0.1 * u * v * v * v,
                 (1 - 2 * u + u * u * u) * (0.5 + v * v - v * v * v)};
  };
  const int m = 25;
  std::vector<Point> samples;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) samples.push_back(f(double(i) / (m - 1), double(j) / (m - 1)));
  for (int n : {4, 6, 9}) {
    const CubicPatch patch = fit_patch(samples, m, n);
    double worst = 0;
    for (double u = 0; u <= 1; u += 0.037)
      for (double v = 0; v <= 1; v += 0.041) {
        const Point a = patch.evaluate(u, v), b = f(u, v);
        worst = std::max(worst, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
      }
    EXPECT_LT(worst, 1e-12) << n << " control points a side";
  }
}

TEST(StepFit, BoundaryCurvesComeFromTheirOwnSamplesOnly) {
  // Two sample grids that differ only inside give the same boundary control points (bitwise): two
  // patches that share a boundary's samples share its curve.
  const int m = 13, n = 5;
  std::vector<Point> a, b;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = double(i) / (m - 1), v = double(j) / (m - 1);
      const Point p{u, v, std::sin(3 * u) * std::cos(2 * v)};
      a.push_back(p);
      const bool inside = i > 0 && j > 0 && i < m - 1 && j < m - 1;
      b.push_back(inside ? Point{p[0], p[1], p[2] + 0.1 * u * v} : p);
    }
  const CubicPatch pa = fit_patch(a, m, n), pb = fit_patch(b, m, n);
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(pa.at(0, k), pb.at(0, k));
    EXPECT_EQ(pa.at(n - 1, k), pb.at(n - 1, k));
    EXPECT_EQ(pa.at(k, 0), pb.at(k, 0));
    EXPECT_EQ(pa.at(k, n - 1), pb.at(k, n - 1));
  }
  EXPECT_NE(pa.at(2, 2), pb.at(2, 2));
}

TEST(StepSymmetry, TheFortyEightCellImagesAreDistinctAndKeepSchwarzP) {
  auto schwarzp = [](const Point& p) {
    return std::cos(2 * M_PI * p[0]) + std::cos(2 * M_PI * p[1]) + std::cos(2 * M_PI * p[2]);
  };
  const Point p{0.31, 0.17, 0.08};
  std::set<Point> images;
  int reversing = 0;
  for (const CellImage& image : cell_images()) {
    const Point q = image.apply(p);
    images.insert(q);
    EXPECT_NEAR(schwarzp(q), schwarzp(p), 1e-12);
    reversing += image.reverses() ? 1 : 0;
  }
  EXPECT_EQ(images.size(), 48u);
  EXPECT_EQ(reversing, 24);
}

TEST(StepPatch, SchwarzPPatchBoundariesLieExactlyOnTheirMirrorPlanes) {
  mesh::WallRequest request;
  request.generation.surface = "schwarzp";
  request.thickness = "0.1";
  mesh::WallField field(request);
  field.compile();
  for (double h : {0.05, -0.05}) {
    const LevelFunction g = [&field, h](size_t n, const double* x, const double* y, const double* z, double* out) {
      const std::vector<double> hs(n, h);
      field.offsets(n, x, y, z, hs.data(), out);
    };
    const int m = 19, n = 6;
    const std::vector<Point> points = schwarzp_patch_points(g, m);
    // The samples are on the offset surface.
    for (const Point& p : points) {
      double value = 0;
      g(1, &p[0], &p[1], &p[2], &value);
      EXPECT_LT(std::fabs(value), 1e-12);
    }
    CubicPatch patch = fit_patch(points, m, n);
    for (int k = 0; k < n; ++k) {
      EXPECT_EQ(patch.at(0, k)[0], patch.at(0, k)[1]) << "u = 0 lies on x = y";
      EXPECT_EQ(patch.at(k, 0)[2], 0.0) << "v = 0 lies on z = 0";
      EXPECT_EQ(patch.at(k, n - 1)[1], patch.at(k, n - 1)[2]) << "v = 1 lies on y = z";
      EXPECT_NEAR(patch.at(n - 1, k)[0], 0.5, 1e-14) << "u = 1 lies on x = 1/2 (snapped exactly)";
    }
    snap_schwarzp_boundary(patch);
    for (int k = 0; k < n; ++k) EXPECT_EQ(patch.at(n - 1, k)[0], 0.5);
  }
}

TEST(StepPatch, NormalJumpAcrossMirrorPlanesShrinksTowardZeroAsTheFitConverges) {
  // The exact surface meets its mirror planes at right angles, so the measured jump of a fit must
  // fall toward 0 with more control points (wrong plane normals would leave it large).
  mesh::WallRequest request;
  request.generation.surface = "schwarzp";
  request.thickness = "0.1";
  mesh::WallField field(request);
  field.compile();
  const LevelFunction g = [&field](size_t n, const double* x, const double* y, const double* z, double* out) {
    const std::vector<double> hs(n, 0.05);
    field.offsets(n, x, y, z, hs.data(), out);
  };
  std::vector<double> jumps;
  for (int n : {5, 8, 16}) {
    const int m = 3 * n + 1;
    CubicPatch patch = fit_patch(schwarzp_patch_points(g, m), m, n);
    snap_schwarzp_boundary(patch);
    jumps.push_back(schwarzp_normal_jump(patch, 100) * 180 / M_PI);
  }
  EXPECT_GT(jumps[0], jumps[1]);
  EXPECT_GT(jumps[1], jumps[2]);
  EXPECT_LT(jumps[2], 0.2) << "degrees at 16 x 16";
  EXPECT_GT(jumps[2], 0.0);
}

}  // namespace
}  // namespace offsetgen::step
