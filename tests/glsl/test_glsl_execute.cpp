// Runs snippets on llvmpipe (compute and fragment paths) against double-precision references.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <tuple>

#include "glsl_executor.h"
#include "glsl_source.h"
#include "headless_gl.h"
#include "reference_check.h"
#include "reference_surfaces.h"

namespace {

namespace glsl = offsetgen::glsl;
namespace gt = offsetgen::glsl_test;
using gt::Quantity;

constexpr std::size_t kPoints = 100000;
constexpr double kHMax = 0.05;
// Absolute tolerance in units of F. The first-order gyroid reaches |F| + |h||grad F| ~ 1.9, and
// float32 sin/cos/sqrt at that size err by a few 1e-7, so 2e-5 leaves a wide margin while still
// catching a lost highp (fp16 would be off by ~1e-3).
constexpr double kTolerance = 2e-5;
// The shell multiplies two offsets of size up to ~2: its error scales accordingly.
constexpr double kShellTolerance = 1e-4;
// Unit normals, compared where |grad phi| >= 0.5.
constexpr double kNormalTolerance = 1e-4;

const std::vector<glsl::Point>& points() {
  static const auto pts = gt::random_points(kPoints, 3, kHMax, 20210412u);
  return pts;
}

using Case = std::tuple<gt::SurfaceReference, glsl::Path>;

class SnippetVsReference : public ::testing::TestWithParam<Case> {
 protected:
  void expect_within(Quantity q, double tolerance) {
    const auto& [ref, path] = GetParam();
    const gt::ErrorReport r = gt::check(ref, q, path, points());
    std::cout << "[ measured ] " << r.describe() << "\n";
    RecordProperty(std::string(gt::quantity_name(q)) + "_max_abs_error",
                   std::to_string(r.max_abs_error));
    EXPECT_LT(r.max_abs_error, tolerance) << r.describe();
    EXPECT_GT(r.compared, kPoints / 2) << r.describe();
  }
};

TEST_P(SnippetVsReference, Field) { expect_within(Quantity::Field, kTolerance); }
TEST_P(SnippetVsReference, Offset) { expect_within(Quantity::Offset, kTolerance); }
TEST_P(SnippetVsReference, Shell) { expect_within(Quantity::Shell, kShellTolerance); }
TEST_P(SnippetVsReference, Normal) {
  if (!std::get<0>(GetParam()).offset_gradient) GTEST_SKIP() << "no reference gradient";
  expect_within(Quantity::Normal, kNormalTolerance);
}

INSTANTIATE_TEST_SUITE_P(AllSnippets, SnippetVsReference,
                         ::testing::Combine(::testing::ValuesIn(gt::all_references()),
                                            ::testing::ValuesIn(glsl::all_paths())),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           return std::get<0>(param_info.param).prefix +
                                  (std::get<1>(param_info.param) == glsl::Path::Compute
                                       ? "_Compute"
                                       : "_Fragment");
                         });

// The reference gradient is hand-derived (Hessian): check it against central differences.
TEST(Reference, GyroidOffsetGradientMatchesFiniteDifferences) {
  const auto pts = gt::random_points(200, 3, kHMax, 7u);
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

class ExecutorPath : public ::testing::TestWithParam<glsl::Path> {};

// More points than one draw / texture holds: chunk boundaries must not shift or drop results.
TEST_P(ExecutorPath, PassesInputsThroughBitExactAcrossChunks) {
  const std::size_t n = GetParam() == glsl::Path::Fragment ? 1024 * 1024 + 77 : 65535 * 64 + 77;
  std::vector<glsl::Point> in(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto f = static_cast<float>(i);
    in[i] = {f, -f, 1.0f / (f + 1.0f), std::sqrt(f)};
  }
  const auto out = glsl::run(GetParam(), "", "p.wzy", in, 3);
  ASSERT_EQ(out.size(), 3 * n);
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mismatches += std::memcmp(&out[3 * i], &in[i][3], 4) != 0;
    mismatches += std::memcmp(&out[3 * i + 1], &in[i][2], 4) != 0;
    mismatches += std::memcmp(&out[3 * i + 2], &in[i][1], 4) != 0;
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST_P(ExecutorPath, BrokenSnippetNamesTheSnippetLine) {
  const std::string snippet =
      "highp float good(highp vec3 p) { return p.x; }\n"
      "highp float bad(highp vec3 p) { return p.x + undefined_thing; }\n";
  try {
    glsl::run(GetParam(), snippet, "bad(p.xyz)", {glsl::Point{}}, 1);
    FAIL() << "expected a ShaderError";
  } catch (const offsetgen::gl::ShaderError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("snippet line 2: highp float bad"), std::string::npos) << msg;
    EXPECT_NE(msg.find("undefined_thing"), std::string::npos) << msg;
  }
}

TEST_P(ExecutorPath, WrongResultTypeIsAHostLineError) {
  try {
    glsl::run(GetParam(), "", "p.xyz", {glsl::Point{}}, 1);
    FAIL() << "expected a ShaderError";
  } catch (const offsetgen::gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("host line"), std::string::npos) << e.what();
  }
}

TEST_P(ExecutorPath, EmptyInputGivesEmptyOutput) {
  EXPECT_TRUE(glsl::run(GetParam(), "", "p.x", {}, 1).empty());
}

INSTANTIATE_TEST_SUITE_P(BothPaths, ExecutorPath, ::testing::ValuesIn(glsl::all_paths()),
                         [](const ::testing::TestParamInfo<glsl::Path>& param_info) {
                           return std::string(param_info.param == glsl::Path::Compute ? "Compute"
                                                                                      : "Fragment");
                         });

TEST(Executor, ReportsRendererAndDesktopVersion) {
  offsetgen::gl::make_current(offsetgen::gl::Api::Desktop43);
  std::cout << "[ renderer ] " << offsetgen::gl::renderer() << " / " << offsetgen::gl::version()
            << "\n";
  EXPECT_NE(offsetgen::gl::version().find("4."), std::string::npos);
}

}  // namespace
