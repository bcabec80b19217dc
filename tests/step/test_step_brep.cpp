// The B-rep assembly of `offsetgen step` in memory, below the file: the solid's orientation comes from
// the outward direction it is given, not from classifying a point against its faces.
#include "step/symmetry_patch.h"
#include "step/wall_brep.h"
#include "step_test_walls.h"

#include <gtest/gtest.h>

namespace offsetgen::step {
namespace {

TEST(StepBrep, TheSolidPointsOutAlongTheGivenOutwardDirection) {
  const auto field = compiled_walls("schwarzp", "0.1");
  const PatchLayout& layout = *find_patch_layout("schwarzp");
  auto sheet = [&field](double h) { return uniform_sheet(*field, h); };
  const int n = 5, m = 3 * n + 1;
  std::vector<CubicPatch> plus{fit_patch(patch_points(layout, sheet(0.05), m), m, n)};
  std::vector<CubicPatch> minus{fit_patch(patch_points(layout, sheet(-0.05), m), m, n)};
  snap_boundary(layout, plus[0]);
  snap_boundary(layout, minus[0]);
  // Out of the wall at the plus patch's middle: along grad phi(p, +t/2).
  const Point p = plus[0].evaluate(0.5, 0.5);
  Point out{};
  for (size_t a = 0; a < 3; ++a) {
    Point lo = p, hi = p;
    lo[a] -= 1e-6;
    hi[a] += 1e-6;
    double f[2];
    const double x[2] = {lo[0], hi[0]}, y[2] = {lo[1], hi[1]}, z[2] = {lo[2], hi[2]};
    sheet(0.05)(2, x, y, z, f);
    out[a] = f[1] - f[0];
  }
  const ShapeCheck right = check_shape(build_wall(layout, plus, minus, out, {1, 1, 1}, 10).solid);
  EXPECT_TRUE(right.valid);
  EXPECT_GT(right.volume, 200.0);
  const ShapeCheck wrong =
      check_shape(build_wall(layout, plus, minus, {-out[0], -out[1], -out[2]}, {1, 1, 1}, 10).solid);
  EXPECT_LT(wrong.volume, -200.0) << "told the opposite, it builds the complement's orientation";
}

}  // namespace
}  // namespace offsetgen::step
