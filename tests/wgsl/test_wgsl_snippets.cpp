// The WGSL snippets on Dawn (run_wgsl.mjs: Dawn's OpenGL ES backend on Mesa llvmpipe): each one runs
// in a compute shader on points near its zero set and stays within the README's 2e-5 (units of F)
// of its double C header; a second paste is a redeclaration that Dawn names with line:column; and
// --name refuses what WGSL reserves.
#include "emit/backend.h"
#include "offsetgen_test_support.h"
#include "wgsl_cases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace offsetgen::wgsl_test {
namespace {

namespace ts = test_support;

// The README's limit on a float32 snippet's offset near the zero set, in units of F.
constexpr double kLimit = 2e-5;

ts::CommandResult run_wgsl(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {OFFSETGEN_NODE, OFFSETGEN_WGSL_RUNNER};
  argv.insert(argv.end(), args.begin(), args.end());
  return ts::run_command(argv);
}

using Sample = std::array<float, 4>;  // x, y, z, h: what the shader reads

// Points near the zero set, as the README measures accuracy: |phi_d(p, h)| / |grad F(p)| <= 0.05
// cell lengths at points where |grad F| is at least 10% of its sample maximum; p uniform in
// [0, 1]^3, h uniform in [-0.05, 0.05]. Inputs are float, as the GPU sees them.
std::vector<Sample> points_near_zero_set(const WgslCase& c, std::size_t wanted, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), offset(-0.05f, 0.05f);
  const auto grad_len = [&c](const Sample& q) {
    const double e = 1e-6;
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      std::array<double, 3> a = {q[0], q[1], q[2]}, b = a;
      a[static_cast<size_t>(k)] += e;
      b[static_cast<size_t>(k)] -= e;
      const double d = (c.field(a[0], a[1], a[2]) - c.field(b[0], b[1], b[2])) / (2 * e);
      sum += d * d;
    }
    return std::sqrt(sum);
  };
  std::vector<Sample> candidates(20000);
  std::vector<double> grads(candidates.size());
  double max_grad = 0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    candidates[i] = {unit(rng), unit(rng), unit(rng), offset(rng)};
    grads[i] = grad_len(candidates[i]);
    max_grad = std::max(max_grad, grads[i]);
  }
  std::vector<Sample> near;
  for (size_t i = 0; i < candidates.size() && near.size() < wanted; ++i) {
    const Sample& q = candidates[i];
    if (grads[i] < 0.1 * max_grad) continue;
    if (std::abs(c.offset(q[0], q[1], q[2], q[3])) / grads[i] <= 0.05) near.push_back(q);
  }
  return near;
}

void write_points(const std::string& path, const std::vector<Sample>& points) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(points.data()), static_cast<std::streamsize>(points.size() * sizeof(Sample)));
}

std::vector<float> read_floats(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<float> values(bytes.size() / sizeof(float));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
  return values;
}

class WgslOnDawn : public ::testing::TestWithParam<WgslCase> {};

