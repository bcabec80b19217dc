// The project's own root finder (Brent) and the slope fit used by the convergence measurements.
#include "check/convergence.h"
#include "numeric/root_finding.h"

#include <gtest/gtest.h>

#include <cmath>

namespace offsetgen::check {
namespace {

TEST(RootFinding, BrentConvergesToMachinePrecision) {
  int calls = 0;
  auto f = [&calls](double x) {
    ++calls;
    return std::cos(x) - x;
  };
  const double r = numeric::brent_root(f, 0.0, 1.0, f(0.0), f(1.0));
  EXPECT_NEAR(r, 0.73908513321516064, 2e-16);
  EXPECT_LT(calls, 20);
}

TEST(RootFinding, BrentSurvivesNastyFunctions) {
  auto cubic = [](double x) { return std::pow(x - 1.0 / 3.0, 3); };  // flat, triple root
  EXPECT_NEAR(numeric::brent_root(cubic, 0.0, 1.0, cubic(0.0), cubic(1.0)), 1.0 / 3.0, 1e-5);
  auto step = [](double x) { return x < 0.25 ? -1.0 : 1.0; };  // discontinuous: converges to the jump
  EXPECT_NEAR(numeric::brent_root(step, 0.0, 1.0, -1.0, 1.0), 0.25, 1e-15);
}

TEST(RootFinding, AllRootsInAnInterval) {
  auto f = [](double x) { return std::sin(2 * M_PI * 3 * x); };  // roots at k/6
  auto roots = numeric::roots_in_interval(f, 0.01, 0.99, 200);
  ASSERT_EQ(roots.size(), 5u);
  for (size_t k = 0; k < roots.size(); ++k) EXPECT_NEAR(roots[k], static_cast<double>(k + 1) / 6.0, 1e-14);
  auto g = [](double x) { return x - 0.5; };  // exact zero on a scan node counts once
  auto r = numeric::roots_in_interval(g, 0.0, 1.0, 4);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0], 0.5);
}

TEST(RootFinding, RootNearPicksTheClosestCrossingAndReportsMisses) {
  auto f = [](double s) { return (s - 0.1) * (s - 0.3); };
  auto r = numeric::root_near(f, 0.12, 0.12);
  ASSERT_TRUE(r);
  EXPECT_NEAR(*r, 0.1, 1e-15);
  auto none = [](double s) { return 1.0 + s * s; };
  EXPECT_FALSE(numeric::root_near(none, 0.1, 0.1));
}

TEST(Convergence, FitsTheSlopeOverTheSmallHalfAboveTheFloor) {
  std::vector<double> h, e;
  for (int k = 0; k <= 8; ++k) {
    h.push_back(0.001 * std::pow(10.0, k / 4.0));
    e.push_back(std::max(3.0 * std::pow(h.back(), 4), 1e-14));  // order 4, with a roundoff floor
  }
  OrderFit fit = fit_order(h, e);
  ASSERT_TRUE(fit.fitted);
  EXPECT_NEAR(fit.slope, 4.0, 1e-9);
  EXPECT_GE(fit.points, 3);
  EXPECT_GT(fit.h_min, 0.001);  // floor points were left out
  std::vector<double> flat(h.size(), 1e-14);
  EXPECT_FALSE(fit_order(h, flat).fitted);
}

}  // namespace
}  // namespace offsetgen::check
