// The parts of `offsetgen step` below the B-rep: the B-spline fit, the symmetry patches of the
// surfaces with mirror planes and the images that copy them through the block.
#include "step/bspline_fit.h"
#include "step/symmetry_patch.h"
#include "step_test_walls.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <utility>

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

double catalog_value(const std::string& surface, const Point& p) {
  const double x = 2 * M_PI * p[0], y = 2 * M_PI * p[1], z = 2 * M_PI * p[2];
  if (surface == "schwarzp") return std::cos(x) + std::cos(y) + std::cos(z);
  if (surface == "neovius")
    return 3 * (std::cos(x) + std::cos(y) + std::cos(z)) + 4 * std::cos(x) * std::cos(y) * std::cos(z);
  if (surface == "iwp")
    return 2 * (std::cos(x) * std::cos(y) + std::cos(y) * std::cos(z) + std::cos(z) * std::cos(x)) -
           (std::cos(2 * x) + std::cos(2 * y) + std::cos(2 * z));
  if (surface == "frd")
    return 4 * std::cos(x) * std::cos(y) * std::cos(z) -
           (std::cos(2 * x) * std::cos(2 * y) + std::cos(2 * y) * std::cos(2 * z) + std::cos(2 * z) * std::cos(2 * x));
  return std::sin(x) * std::sin(y) * std::sin(z) + std::sin(x) * std::cos(y) * std::cos(z) +
         std::cos(x) * std::sin(y) * std::cos(z) + std::cos(x) * std::cos(y) * std::sin(z);
}

// Every surface with a layout, and the half-thickness its offset sheets are sampled at below (Neovius'
// and F-RD's curvature limits are 0.106 and 0.107 cell).
const std::pair<const char*, double> kLayouts[] = {
    {"schwarzp", 0.05}, {"diamond", 0.05}, {"neovius", 0.025}, {"iwp", 0.05}, {"frd", 0.025}};

TEST(StepSymmetry, EverySurfaceWithALayoutIsTested) {
  std::string names;
  for (const auto& [name, h] : kLayouts) names += (names.empty() ? "" : ", ") + std::string(name);
  EXPECT_EQ(names, patch_layout_surfaces());
}

TEST(StepSymmetry, EachSideIsAMirrorPlaneOfItsSurfaceThatItsReflectionFixes) {
  for (const auto& [name, h] : kLayouts) {
    const PatchLayout& layout = *find_patch_layout(name);
    for (const MirrorPlane& plane : layout.sides) {
      const Isometry r = reflection(plane);
      EXPECT_TRUE(r.reverses()) << name;
      for (const Point& p : {Point{0.31, 0.17, 0.08}, Point{-0.2, 0.45, 0.71}}) {
        EXPECT_NEAR(catalog_value(name, r.apply(p)), catalog_value(name, p), 1e-12) << name;
        const Point q = r.apply(r.apply(p));
        for (size_t a = 0; a < 3; ++a) EXPECT_NEAR(q[a], p[a], 1e-15) << name << ": a reflection is its own inverse";
      }
    }
  }
}