TEST_P(WgslOnDawn, StaysWithinTwoE5OfTheDoubleHeaderNearTheZeroSet) {
  const WgslCase& c = GetParam();
  const std::vector<Sample> points = points_near_zero_set(c, 400, 14u);
  ASSERT_GE(points.size(), 200u) << c.prefix << ": too few sample points near the zero set";
  const std::string dir = ts::scratch_dir(std::string("wgsl-") + c.prefix);
  write_points(dir + "/points.f32", points);
  const ts::CommandResult r = run_wgsl({"run", c.snippet, c.prefix, "3", dir + "/points.f32", dir + "/results.f32"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<float> got = read_floats(dir + "/results.f32");
  ASSERT_EQ(got.size(), points.size() * 8) << r.output;

  double field = 0, offset = 0, shell = 0, normal = 0;
  size_t worst = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Sample& q = points[i];
    const float* g = &got[8 * i];
    field = std::max(field, std::abs(g[0] - c.field(q[0], q[1], q[2])));
    const double e = std::abs(g[1] - c.offset(q[0], q[1], q[2], q[3]));
    if (e > offset) offset = e, worst = i;
    // The shell is a product of two offsets: its error relative to that of one face.
    const double s = c.shell(q[0], q[1], q[2], 2.0 * std::abs(static_cast<double>(q[3])));
    shell = std::max(shell, std::abs(g[2] - s) / (1.0 + std::abs(s)));
    double n[3];
    c.normal(q[0], q[1], q[2], q[3], n);
    normal = std::max(normal, std::hypot(g[4] - n[0], g[5] - n[1], g[6] - n[2]));
  }
  // The numbers the README quotes: ctest -L wgsl --verbose prints them.
  std::cout << "[wgsl accuracy] " << c.prefix << ": offset " << offset << " (units of F, " << points.size()
            << " points near the zero set), field " << field << ", shell " << shell << ", normal " << normal << "\n";
  RecordProperty("offset_max_error", std::to_string(offset));
  const Sample& w = points[worst];
  EXPECT_LT(offset, kLimit) << c.prefix << ": worst at (" << w[0] << ", " << w[1] << ", " << w[2] << "), h = " << w[3]
                            << "\n"
                            << r.output;
  EXPECT_LT(field, kLimit) << c.prefix;
  EXPECT_LT(shell, kLimit) << c.prefix;
  EXPECT_LT(normal, 1e-4) << c.prefix << ": the unit normal";
}

INSTANTIATE_TEST_SUITE_P(Generated, WgslOnDawn, ::testing::ValuesIn(wgsl_cases()),
                         [](const ::testing::TestParamInfo<WgslCase>& param_info) {
                           return std::string(param_info.param.prefix);
                         });

TEST(WgslSnippet, WithTheDensityRelationsValidatesOnDawn) {
  const ts::CommandResult r = run_wgsl({"validate", OFFSETGEN_WGSL_DENSITY_SNIPPET});
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// WGSL has no preprocessor: the snippet cannot guard itself, so its comment says "paste once" and a
// second copy must fail loudly, naming the function and the line of the second copy.
TEST(WgslSnippet, PastedTwiceIsARedeclarationDawnReportsWithLineAndColumn) {
  const std::string snippet = wgsl_cases().front().snippet;
  const std::string prefix = wgsl_cases().front().prefix;
  const ts::CommandResult once = run_wgsl({"validate", snippet});
  EXPECT_EQ(once.exit_code, 0) << once.output;
  const ts::CommandResult twice = run_wgsl({"validate", snippet, snippet});
  EXPECT_EQ(twice.exit_code, 1) << twice.output;
  EXPECT_NE(twice.output.find("redeclaration of '" + prefix + "_field'"), std::string::npos) << twice.output;
  // <file>#2:<line>:<column>: error: ... (the line counted within the second copy).
  const std::string text = ts::read_file(snippet);
  const size_t at = text.find("\nfn " + prefix + "_field(");  // the declaration, not the comment's list
  ASSERT_NE(at, std::string::npos);
  const auto line = 2 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  EXPECT_NE(
      twice.output.find(snippet + "#2:" + std::to_string(line) + ":1: error: redeclaration of '" + prefix + "_field'"),
      std::string::npos)
      << twice.output;
}

// The README's paste example, after the golden gyroid_o4.wgsl it names, is a valid module.
TEST(WgslSnippet, TheReadmePasteExampleValidatesOnDawn) {
  const std::string readme = ts::read_file(ts::source_dir() + "/README.md");
  const size_t begin = readme.find("```wgsl\n");
  ASSERT_NE(begin, std::string::npos) << "README.md has no ```wgsl example";
  const size_t end = readme.find("```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  const std::string example = ts::scratch_dir("wgsl-readme") + "/example.wgsl";
  ts::write_file(example, readme.substr(begin + 8, end - begin - 8));
  const ts::CommandResult r = run_wgsl({"validate", ts::source_dir() + "/generated/gyroid_o4.wgsl", example});
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(WgslNames, TheBackendRefusesWhatWgslReserves) {
  const Backend& wgsl = backend("wgsl");
  for (const char* word : {"fn", "let", "var", "override", "wgsl", "demote_to_helper", "_", "__x", "__"})
    EXPECT_TRUE(wgsl.reserved(word).has_value()) << word;
  for (const char* word : {"gyroid_o4_field", "_x", "a__b", "gl_foo", "float3", "texture"})
    EXPECT_FALSE(wgsl.reserved(word).has_value()) << word;
}

TEST(WgslNames, NameStartingWithTwoUnderscoresIsRefusedForWgsl) {
  const std::string dir = ts::scratch_dir("wgsl-names");
  const ts::CommandResult r = ts::run_offsetgen(
      {"generate", "--surface", "gyroid", "--order", "1", "--name", "__g", "--lang", "wgsl", "--out-dir", dir});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("WGSL"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("__"), std::string::npos) << r.output;
  EXPECT_TRUE(ts::read_file(dir + "/__g_o1.wgsl").empty()) << "a refused name must write nothing";
}

}  // namespace
}  // namespace offsetgen::wgsl_test
