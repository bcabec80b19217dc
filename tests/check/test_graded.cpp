// Graded walls (paper section 6, Figure 8): the total thickness between the +h(x) and -h(x) walls
// converges with order min(m, 2), the one-sided measure from F = 0 against h(p) with order 1.
// Second order reaches the paper's "< 0.03 % at a total thickness of 0.01 L".
#include "check/thickness.h"
#include "check_test_support.h"
#include "surfaces/expression_input.h"

#include <gtest/gtest.h>

namespace offsetgen::check {
namespace {

GradedReport graded(const char* surface, int order, const std::string& thickness, std::vector<double> h) {
  auto c = testing::compile_catalog(surface, order, thickness);
  EXPECT_TRUE(c->result.ok);
  ThicknessFunction t(parse_thickness_expression(thickness, {}, 3), 3);
  ThicknessOptions o;
  o.h = std::move(h);
  o.grid = 11;
  o.scan = 100;
  return measure_graded(make_probe(c->functions()), t, thickness, true, o);
}

std::vector<double> means(const GradedReport& r, ErrorStats GradedRow::*member, std::vector<double>* h) {
  std::vector<double> v;
  for (const auto& row : r.rows) {
    if (row.as_given) continue;
    v.push_back((row.*member).mean);
    if (h) h->push_back(row.h_max);
  }
  return v;
}

TEST(Graded, SecondOrderMeetsThePapersThreshold) {
  // t(x) = 0.01 x: total thickness up to 0.01 L, h up to 0.005 L (the paper's linear grading).
  GradedReport r = graded("gyroid", 2, "0.01*x", {0.00125, 0.0025, 0.005, 0.01});
  EXPECT_NEAR(r.t_peak, 0.01, 1e-15);
  const GradedRow& given = r.rows.back();
  ASSERT_TRUE(given.as_given);
  EXPECT_TRUE(given.compiled_graded);
  EXPECT_NEAR(given.h_max, 0.005, 1e-15);
  EXPECT_EQ(given.total.missed, 0);
  EXPECT_GT(given.total.skipped, 0);  // the points at x = 0 (t = 0) are counted, not hidden
  EXPECT_LT(given.total.mean, 3e-4);
  EXPECT_LT(given.paper.mean, 3e-4);
  std::vector<double> h;
  const auto total = means(r, &GradedRow::total, &h);
  EXPECT_NEAR(loglog_slope(h, total), 2.0, 0.3);
  EXPECT_NEAR(loglog_slope(h, means(r, &GradedRow::paper, nullptr)), 2.0, 0.3);
  EXPECT_NEAR(loglog_slope(h, means(r, &GradedRow::one_sided, nullptr)), 1.0, 0.3);
}

TEST(Graded, HigherOrdersStayAtSecondOrderAndOneSidedAtFirst) {
  GradedReport r = graded("schwarzp", 4, "0.02*x", {0.00125, 0.0025, 0.005, 0.01});
  std::vector<double> h;
  const auto total = means(r, &GradedRow::total, &h);
  EXPECT_NEAR(loglog_slope(h, total), 2.0, 0.3);
  EXPECT_NEAR(loglog_slope(h, means(r, &GradedRow::one_sided, nullptr)), 1.0, 0.3);
  for (const auto& row : r.rows) EXPECT_EQ(row.total.missed, 0);
}

TEST(Graded, ConstantThicknessKeepsTheFullOrder) {
  // With t constant nothing varies across the wall: the graded measurement is the constant one.
  GradedReport r = graded("gyroid", 3, "0.02", {0.0025, 0.005, 0.01});
  std::vector<double> h;
  const auto total = means(r, &GradedRow::total, &h);
  EXPECT_GT(loglog_slope(h, total), 3.7);  // the shell cancels the odd error term: order 4
  EXPECT_NEAR(loglog_slope(h, means(r, &GradedRow::one_sided, nullptr)), 3.0, 0.3);
}

}  // namespace
}  // namespace offsetgen::check
