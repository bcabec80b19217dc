// The llvmpipe executor itself (compute and fragment paths): inputs pass through bit-exactly, and
// shader errors name their line. Generated snippets are run in test_generated_execute.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <tuple>

#include "run/glsl_executor.h"
#include "run/glsl_source.h"
#include "run/headless_gl.h"

namespace {

namespace glsl = offsetgen::glsl;

class ExecutorPath : public ::testing::TestWithParam<glsl::Path> {};

// More points than one draw / texture holds: chunk boundaries must not shift or drop results.
TEST_P(ExecutorPath, PassesInputsThroughBitExactAcrossChunks) {
  const std::size_t n = GetParam() == glsl::Path::Fragment ? 1024 * 1024 + 77 : 65535 * 64 + 77;
  std::vector<glsl::Sample> in(n);
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
    glsl::run(GetParam(), snippet, "bad(p.xyz)", {glsl::Sample{}}, 1);
    FAIL() << "expected a ShaderError";
  } catch (const offsetgen::gl::ShaderError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("snippet line 2: highp float bad"), std::string::npos) << msg;
    EXPECT_NE(msg.find("undefined_thing"), std::string::npos) << msg;
  }
}

TEST_P(ExecutorPath, WrongResultTypeIsAHostLineError) {
  try {
    glsl::run(GetParam(), "", "p.xyz", {glsl::Sample{}}, 1);
    FAIL() << "expected a ShaderError";
  } catch (const offsetgen::gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("host line"), std::string::npos) << e.what();
  }
}

TEST_P(ExecutorPath, EmptyInputGivesEmptyOutput) { EXPECT_TRUE(glsl::run(GetParam(), "", "p.x", {}, 1).empty()); }

INSTANTIATE_TEST_SUITE_P(BothPaths, ExecutorPath, ::testing::ValuesIn(glsl::all_paths()),
                         [](const ::testing::TestParamInfo<glsl::Path>& param_info) {
                           return std::string(param_info.param == glsl::Path::Compute ? "Compute" : "Fragment");
                         });

TEST(Executor, ReportsRendererAndDesktopVersion) {
  offsetgen::gl::make_current(offsetgen::gl::Api::Desktop43);
  std::cout << "[ renderer ] " << offsetgen::gl::renderer() << " / " << offsetgen::gl::version() << "\n";
  EXPECT_NE(offsetgen::gl::version().find("4."), std::string::npos);
}

}  // namespace
