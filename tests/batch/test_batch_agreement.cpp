// The `_n` batch functions against their scalar twins, at random points, on the lattice of critical
// points, beyond the fast sin/cos range, for non-finite input and for every loop-tail length.
#include "batch_cases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace offsetgen::batch_test {
namespace {

// Agreement target, relative to max(|scalar|, 1) (the field's own scale is 1): 1e-14 in double.
// In float the bound is 1e-5 (float's own rounding is ~1e-6 of the scale at these orders).
template <class T>
constexpr double kAgree = sizeof(T) == 8 ? 1e-14 : 1e-5;
// Scalar and batch functions share their sin/cos polynomials, and their sqrt agree but in about 1e-6
// of the cases (1 ulp; 13% without FMA); what differs otherwise is how the compiler contracts the
// same program into FMAs in vector and scalar code (the scalar sqrt's errno branch splits the scalar
// code into blocks that are contracted apart). Up to order 4 at least this fraction of random points
// meets kAgree outright. Beyond, the scalar function's own rounding error is itself above 1e-14 at
// its 99th percentile, and the contraction alone moves 6-12% of the order-6 points past 1e-14 (100%
// within it with -ffp-contract=off or -fno-math-errno); there, and at every order, the batch
// function must be as accurate as the scalar one, quantile by quantile, against the same program in
// more precision.
constexpr double kAgreeFraction = 0.999;
constexpr int kAgreeMaxOrder = 4;

template <class T>
struct Points {
  std::vector<T> x, y, z, w;
  std::size_t size() const { return x.size(); }
};

template <class T>
Points<T> random_points(const BatchFunction<T>& f, std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coordinate(-2.0, 3.0);
  // offset: h in [-0.1, 0.1]; shell: total thickness t in [0, 0.2] (cell units).
  std::uniform_real_distribution<double> w(f.function == "shell" ? 0.0 : -0.1, f.function == "shell" ? 0.2 : 0.1);
  Points<T> p;
  for (std::size_t i = 0; i < n; ++i) {
    p.x.push_back(static_cast<T>(coordinate(rng)));
    p.y.push_back(static_cast<T>(coordinate(rng)));
    p.z.push_back(f.dims == 3 ? static_cast<T>(coordinate(rng)) : T(0));
    p.w.push_back(static_cast<T>(w(rng)));
  }
  return p;
}

template <class T>
std::vector<T> run_batch(const BatchFunction<T>& f, const Points<T>& p) {
  std::vector<T> out(p.size(), T(-12345));
  f.batch(p.size(), p.x.data(), p.y.data(), p.z.data(), p.w.data(), out.data());
  return out;
}

double scaled(double difference, double reference) {
  return std::fabs(difference) / std::max(std::fabs(reference), 1.0);
}

double quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
}

template <class T>
void check_random_agreement() {
  const double eps = std::numeric_limits<T>::epsilon();
  for (const auto& f : cases_of<T>()) {
    SCOPED_TRACE(f.label());
    const Points<T> p = random_points(f, 20011, 7);
    const std::vector<T> out = run_batch(f, p);
    std::vector<double> difference, scalar_error, batch_error;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const T s = f.scalar(p.x[i], p.y[i], p.z[i], p.w[i]);
      ASSERT_TRUE(std::isfinite(out[i])) << "at " << p.x[i] << ", " << p.y[i] << ", " << p.z[i] << ", " << p.w[i];
      const long double reference = f.reference(p.x[i], p.y[i], p.z[i], p.w[i]);
      const double scale = std::max(std::fabs(static_cast<double>(reference)), 1.0);
      difference.push_back(scaled(static_cast<double>(out[i]) - static_cast<double>(s), s));
      scalar_error.push_back(static_cast<double>(std::fabs(static_cast<long double>(s) - reference)) / scale);
      batch_error.push_back(static_cast<double>(std::fabs(static_cast<long double>(out[i]) - reference)) / scale);
    }
    const double within = static_cast<double>(std::count_if(difference.begin(), difference.end(),
                                                            [](double d) { return d <= kAgree<T>; })) /
                          static_cast<double>(difference.size());
    if (f.order <= kAgreeMaxOrder) {
      EXPECT_GE(within, kAgreeFraction) << "largest difference " << quantile(difference, 1.0);
    }
    // As accurate as the scalar function: median, 99th percentile and worst error against the
    // more precise evaluation of the same program.
    for (double q : {0.5, 0.99}) {
      EXPECT_LE(quantile(batch_error, q), 1.5 * quantile(scalar_error, q) + eps) << "quantile " << q;
    }
    EXPECT_LE(quantile(batch_error, 1.0), 2.0 * quantile(scalar_error, 1.0) + 10 * eps);
  }
}

TEST(BatchAgreement, DoubleMatchesScalarAtRandomPoints) { check_random_agreement<double>(); }
TEST(BatchAgreement, FloatMatchesScalarAtRandomPoints) { check_random_agreement<float>(); }

