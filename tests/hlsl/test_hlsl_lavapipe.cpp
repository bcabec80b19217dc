// Every generated HLSL snippet runs as a Vulkan compute shader on Mesa's lavapipe: glslang's HLSL
// front end (-D -V -S comp -e main) makes the SPIR-V, vulkan_compute.h runs it over points near
// the zero set, and the float results are compared with the double C header of the same program
// (the metrics of tests/glsl/generated_accuracy.h), held to the README's 2e-5.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "generated_accuracy.h"
#include "generated_cases.h"
#include "lavapipe_cases.h"
#include "offsetgen_test_support.h"
#include "run/vulkan_compute.h"

namespace {

namespace gt = offsetgen::glsl_test;
namespace ht = offsetgen::hlsl_test;
namespace vk = offsetgen::vulkan;
namespace ts = offsetgen::test_support;

constexpr std::size_t kPoints = 32768;
constexpr std::uint32_t kSeed = 20261123u;
constexpr double kTolerance = 2e-5;        // the README's limit, units of F
constexpr double kNormalTolerance = 2e-4;  // as tests/glsl: unit normals near the zero set

// The compute shader a user would write around the snippet: one point in, two float4 out.
std::string compute_shader(const std::string& snippet, const std::string& P) {
  return snippet +
         "\n[[vk::binding(0, 0)]] StructuredBuffer<float4> og_in;\n"
         "[[vk::binding(1, 0)]] RWStructuredBuffer<float4> og_out;\n"
         "[numthreads(64, 1, 1)]\n"
         "void main(uint3 id : SV_DispatchThreadID)\n"
         "{\n"
         "    float4 q = og_in[id.x];\n"
         "    float3 p = q.xyz;\n"
         "    og_out[2 * id.x] = float4(" +
         P + "_field(p), " + P + "_offset(p, q.w), " + P +
         "_shell(p, 2.0 * abs(q.w)), 0.0);\n"
         "    og_out[2 * id.x + 1] = float4(" +
         P +
         "_normal(p, q.w), 0.0);\n"
         "}\n";
}

class HlslOnLavapipe : public ::testing::TestWithParam<ht::LavapipeCase> {};

TEST_P(HlslOnLavapipe, WithinTheLimitOfTheDoubleHeader) {
  const ht::LavapipeCase& c = GetParam();
  const gt::GeneratedCase as_glsl_case = {"",      0,        "",      c.prefix, "",      c.snippet, c.field, c.offset,
                                          c.shell, c.normal, nullptr, nullptr,  nullptr, nullptr,   nullptr, nullptr};
  const gt::DoubleReference ref = gt::make_reference(as_glsl_case, kPoints, kSeed);

  const std::string dir = ts::scratch_dir(std::string("lavapipe_") + c.prefix);
  const std::string shader = dir + "/compute.hlsl", module = dir + "/compute.spv";
  ts::write_file(shader, compute_shader(ts::read_file(c.snippet), c.prefix));
  const auto compiled =
      ts::run_command({OFFSETGEN_GLSLANG, "-D", "-V", "-S", "comp", "-e", "main", "-o", module, shader});
  ASSERT_EQ(compiled.exit_code, 0) << "glslangValidator rejects " << shader << ":\n" << compiled.output;

  std::vector<vk::Float4> inputs(ref.points.begin(), ref.points.end());
  const vk::ComputeRun run = vk::run_on_lavapipe(vk::read_spirv(module), inputs, 2);
  gt::FloatResults got;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const float* out = &run.outputs[8 * i];
    got.field.push_back(out[0]);
    got.offset.push_back(out[1]);
    got.shell.push_back(out[2]);
    got.normal.insert(got.normal.end(), out + 4, out + 7);
  }
  const gt::Accuracy a = gt::measure(ref, got);
  std::printf("[ measured ] %-16s HLSL on %s: %s\n", c.prefix, run.device.c_str(), gt::describe(a).c_str());
  EXPECT_LT(a.field, kTolerance) << c.prefix;
  EXPECT_LT(a.offset, kTolerance) << c.prefix;
  EXPECT_LT(a.zero_set, kTolerance) << c.prefix;
  EXPECT_LT(a.shell, kTolerance) << c.prefix;
  EXPECT_LT(a.normal, kNormalTolerance) << c.prefix;
  EXPECT_GT(a.near_points, kPoints / 50) << c.prefix << ": too few points near the zero set";
}

