// Requirement 7 of the core issue: no NaN and no phantom walls, on grids that contain the lattice
// points (multiples of 1/8) where gradients vanish, for every catalog surface and orders 1-8.
// The programs checked here are the ones the emitters print; tests/core/test_golden_values.cpp and
// the check stage tie the printed C to them.
#include "test_support.h"

#include "surfaces/expression_input.h"

#include <gtest/gtest.h>

#include <cmath>

namespace offsetgen {
namespace {

// max |grad F| estimated independently of the generator's bound: central differences on a grid.
double estimated_max_gradient(const Program& field, int n) {
  Evaluator f(field);
  const double d = 1e-6;
  double best = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        double x = double(i) / n, y = double(j) / n, z = double(k) / n;
        double gx = (f({x + d, y, z})[0] - f({x - d, y, z})[0]) / (2 * d);
        double gy = (f({x, y + d, z})[0] - f({x, y - d, z})[0]) / (2 * d);
        double gz = (f({x, y, z + d})[0] - f({x, y, z - d})[0]) / (2 * d);
        best = std::max(best, std::sqrt(gx * gx + gy * gy + gz * gz));
      }
  return best;
}

struct Case {
  std::string surface;
  int order;
};

class Safeguard : public ::testing::TestWithParam<Case> {};

TEST_P(Safeguard, FiniteEverywhereAndNeverTheWrongSideFarFromTheSurface) {
  const auto& [name, order] = GetParam();
  auto b = testing::build(name, order);
  const double max_gradient = estimated_max_gradient(b->programs.field, 40);
  EXPECT_LE(max_gradient, b->programs.gradient_bound * 6.2831853071795862 * (1 + 1e-6));

  Evaluator field(b->programs.field), offset(b->programs.offset), shell(b->programs.shell), normal(b->programs.normal);
  const int n = order <= 4 ? 24 : 16;  // both contain every multiple of 1/8
  long checked_far = 0;
  for (double t : {0.01, 0.05, 0.1}) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= n; ++k) {
          const double x = double(i) / n, y = double(j) / n, z = double(k) / n;
          const double F = field({x, y, z})[0];
          const double Phi = shell({x, y, z, t})[0];
          ASSERT_TRUE(std::isfinite(Phi)) << name << " o" << order << " shell at " << x << "," << y << "," << z;
          const bool far = std::fabs(F) > t / 2 * max_gradient;
          if (far) {
            ++checked_far;
            ASSERT_GT(Phi, 0) << name << " o" << order << " phantom wall at " << x << "," << y << "," << z << " t " << t;
          }
          const bool lattice = i % (n / 8) == 0 && j % (n / 8) == 0 && k % (n / 8) == 0;
          if (!lattice && order > 4) continue;  // offsets and normals: every point up to order 4
          for (double h : {t / 2, -t / 2}) {
            const double phi = offset({x, y, z, h})[0];
            ASSERT_TRUE(std::isfinite(phi)) << name << " o" << order << " offset at " << x << "," << y << "," << z;
            if (std::fabs(F) > std::fabs(h) * max_gradient) {
              ASSERT_EQ(phi > 0, F > 0) << name << " o" << order << " wrong side at " << x << "," << y << "," << z;
            }
            for (double c : normal({x, y, z, h})) ASSERT_TRUE(std::isfinite(c));
          }
        }
  }
  EXPECT_GT(checked_far, 0);
}

// A user expression whose gradient has a pole in the cell (x^y and log(x) at x = 0): the bound
// search skips non-finite samples and stops instead of creeping towards the pole (it used to run
// for more than ten minutes), and the bound is a finite upper bound of the sampled gradient.
TEST(SafeguardBound, FiniteForGradientsWithPolesInTheCell) {
  for (const char* text : {"x^y", "log(x) + y", "1/(x + 0.001) + y"}) {
    const Surface surface = parse_user_expression(text, {}, "pole");
    const OffsetModel model = build_offset_model(surface, 1, true);
    const double bound = max_gradient_norm(surface, model);
    EXPECT_TRUE(std::isfinite(bound)) << text;
    EXPECT_GT(bound, 1.0) << text;
  }
  // The smooth quarter circle's gradient (2x, 2y) peaks at (1, 1): |grad F| = 2 sqrt(2).
  const Surface circle = parse_user_expression("x^2 + y^2 - 0.25", {}, "circle");
  EXPECT_NEAR(max_gradient_norm(circle, build_offset_model(circle, 1, true)), 2 * std::sqrt(2.0), 1e-5);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const auto& entry : catalog())
    for (int order = 1; order <= 8; ++order) cases.push_back({entry.name, order});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllSurfacesOrders1To8, Safeguard, ::testing::ValuesIn(all_cases()),
                         [](const auto& p) { return p.param.surface + "_o" + std::to_string(p.param.order); });

}  // namespace
}  // namespace offsetgen