// On the lattice of multiples of 1/8, where the catalog surfaces' gradients vanish (up to rounding),
// the results must be finite and, wherever the point is provably farther from the surface than the
// offset (|F| > |h| max|grad F|), on the side of F: the safeguard survives vectorisation.
template <class T>
void check_lattice() {
  for (const auto& f : cases_of<T>()) {
    if (!f.periodic) continue;
    SCOPED_TRACE(f.label());
    const HeaderFacts facts = header_facts(f.header);
    const double max_gradient = facts.gradient_bound * facts.scale;  // cell units
    for (double thickness : {0.01, 0.05, 0.1}) {
      Points<T> p;
      const int zmax = f.dims == 3 ? 8 : 0;
      for (int i = -8; i <= 8; ++i)
        for (int j = -8; j <= 8; ++j)
          for (int k = -zmax; k <= zmax; ++k)
            for (double sign : {-1.0, 1.0}) {
              if (f.function == "shell" && sign < 0) continue;
              p.x.push_back(static_cast<T>(i / 8.0));
              p.y.push_back(static_cast<T>(j / 8.0));
              p.z.push_back(static_cast<T>(k / 8.0));
              p.w.push_back(static_cast<T>(f.function == "shell" ? thickness : sign * thickness / 2));
            }
      const std::vector<T> out = run_batch(f, p);
      std::size_t checked = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_TRUE(std::isfinite(out[i]));
        const double field = f.field(p.x[i], p.y[i], p.z[i]);
        const double half = f.function == "shell" ? thickness / 2 : std::fabs(static_cast<double>(p.w[i]));
        if (std::fabs(field) <= 1.01 * half * max_gradient + 1e-6) continue;
        ++checked;
        const double expected = f.function == "shell" ? 1.0 : field;
        EXPECT_GT(static_cast<double>(out[i]) * expected, 0.0)
            << "wrong side at " << p.x[i] << ", " << p.y[i] << ", " << p.z[i] << " w " << p.w[i] << ": F " << field
            << " batch " << out[i] << " scalar " << f.scalar(p.x[i], p.y[i], p.z[i], p.w[i]);
      }
      EXPECT_GT(checked, 0u);
    }
  }
}

TEST(BatchLattice, DoubleFiniteAndOnTheRightSide) { check_lattice<double>(); }
TEST(BatchLattice, FloatFiniteAndOnTheRightSide) { check_lattice<float>(); }

// Beyond the fast sin/cos range (|arg| > 1e8 in double, 8192 in float) the batch function hands the
// point to the scalar function: identical results, interleaved with ordinary points.
template <class T>
void check_fallback(T far) {
  for (const auto& f : cases_of<T>()) {
    SCOPED_TRACE(f.label());
    Points<T> p = random_points(f, 37, 11);
    for (std::size_t i = 0; i < p.size(); i += 3) p.x[i] = far + static_cast<T>(i) / T(7);
    const std::vector<T> out = run_batch(f, p);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const T s = f.scalar(p.x[i], p.y[i], p.z[i], p.w[i]);
      if (i % 3 == 0) {
        EXPECT_EQ(out[i], s) << "far point " << p.x[i];
        EXPECT_TRUE(std::isfinite(out[i]));
      } else {
        EXPECT_LE(scaled(static_cast<double>(out[i]) - static_cast<double>(s), s), 100 * kAgree<T>);
      }
    }
  }
}

TEST(BatchFallback, DoubleBeyondTrigRangeUsesScalar) { check_fallback<double>(2.0e7); }
TEST(BatchFallback, FloatBeyondTrigRangeUsesScalar) { check_fallback<float>(1500.0f); }

template <class T>
void check_non_finite() {
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (const auto& f : cases_of<T>()) {
    SCOPED_TRACE(f.label());
    Points<T> p = random_points(f, 9, 3);
    p.x[1] = nan;
    p.y[4] = inf;
    p.x[7] = -inf;
    const std::vector<T> out = run_batch(f, p);
    for (std::size_t i : {std::size_t{1}, std::size_t{4}, std::size_t{7}}) {
      const T s = f.scalar(p.x[i], p.y[i], p.z[i], p.w[i]);
      EXPECT_EQ(std::isnan(out[i]), std::isnan(s)) << "point " << i;
      if (!std::isnan(s)) {
        EXPECT_EQ(out[i], s);
      }
    }
  }
}

TEST(BatchNonFinite, DoubleLikeScalar) { check_non_finite<double>(); }
TEST(BatchNonFinite, FloatLikeScalar) { check_non_finite<float>(); }

// Every length from 0 to 40 (vector bodies and all remainder tails); n = 0 writes nothing.
template <class T>
void check_lengths() {
  for (const auto& f : cases_of<T>()) {
    SCOPED_TRACE(f.label());
    const Points<T> p = random_points(f, 40, 5);
    for (std::size_t n = 0; n <= p.size(); ++n) {
      std::vector<T> out(p.size() + 1, T(-777));
      f.batch(n, p.x.data(), p.y.data(), p.z.data(), p.w.data(), out.data());
      for (std::size_t i = 0; i < n; ++i) {
        const T s = f.scalar(p.x[i], p.y[i], p.z[i], p.w[i]);
        // The same function (its accuracy is checked above), whichever part of the loop ran it.
        EXPECT_LE(scaled(static_cast<double>(out[i]) - static_cast<double>(s), s), 1000 * kAgree<T>)
            << "n " << n << " i " << i << ": " << out[i] << " vs " << s;
      }
      for (std::size_t i = n; i < out.size(); ++i) EXPECT_EQ(out[i], T(-777)) << "wrote past n = " << n;
    }
  }
}

TEST(BatchLengths, DoubleEveryTail) { check_lengths<double>(); }
TEST(BatchLengths, FloatEveryTail) { check_lengths<float>(); }

TEST(BatchCases, AllHeadersPresent) {
  EXPECT_EQ(cases_of<double>().size(), 16u);
  EXPECT_EQ(cases_of<float>().size(), 10u);
}

}  // namespace
}  // namespace offsetgen::batch_test