// Snippets of two surfaces in one shader, one of them twice: each brings its own <prefix>_sin/_cos,
// nothing clashes, and both still match their C headers.
TEST(HlslSnippetsOfTwoSurfaces, RunTogetherInOneShader) {
  const ht::LavapipeCase* g = nullptr;
  const ht::LavapipeCase* d = nullptr;
  for (const auto& c : ht::lavapipe_cases()) {
    if (std::string(c.prefix) == "gyroid_o4") g = &c;
    if (std::string(c.prefix) == "diamond_proj_o4") d = &c;
  }
  ASSERT_TRUE(g && d);
  const std::string gs = ts::read_file(g->snippet), ds = ts::read_file(d->snippet);
  const std::string dir = ts::scratch_dir("lavapipe_two_surfaces");
  const std::string shader = dir + "/compute.hlsl", module = dir + "/compute.spv";
  ts::write_file(shader, gs + ds + gs +
                             "\n[[vk::binding(0, 0)]] StructuredBuffer<float4> og_in;\n"
                             "[[vk::binding(1, 0)]] RWStructuredBuffer<float4> og_out;\n"
                             "[numthreads(64, 1, 1)]\n"
                             "void main(uint3 id : SV_DispatchThreadID)\n"
                             "{\n"
                             "    float4 q = og_in[id.x];\n"
                             "    og_out[id.x] = float4(gyroid_o4_field(q.xyz), diamond_proj_o4_field(q.xyz), "
                             "gyroid_o4_offset(q.xyz, q.w), diamond_proj_o4_offset(q.xyz, q.w));\n"
                             "}\n");
  const auto compiled =
      ts::run_command({OFFSETGEN_GLSLANG, "-D", "-V", "-S", "comp", "-e", "main", "-o", module, shader});
  ASSERT_EQ(compiled.exit_code, 0) << "glslangValidator rejects " << shader << ":\n" << compiled.output;
  const gt::GeneratedCase as_glsl_case = {"",       0,         "",      "",      "",      "",      g->field, g->offset,
                                          g->shell, g->normal, nullptr, nullptr, nullptr, nullptr, nullptr,  nullptr};
  const auto points = gt::make_reference(as_glsl_case, 4096, kSeed).points;
  const std::vector<vk::Float4> inputs(points.begin(), points.end());
  const vk::ComputeRun run = vk::run_on_lavapipe(vk::read_spirv(module), inputs, 1);
  double worst = 0.0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& p = inputs[i];
    const double want[4] = {g->field(p[0], p[1], p[2]), d->field(p[0], p[1], p[2]), g->offset(p[0], p[1], p[2], p[3]),
                            d->offset(p[0], p[1], p[2], p[3])};
    for (int k = 0; k < 2; ++k) worst = std::max(worst, std::abs(run.outputs[4 * i + k] - want[k]));
    for (int k = 2; k < 4; ++k) EXPECT_TRUE(std::isfinite(run.outputs[4 * i + k]));
  }
  std::printf("[ measured ] gyroid_o4 and diamond_proj_o4 in one shader: fields within %.2e\n", worst);
  EXPECT_LT(worst, kTolerance);
}

INSTANTIATE_TEST_SUITE_P(All, HlslOnLavapipe, ::testing::ValuesIn(ht::lavapipe_cases()),
                         [](const ::testing::TestParamInfo<ht::LavapipeCase>& p) {
                           return std::string(p.param.prefix);
                         });

}  // namespace
