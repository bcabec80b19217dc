// Degenerate expressions: linear (constant gradient), one variable, constant Hessian. Their functions
// ignore some inputs or fold to constants; every emitted function must still compile under the flags
// the README promises (C99 and C++17 with -pedantic -Wall -Wextra -Werror, double and float; the
// GLSL snippet under glslang for the four targets) and match the 40-digit reference.
#include "check_test_support.h"
#include "run/process.h"

#include <gtest/gtest.h>

#include <ostream>
#include <regex>
#include <tuple>

namespace offsetgen::check {
namespace {

struct Degenerate {
  const char* name;
  const char* expression;
};
// Stable test names (the default would print the pointers' bytes).
void PrintTo(const Degenerate& d, std::ostream* os) { *os << d.name; }

class DegenerateExpression : public ::testing::TestWithParam<std::tuple<Degenerate, int>> {};

TEST_P(DegenerateExpression, CompilesStrictlyInEveryLanguageAndMatchesTheReference) {
  const auto [expression, order] = GetParam();
  const std::string dir = testing::scratch_dir(std::string("degenerate-") + expression.name + std::to_string(order));
  auto gen = testing::run_offsetgen({"generate", "--expr", expression.expression, "--name", expression.name, "--order",
                                     std::to_string(order), "--precision", "both", "--lang", "all", "--out-dir", dir,
                                     "--quiet"});
  ASSERT_EQ(gen.exit_code, 0) << gen.output;
  const std::string header = dir + "/" + expression.name + ".h";
  const std::regex constant_comparison(R"(= \(?-?[0-9][0-9.e+-]*f?\)? (>|<=) \(?-?[0-9][0-9.e+-]*f?\)?;)");
  EXPECT_FALSE(std::regex_search(testing::read_text(header), constant_comparison)) << "an unfolded constant comparison";
  auto c = testing::run_offsetgen({"check", header, "--no-thickness", "--points", "40"});
  EXPECT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("C++17 strict                 ok"), std::string::npos) << c.output;
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed (glslang-tools)";
  auto g = testing::run_offsetgen({"check", dir + "/" + expression.name + ".glsl", "--points", "40"});
  EXPECT_EQ(g.exit_code, 0) << g.output;
}

INSTANTIATE_TEST_SUITE_P(
    LinearOneVariableConstantHessian, DegenerateExpression,
    ::testing::Combine(::testing::Values(Degenerate{"plane3", "x + y + z"}, Degenerate{"line2", "2*x - 3*y + 0.5"},
                                         Degenerate{"xonly2", "x - 0.5"}, Degenerate{"zonly3", "z - 0.25"},
                                         Degenerate{"ycubic2", "y^3 - 0.1"},
                                         Degenerate{"sphere3", "x^2 + y^2 + z^2 - 0.2"}),
                       ::testing::Values(1, 3)),
    [](const auto& param_info) {
      return std::string(std::get<0>(param_info.param).name) + "_o" + std::to_string(std::get<1>(param_info.param));
    });

}  // namespace
}  // namespace offsetgen::check
