// The projection method measured the paper's way (section 5.2.1) on compiled headers: slopes 2, 4,
// 6 and 8 both ways for orders 2-8 on the gyroid, Schwarz P and Neovius, the errors at h = 0.01 L
// the method's issue asks for, and graded walls of order K + 1 read at the foot point.
#include "check/reference.h"
#include "check/thickness.h"
#include "check_test_support.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace offsetgen::check {
namespace {

struct Case {
  std::string surface;
  int order;
  std::vector<double> h;  // inside the asymptotic range and above the roundoff floor
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.surface << "_o" << c.order; }

class ProjectionConvergence : public ::testing::TestWithParam<Case> {};

TEST_P(ProjectionConvergence, SlopeMatchesTheOrderBothWays) {
  const Case& c = GetParam();
  auto compiled = testing::compile_catalog(c.surface, c.order, "", "projection");
  ASSERT_TRUE(compiled->result.ok) << compiled->result.steps.front().output;
  // phi -> F starts from points on phi = 0, whose sample at high order needs the paper's grid.
  ThicknessReport r =
      measure_constant(make_probe(compiled->functions()), testing::thickness_options(c.h, c.order >= 6 ? 21 : 11));
  for (const auto& row : r.rows) {
    EXPECT_EQ(row.f_to_phi.missed, 0) << "h = " << row.h;
    EXPECT_EQ(row.phi_to_f.missed, 0) << "h = " << row.h;
  }
  const double forward = loglog_slope(c.h, testing::column(r, &SweepRow::f_to_phi));
  const double backward = loglog_slope(c.h, testing::column(r, &SweepRow::phi_to_f));
  EXPECT_NEAR(forward, c.order, 0.3) << "F -> phi";
  EXPECT_NEAR(backward, c.order, 0.3) << "phi -> F";
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* s : {"gyroid", "schwarzp", "neovius"}) {
    const std::string surface = s;
    out.push_back({surface, 2, {0.0025, 0.005, 0.01}});
    out.push_back({surface, 4, {0.0025, 0.005, 0.01}});
    // High orders reach the roundoff floor early (gyroid, Schwarz P); Neovius converges later.
    const bool late = surface == "neovius";
    out.push_back({surface, 6, late ? std::vector<double>{0.005, 0.01, 0.02} : std::vector<double>{0.01, 0.02, 0.04}});
    out.push_back({surface, 8, late ? std::vector<double>{0.007, 0.01, 0.014} : std::vector<double>{0.02, 0.04, 0.08}});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(CatalogOrders2To8, ProjectionConvergence, ::testing::ValuesIn(cases()),
                         [](const auto& test) { return test.param.surface + "_o" + std::to_string(test.param.order); });

double error_at_one_percent(const std::string& surface, int order) {
  auto c = testing::compile_catalog(surface, order, "", "projection");
  EXPECT_TRUE(c->result.ok);
  if (!c->result.ok) return 1;
  ThicknessReport r = measure_constant(make_probe(c->functions()), testing::thickness_options({0.01}));
  return std::max(r.rows.at(0).f_to_phi.mean, r.rows.at(0).phi_to_f.mean);
}

TEST(ProjectionAccuracy, ErrorsAtOnePercentMeetTheMethodsTargets) {
  EXPECT_LT(error_at_one_percent("gyroid", 4), 1e-7);
  EXPECT_LT(error_at_one_percent("gyroid", 8), 1e-12);
  EXPECT_LT(error_at_one_percent("schwarzp", 8), 1e-12);
  EXPECT_LT(error_at_one_percent("neovius", 8), 2e-9);
  for (const char* surface : {"gyroid", "schwarzp", "neovius"})
    EXPECT_LT(error_at_one_percent(surface, 16), 1e-13) << surface;
}

// A linear thickness field with total thickness 0.01 L at its thick end, order 8 (K = 3): each wall
// converges at order 4 to t(p0)/2 from its foot point p0, with a mean error below 1e-7.
TEST(ProjectionGraded, LinearThicknessConvergesAtOrderFourAtOrderEight) {
  auto c = testing::compile_catalog("gyroid", 8, "0.01*x", "projection");
  ASSERT_TRUE(c->result.ok);
  auto reference = rebuild_reference(c->meta);
  const Generation& g = reference->generation;
  const GiNaC::ex t = parse_thickness("0.01*x", c->meta, {});
  ThicknessFunction thickness(t, 3);
  Probe probe = make_probe(c->functions());
  auto program = std::make_shared<Program>(lower_graded_wall(g.surface, *g.construction, t));
  auto wall = std::make_shared<Evaluator>(*program);
  probe.graded_wall = [program, wall](const double* q, double s) { return (*wall)({q[0], q[1], q[2], s}).at(0); };
  GradedReport r = measure_graded(probe, thickness, "0.01*x", true, testing::thickness_options({0.0025, 0.005, 0.01}));
  ASSERT_TRUE(r.fit_one_sided.fitted);
  EXPECT_GE(r.fit_one_sided.slope, 3.8);
  EXPECT_GE(r.fit_total.slope, 3.8);
  const GradedRow& given = r.rows.back();
  ASSERT_TRUE(given.as_given && given.compiled_graded);
  EXPECT_LT(given.one_sided.mean, 1e-7);
  EXPECT_LT(given.total.mean, 1e-7);
}

}  // namespace
}  // namespace offsetgen::check
