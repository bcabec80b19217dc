// The inline sin/cos helpers of every generated header against libm: the batch loops'
// (offsetgen_batch_sin/cos[f]) and the scalar functions' (offsetgen_sin/cos[f]). Compiled with the
// fast flags, like the batch cases.
#include "gyroid_o4.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kEpsF = std::numeric_limits<float>::epsilon();

TEST(BatchTrig, DoubleWithinTwoUlpOfLibm) {
  std::mt19937_64 rng(1);
  for (double range : {1.0, 10.0, 1000.0, 1.0e6}) {
    std::uniform_real_distribution<double> arg(-range, range);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
      const double a = arg(rng);
      worst = std::max(worst, std::fabs(offsetgen_batch_sin(a) - std::sin(a)) / std::fabs(std::sin(a)));
      worst = std::max(worst, std::fabs(offsetgen_batch_cos(a) - std::cos(a)) / std::fabs(std::cos(a)));
    }
    EXPECT_LE(worst / kEps, 2.0) << "range " << range;
  }
}

// At the double nearest k*pi/2 the result is tiny (the reduction's residue); it must still be
// right to within the reduction's absolute error, about |k| * 1e-31.
TEST(BatchTrig, DoubleNearMultiplesOfHalfPi) {
  for (int k = -2000; k <= 2000; ++k) {
    const double a = k * (M_PI / 2);
    EXPECT_NEAR(offsetgen_batch_sin(a), std::sin(a), 2 * kEps * std::fabs(std::sin(a)) + 1e-30 * std::abs(k) + 1e-300)
        << k;
    EXPECT_NEAR(offsetgen_batch_cos(a), std::cos(a), 2 * kEps * std::fabs(std::cos(a)) + 1e-30 * std::abs(k) + 1e-300)
        << k;
  }
  EXPECT_EQ(offsetgen_batch_sin(0.0), 0.0);
  EXPECT_EQ(offsetgen_batch_cos(0.0), 1.0);
}

// Within 2 float ulps of the true value, plus the reduction's absolute error (about 5e-15 |a|, far
// below the float argument's own resolution), which matters only next to a zero of sin or cos.
TEST(BatchTrig, FloatWithinTwoUlpOfTheTrueValue) {
  std::mt19937 rng(2);
  for (float range : {1.0f, 10.0f, 1000.0f, 8000.0f}) {
    std::uniform_real_distribution<float> arg(-range, range);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
      const float a = arg(rng);
      const double s = std::sin(static_cast<double>(a)), c = std::cos(static_cast<double>(a));
      const double slack = 5e-15 * std::fabs(static_cast<double>(a));
      worst = std::max(worst, std::max(std::fabs(offsetgen_batch_sinf(a) - s) - slack, 0.0) / std::fabs(s));
      worst = std::max(worst, std::max(std::fabs(offsetgen_batch_cosf(a) - c) - slack, 0.0) / std::fabs(c));
    }
    EXPECT_LE(worst / kEpsF, 2.0) << "range " << range;
  }
}

TEST(BatchTrig, BeyondRangeOrNonFiniteIsNaN) {
  EXPECT_TRUE(std::isnan(offsetgen_batch_sin(1.5e8)));
  EXPECT_TRUE(std::isnan(offsetgen_batch_cos(-1.5e8)));
  EXPECT_FALSE(std::isnan(offsetgen_batch_sin(0.99e8)));
  EXPECT_TRUE(std::isnan(offsetgen_batch_sin(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(offsetgen_batch_cos(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(offsetgen_batch_sinf(8193.0f)));
  EXPECT_FALSE(std::isnan(offsetgen_batch_cosf(8191.0f)));
  EXPECT_TRUE(std::isnan(offsetgen_batch_cosf(std::numeric_limits<float>::infinity())));
}

// The scalar helpers: libm accuracy in range, libm itself beyond it and for non-finite input, and
// the batch helpers' values (same reduction and polynomials), so scalar and batch functions agree.
TEST(ScalarTrig, DoubleWithinTwoUlpOfLibmAndEqualToTheBatchHelpers) {
  std::mt19937_64 rng(3);
  for (double range : {1.0, 10.0, 1000.0, 1.0e6, 0.99e8}) {
    std::uniform_real_distribution<double> arg(-range, range);
    double worst = 0, worst_vs_batch = 0;
    for (int i = 0; i < 200000; ++i) {
      const double a = arg(rng);
      worst = std::max(worst, std::fabs(offsetgen_sin(a) - std::sin(a)) / std::fabs(std::sin(a)));
      worst = std::max(worst, std::fabs(offsetgen_cos(a) - std::cos(a)) / std::fabs(std::cos(a)));
      worst_vs_batch = std::max(worst_vs_batch, std::fabs(offsetgen_sin(a) - offsetgen_batch_sin(a)) / std::fabs(std::sin(a)));
      worst_vs_batch = std::max(worst_vs_batch, std::fabs(offsetgen_cos(a) - offsetgen_batch_cos(a)) / std::fabs(std::cos(a)));
    }
    EXPECT_LE(worst / kEps, 2.0) << "range " << range;
    EXPECT_LE(worst_vs_batch / kEps, 1.0) << "range " << range;
  }
  for (int k = -2000; k <= 2000; ++k) {
    const double a = k * (M_PI / 2);
    EXPECT_NEAR(offsetgen_sin(a), std::sin(a), 2 * kEps * std::fabs(std::sin(a)) + 1e-30 * std::abs(k) + 1e-300) << k;
    EXPECT_NEAR(offsetgen_cos(a), std::cos(a), 2 * kEps * std::fabs(std::cos(a)) + 1e-30 * std::abs(k) + 1e-300) << k;
  }
}

TEST(ScalarTrig, BeyondRangeOrNonFiniteIsLibm) {
  for (double a : {1.5e8, -3.0e9, 1.0e300, -1.0e18}) {
    EXPECT_EQ(offsetgen_sin(a), std::sin(a)) << a;
    EXPECT_EQ(offsetgen_cos(a), std::cos(a)) << a;
  }
  EXPECT_TRUE(std::isnan(offsetgen_sin(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(offsetgen_cos(std::numeric_limits<double>::quiet_NaN())));
  for (float a : {8193.0f, -1.0e7f, 3.0e38f}) {
    EXPECT_EQ(offsetgen_sinf(a), std::sin(a)) << a;
    EXPECT_EQ(offsetgen_cosf(a), std::cos(a)) << a;
  }
  EXPECT_TRUE(std::isnan(offsetgen_sinf(-std::numeric_limits<float>::infinity())));
}

TEST(ScalarTrig, FloatWithinTwoUlpOfTheTrueValue) {
  std::mt19937 rng(4);
  for (float range : {1.0f, 10.0f, 1000.0f, 8000.0f}) {
    std::uniform_real_distribution<float> arg(-range, range);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
      const float a = arg(rng);
      const double s = std::sin(static_cast<double>(a)), c = std::cos(static_cast<double>(a));
      const double slack = 5e-15 * std::fabs(static_cast<double>(a));
      worst = std::max(worst, std::max(std::fabs(offsetgen_sinf(a) - s) - slack, 0.0) / std::fabs(s));
      worst = std::max(worst, std::max(std::fabs(offsetgen_cosf(a) - c) - slack, 0.0) / std::fabs(c));
    }
    EXPECT_LE(worst / kEpsF, 2.0) << "range " << range;
  }
}

}  // namespace
