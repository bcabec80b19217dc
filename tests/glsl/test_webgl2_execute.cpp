// The order-4 gyroid snippet as a WebGL2 page runs it: headless Chromium, ANGLE on SwiftShader
// (webgl2_runner.h), a GLSL ES 3.00 fragment shader under a `precision mediump float` host and
// under a highp one, compared with the double C header near the zero set (generated_accuracy.h).
// SwiftShader's builtin sin is off by 1.9e-4; the snippet's own sin/cos (emit/shader_trig.h) keep
// the README's 2e-5. The same snippet on the builtins is measured too, to show what the own trig
// buys (printed, not asserted: a future SwiftShader may get better).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "generated_accuracy.h"
#include "generated_cases.h"
#include "gyroid_o4.h"
#include "offsetgen_test_support.h"
#include "run/glsl_source.h"
#include "webgl2_runner.h"

namespace {

namespace glsl = offsetgen::glsl;
namespace gt = offsetgen::glsl_test;

constexpr std::size_t kPoints = 65536;
constexpr std::uint32_t kSeed = 20261123u;
constexpr double kTolerance = 2e-5;  // the README's limit, units of F

// The build-time gyroid snippets of tests/glsl/CMakeLists.txt (target glsl_gyroid).
const gt::GeneratedCase& gyroid_order4() {
  static const gt::GeneratedCase c = {"gyroid",
                                      4,
                                      "richardson",
                                      "gyroid_o4",
                                      OFFSETGEN_GYROID_O4 ".h",
                                      OFFSETGEN_GYROID_O4 ".glsl",
                                      &gyroid_o4_field,
                                      &gyroid_o4_offset,
                                      &gyroid_o4_shell,
                                      &gyroid_o4_normal,
                                      nullptr,
                                      &gyroid_o4_fieldf,
                                      &gyroid_o4_offsetf,
                                      &gyroid_o4_shellf,
                                      &gyroid_o4_normalf,
                                      nullptr};
  return c;
}

// The snippet with the driver's sin and cos in place of its own: what it was before issue 14.
std::string on_builtin_trig(std::string snippet, const std::string& prefix) {
  for (const std::string fn : {"sin", "cos"}) {
    const std::string own = prefix + "_" + fn;
    const std::string definition = "highp float " + own + "(";
    for (auto at = snippet.find(definition); at != std::string::npos; at = snippet.find(definition, at))
      snippet.replace(at, definition.size(), "highp float unused_" + fn + "(");
    for (auto at = snippet.find(own + "("); at != std::string::npos; at = snippet.find(own + "(", at))
      snippet.replace(at, own.size(), fn);
  }
  return snippet;
}

std::vector<gt::WebGl2Job> jobs_for(const std::string& snippet, const std::string& precision, const std::string& P) {
  return {{snippet, precision,
           "vec3(" + P + "_field(p.xyz), " + P + "_offset(p.xyz, p.w), " + P + "_shell(p.xyz, 2.0 * abs(p.w)))", 3},
          {snippet, precision, P + "_normal(p.xyz, p.w)", 3}};
}

gt::Accuracy accuracy(const gt::DoubleReference& ref, const std::vector<float>& values,
                      const std::vector<float>& normals) {
  gt::FloatResults got;
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    got.field.push_back(values[3 * i]);
    got.offset.push_back(values[3 * i + 1]);
    got.shell.push_back(values[3 * i + 2]);
  }
  got.normal = normals;
  return gt::measure(ref, got);
}

TEST(SlowWebGl2SwiftShader, GyroidOrder4WithinTheLimitUnderMediumpAndHighpHosts) {
  const gt::GeneratedCase& c = gyroid_order4();
  const gt::DoubleReference ref = gt::make_reference(c, kPoints, kSeed);
  const std::string snippet = glsl::read_text_file(c.snippet);
  ASSERT_NE(snippet.find(std::string(c.prefix) + "_sin("), std::string::npos) << "the snippet has no own sin";
  const std::vector<std::string> hosts = {"mediump", "highp"};
  std::vector<gt::WebGl2Job> jobs;
  for (const auto& host : hosts)
    for (auto& job : jobs_for(snippet, host, c.prefix)) jobs.push_back(job);
  for (auto& job : jobs_for(on_builtin_trig(snippet, c.prefix), "highp", c.prefix)) jobs.push_back(job);

  const auto results = gt::run_webgl2(jobs, ref.points, offsetgen::test_support::scratch_dir("webgl2"));
  for (std::size_t h = 0; h < hosts.size(); ++h) {
    const gt::Accuracy a = accuracy(ref, results[2 * h], results[2 * h + 1]);
    std::printf("[ measured ] gyroid o4 WebGL2/SwiftShader, %s host: %s\n", hosts[h].c_str(), gt::describe(a).c_str());
    EXPECT_LT(a.offset, kTolerance) << hosts[h] << " host";
    EXPECT_LT(a.field, kTolerance) << hosts[h] << " host";
    EXPECT_LT(a.zero_set, kTolerance) << hosts[h] << " host";
    EXPECT_GT(a.near_points, kPoints / 50);
  }
  const gt::Accuracy builtin = accuracy(ref, results[4], results[5]);
  std::printf("[ measured ] gyroid o4 WebGL2/SwiftShader, highp host, driver's sin/cos: %s\n",
              gt::describe(builtin).c_str());
}

}  // namespace
