// Issue 2's convergence test, with the project's own root finder (Brent, check/root_finding.h) and
// the paper's measurement (section 5.2.1): the offset of phi^(m) from F = 0 converges with order m
// for m = 1..4 on the gyroid, Schwarz P and Neovius; at h = 0.01 L order 4 on the gyroid is below
// 1e-6 (the paper's headline) and order 6 below 1e-9. A coarser grid than the paper's keeps it fast.
#include "check/thickness.h"
#include "check_test_support.h"

#include <gtest/gtest.h>

#include <tuple>

namespace offsetgen::check {
namespace {

class Convergence : public ::testing::TestWithParam<std::tuple<const char*, int>> {};

TEST_P(Convergence, SlopeMatchesTheOrderBothWays) {
  const auto [surface, order] = GetParam();
  auto c = testing::compile_catalog(surface, order);
  ASSERT_TRUE(c->result.ok) << c->result.steps.front().output;
  // Order 1 on the gyroid: the first-order coefficient is small (the nodal gyroid is nearly minimal,
  // mean curvature ~ 0), so its asymptotic range starts below h ~ 0.002; measure order 1 lower.
  const std::vector<double> h = order == 1 ? std::vector<double>{0.000125, 0.00025, 0.0005, 0.001}
                                           : std::vector<double>{0.00125, 0.0025, 0.005, 0.01};
  ThicknessReport r = measure_constant(make_probe(c->functions()), testing::thickness_options(h));
  EXPECT_GT(r.samples_on_f, 100);
  for (const auto& row : r.rows) {
    EXPECT_EQ(row.f_to_phi.missed, 0) << "h = " << row.h;
    EXPECT_EQ(row.phi_to_f.missed, 0) << "h = " << row.h;
    EXPECT_EQ(row.shell.missed, 0) << "h = " << row.h;
    EXPECT_EQ(row.f_to_phi.crossed, r.samples_on_f);
  }
  const double forward = loglog_slope(h, testing::column(r, &SweepRow::f_to_phi));
  const double backward = loglog_slope(h, testing::column(r, &SweepRow::phi_to_f));
  EXPECT_NEAR(forward, order, 0.3) << surface << " o" << order << " F -> phi";
  EXPECT_NEAR(backward, order, 0.3) << surface << " o" << order << " phi -> F";
}

INSTANTIATE_TEST_SUITE_P(CatalogOrders1To4, Convergence,
                         ::testing::Combine(::testing::Values("gyroid", "schwarzp", "neovius"),
                                            ::testing::Values(1, 2, 3, 4)),
                         [](const auto& param_info) {
                           return std::string(std::get<0>(param_info.param)) + "_o" +
                                  std::to_string(std::get<1>(param_info.param));
                         });

double error_at_one_percent(const char* surface, int order) {
  auto c = testing::compile_catalog(surface, order);
  EXPECT_TRUE(c->result.ok);
  if (!c->result.ok) return 1;
  ThicknessReport r = measure_constant(make_probe(c->functions()), testing::thickness_options({0.01}));
  EXPECT_EQ(r.rows.at(0).f_to_phi.missed, 0);
  EXPECT_EQ(r.rows.at(0).phi_to_f.missed, 0);
  return std::max(r.rows.at(0).f_to_phi.mean, r.rows.at(0).phi_to_f.mean);
}

TEST(Convergence, PaperHeadlineOrder4GyroidBelow1e6AtOnePercent) {
  const double e = error_at_one_percent("gyroid", 4);
  EXPECT_LT(e, 1e-6);
}

TEST(Convergence, Order6Below1e9AtOnePercentOnGyroidAndSchwarzP) {
  for (const char* surface : {"gyroid", "schwarzp"}) {
    const double e = error_at_one_percent(surface, 6);
    EXPECT_LT(e, 1e-9) << surface;
  }
}

TEST(Convergence, SamplesLieOnTheSurface) {
  auto c = testing::compile_catalog("neovius", 1);
  ASSERT_TRUE(c->result.ok);
  Probe probe = make_probe(c->functions());
  const auto points = sample_zero_set(probe.field, 3, 11, 100);
  ASSERT_GT(points.size(), 100u);
  for (const auto& p : points) EXPECT_LT(std::fabs(probe.field(p.data())), 1e-13);
}

}  // namespace
}  // namespace offsetgen::check