TEST(StepSymmetry, TheImagesInOneCellAreTheSurfacesPiecesDistinctAndKeepTheSurface) {
  // Schwarz P, Neovius, I-WP: the 48 symmetries of the cube, half of them reversing. Diamond: 96
  // tetrahedra per cell (the Fd-3m mirror group), its region reaching beyond the cell. F-RD: 192 (Fm-3m).
  for (const auto& [name, per_cell] : {std::pair{"schwarzp", 48}, std::pair{"diamond", 96}, std::pair{"neovius", 48},
                                       std::pair{"iwp", 48}, std::pair{"frd", 192}}) {
    const PatchLayout& layout = *find_patch_layout(name);
    const std::vector<PatchImage> images = region_images(layout, {1, 1, 1});
    std::set<Point> centroids;
    int in_cell = 0, reversing = 0;
    const Point p{0.11, 0.07, -0.03};
    for (const PatchImage& image : images) {
      const Point c = image.map.apply(layout.centroid());
      centroids.insert(c);
      if (c[0] >= 0 && c[0] < 1 && c[1] >= 0 && c[1] < 1 && c[2] >= 0 && c[2] < 1) ++in_cell;  // a periodic count
      reversing += image.map.reverses() ? 1 : 0;
      EXPECT_NEAR(catalog_value(name, image.map.apply(p)), catalog_value(name, p), 1e-12) << name;
    }
    EXPECT_EQ(centroids.size(), images.size()) << name;
    EXPECT_EQ(in_cell, per_cell) << name;
    if (layout.region_is_block) {
      EXPECT_EQ(int(images.size()), per_cell) << name;
      EXPECT_EQ(2 * reversing, int(images.size())) << name;
    } else {
      // Only tetrahedra that reach into the block: each one's bounding box meets it.
      for (const PatchImage& image : images) {
        bool meets = true;
        for (size_t a = 0; a < 3; ++a) {
          double lo = 1e9, hi = -1e9;
          for (const Point& v : {layout.start[0], layout.start[1], layout.end[0], layout.end[1]}) {
            lo = std::min(lo, image.map.apply(v)[a]);
            hi = std::max(hi, image.map.apply(v)[a]);
          }
          meets = meets && hi > 0 && lo < 1;
        }
        EXPECT_TRUE(meets) << name;
      }
      EXPECT_LT(int(images.size()), 3 * per_cell) << name;
    }
  }
}

TEST(StepPatch, PatchBoundariesLieOnTheirMirrorPlanes) {
  for (const auto& [name, half] : kLayouts) {
    const PatchLayout& layout = *find_patch_layout(name);
    const auto field = compiled_walls(name, fmt::format("{}", 2 * half));
    for (double h : {half, -half}) {
      const LevelFunction g = uniform_sheet(*field, h);
      const int m = 19, n = 6;
      const std::vector<Point> points = patch_points(layout, g, m);
      // The samples are on the offset surface.
      for (const Point& p : points) {
        double value = 0;
        g(1, &p[0], &p[1], &p[2], &value);
        EXPECT_LT(std::fabs(value), 1e-12) << name;
      }
      CubicPatch patch = fit_patch(points, m, n);
      snap_boundary(layout, patch);
      auto on = [&layout](size_t side, const Point& p) {
        const MirrorPlane& plane = layout.sides[side];
        return plane.normal[0] * p[0] + plane.normal[1] * p[1] + plane.normal[2] * p[2] - plane.offset;
      };
      for (int k = 0; k < n; ++k) {
        EXPECT_EQ(on(0, patch.at(0, k)), 0.0) << name << ": u = 0";
        EXPECT_EQ(on(1, patch.at(n - 1, k)), 0.0) << name << ": u = 1";
        EXPECT_EQ(on(2, patch.at(k, 0)), 0.0) << name << ": v = 0";
        EXPECT_EQ(on(3, patch.at(k, n - 1)), 0.0) << name << ": v = 1";
      }
    }
  }
}

TEST(StepPatch, NormalJumpAcrossMirrorPlanesShrinksTowardZeroAsTheFitConverges) {
  // The exact surface meets its mirror planes at right angles, so the measured jump of a fit must
  // fall toward 0 with more control points (wrong plane normals would leave it large).
  const auto field = compiled_walls("schwarzp", "0.1");
  const LevelFunction g = uniform_sheet(*field, 0.05);
  std::vector<double> jumps;
  for (int n : {5, 8, 16}) {
    const int m = 3 * n + 1;
    const PatchLayout& layout = *find_patch_layout("schwarzp");
    CubicPatch patch = fit_patch(patch_points(layout, g, m), m, n);
    snap_boundary(layout, patch);
    jumps.push_back(normal_jump(layout, patch, 100) * 180 / M_PI);
  }
  EXPECT_GT(jumps[0], jumps[1]);
  EXPECT_GT(jumps[1], jumps[2]);
  EXPECT_LT(jumps[2], 0.2) << "degrees at 16 x 16";
  EXPECT_GT(jumps[2], 0.0);
}

}  // namespace
}  // namespace offsetgen::step
