// The inline math helpers of every generated header against libm: the batch loops'
// (offsetgen_batch_sin/cos/sqrt[f]) and the scalar functions' (offsetgen_sin/cos[f]). Compiled with
// the fast flags, like the batch cases.
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

// Ulps between two finite doubles (or floats) of the same sign, counted on their bit patterns.
template <class T>
double ulp_distance(T a, T b) {
  return std::fabs(static_cast<double>(a - b)) /
         static_cast<double>(std::nextafter(std::fabs(b), std::numeric_limits<T>::infinity()) - std::fabs(b));
}

// Over the whole normal range, from the smallest normal double to the largest: the bit-level
// seed and Newton steps stay within 1 ulp of sqrt, and are sqrt's value in most cases (all but
// about 1e-6 with FMA, which the fast flags have on this machine's -march=native).
TEST(BatchSqrt, DoubleWithinOneUlpOfSqrtOverTheNormalRange) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-1022, 1023);
  double worst = 0;
  long exact = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    const double a = std::ldexp(mantissa(rng), exponent(rng));
    if (!std::isfinite(a)) continue;
    const double got = offsetgen_batch_sqrt(a), expected = std::sqrt(a);
    worst = std::max(worst, ulp_distance(got, expected));
    exact += got == expected;
  }
  EXPECT_LE(worst, 1.0);
  EXPECT_GE(static_cast<double>(exact) / n, 0.8);
  for (double a : {std::numeric_limits<double>::min(), std::numeric_limits<double>::max(), 1.0, 4.0, 2.0, 0.5}) {
    EXPECT_LE(ulp_distance(offsetgen_batch_sqrt(a), std::sqrt(a)), 1.0) << a;
  }
}

TEST(BatchSqrt, FloatWithinOneUlpOfSqrtfOverTheNormalRange) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> mantissa(1.0f, 2.0f);
  std::uniform_int_distribution<int> exponent(-126, 127);
  double worst = 0;
  for (int i = 0; i < 400000; ++i) {
    const float a = std::ldexp(mantissa(rng), exponent(rng));
    if (!std::isfinite(a)) continue;
    worst = std::max(worst, ulp_distance(offsetgen_batch_sqrtf(a), std::sqrt(a)));
  }
  EXPECT_LE(worst, 1.0);
  for (float a : {std::numeric_limits<float>::min(), std::numeric_limits<float>::max(), 1.0f, 2.0f}) {
    EXPECT_LE(ulp_distance(offsetgen_batch_sqrtf(a), std::sqrt(a)), 1.0) << a;
  }
}

// Subnormal inputs have no exponent for the seed: the documented absolute bound instead of ulps.
TEST(BatchSqrt, SubnormalInputsWithinTheDocumentedAbsoluteError) {
  double worst = 0, worst_float = 0;
  for (double a = std::numeric_limits<double>::denorm_min(); a < std::numeric_limits<double>::min();
       a = a * 1.0137 + std::numeric_limits<double>::denorm_min())
    worst = std::max(worst, std::fabs(offsetgen_batch_sqrt(a) - std::sqrt(a)));
  for (float a = std::numeric_limits<float>::denorm_min(); a < std::numeric_limits<float>::min();
       a = a * 1.0137f + std::numeric_limits<float>::denorm_min())
    worst_float = std::max(
        worst_float, std::fabs(static_cast<double>(offsetgen_batch_sqrtf(a)) - std::sqrt(static_cast<double>(a))));
  EXPECT_LT(worst, 6e-156);
  EXPECT_LT(worst_float, 2e-20);
}

// What sqrt returns for the special cases: +-0 with its sign, +inf, NaN for negative numbers,
// -inf and NaN.
TEST(BatchSqrt, SpecialValuesAsSqrt) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(offsetgen_batch_sqrt(0.0), 0.0);
  EXPECT_FALSE(std::signbit(offsetgen_batch_sqrt(0.0)));
  EXPECT_TRUE(std::signbit(offsetgen_batch_sqrt(-0.0)));
  EXPECT_EQ(offsetgen_batch_sqrt(inf), inf);
  for (double a : {-1.0, -1e-310, -1e300, -inf, nan}) EXPECT_TRUE(std::isnan(offsetgen_batch_sqrt(a))) << a;
  const float inff = std::numeric_limits<float>::infinity(), nanf = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(offsetgen_batch_sqrtf(0.0f), 0.0f);
  EXPECT_TRUE(std::signbit(offsetgen_batch_sqrtf(-0.0f)));
  EXPECT_EQ(offsetgen_batch_sqrtf(inff), inff);
  for (float a : {-1.0f, -1e-40f, -inff, nanf}) EXPECT_TRUE(std::isnan(offsetgen_batch_sqrtf(a))) << a;
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
      worst_vs_batch =
          std::max(worst_vs_batch, std::fabs(offsetgen_sin(a) - offsetgen_batch_sin(a)) / std::fabs(std::sin(a)));
      worst_vs_batch =
          std::max(worst_vs_batch, std::fabs(offsetgen_cos(a) - offsetgen_batch_cos(a)) / std::fabs(std::cos(a)));
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
