// Issue 2's required test, through the check's value stage: the emitted C, compiled and run, agrees
// with a 40-digit GiNaC/CLN evaluation of the un-lowered model; the shift of the zero set,
// |delta phi| / |grad F|, stays below 1e-12 of the cell for orders 1-6 (gyroid, Schwarz P,
// Neovius) and 1-4 (diamond: with the others, every golden file) of the richardson method, and at
// orders 2, 4, 6, 8 of the projection method on the same four surfaces. The project's one 40-digit
// comparison of emitted code.
#include "check/value_check.h"
#include "check_test_support.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <ostream>
#include <regex>
#include <tuple>

namespace offsetgen::check {
namespace {

using ValueCase = std::tuple<const char*, const char*, int>;  // method, surface, order
class Values : public ::testing::TestWithParam<ValueCase> {};

TEST_P(Values, ZeroSetShiftBelow1e12) {
  const auto [method, surface, order] = GetParam();
  auto c = testing::compile_catalog(surface, order, "", method);
  ASSERT_TRUE(c->result.ok) << c->result.steps.front().output;
  auto reference = rebuild_reference(c->meta);
  ValueCheckOptions options;
  options.points = order <= 4 ? 60 : (order == 5 ? 24 : 12);  // 40-digit evaluation costs ~20 ms at order 6
  options.normal_stride = 1000;                               // the normal: first point only
  ValueReport r = check_values(c->functions(), *reference, c->meta, std::nullopt, options);
  EXPECT_TRUE(r.pass);
  EXPECT_LT(r.max_shift_double, 1e-12) << method << " " << surface << " o" << order;
  bool saw_offset = false, saw_shell = false;
  for (const auto& f : r.functions) {
    EXPECT_EQ(f.points, f.function == "normal" ? 1 : options.points) << f.function;
    saw_offset |= f.function == "offset";
    saw_shell |= f.function == "shell";
  }
  EXPECT_TRUE(saw_offset && saw_shell);
}

std::string case_name(const ::testing::TestParamInfo<ValueCase>& param_info) {
  const std::string method = std::get<0>(param_info.param);
  return (method == "richardson" ? "" : method + "_") + std::get<1>(param_info.param) + "_o" +
         std::to_string(std::get<2>(param_info.param));
}

INSTANTIATE_TEST_SUITE_P(CatalogOrders1To6, Values,
                         ::testing::Combine(::testing::Values("richardson"),
                                            ::testing::Values("gyroid", "schwarzp", "neovius"),
                                            ::testing::Values(1, 2, 3, 4, 5, 6)),
                         case_name);
INSTANTIATE_TEST_SUITE_P(DiamondOrders1To4, Values,
                         ::testing::Combine(::testing::Values("richardson"), ::testing::Values("diamond"),
                                            ::testing::Values(1, 2, 3, 4)),
                         case_name);
INSTANTIATE_TEST_SUITE_P(ProjectionOrders2To8, Values,
                         ::testing::Combine(::testing::Values("projection"),
                                            ::testing::Values("gyroid", "schwarzp", "neovius", "diamond"),
                                            ::testing::Values(2, 4, 6, 8)),
                         case_name);

TEST(Values, AWrongConstantIsCaught) {
  // Same header with one constant perturbed in the 10th digit: the check must fail.
  const std::string dir = testing::scratch_dir("values-wrong");
  const std::string path = testing::write_header(dir, "gyroid", 2);
  std::string text = testing::read_text(path);
  const auto at = text.find("6.2831853071795862", text.find("static inline double gyroid_o2_offset"));
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 18, "6.2831853072795862");
  testing::write_text(path, text);
  run::FileMetadata meta = run::read_metadata(path);
  run::CompileOptions options;
  options.optimization = "-O0";
  options.cxx = false;
  run::CompileResult compiled = run::compile_and_load(path, meta, run::find_toolchain(), options);
  ASSERT_TRUE(compiled.ok);
  auto reference = rebuild_reference(meta);
  ValueCheckOptions vo;
  vo.points = 20;
  ValueReport r = check_values(compiled.library->functions(), *reference, meta, std::nullopt, vo);
  EXPECT_FALSE(r.pass);
  EXPECT_GT(r.max_shift_double, 1e-12);
}

// A header with both precisions (and so the float twins and both batch APIs).
std::string write_both_precisions(const std::string& dir, const std::string& surface, int order) {
  GenerationRequest request;
  request.surface = surface;
  request.order = order;
  request.precisions = {Precision::Double, Precision::Float};
  request.command = "check_tests";
  const Generation g = generate(request);
  const std::string path = dir + "/" + g.prefix + ".h";
  testing::write_text(path, g.c_header());
  return path;
}

// The first floating-point literal in the body of the function whose definition starts with
// `signature`, multiplied by 1.01 (suffix kept): a wrong constant in that function only.
std::string with_wrong_constant(std::string text, const std::string& signature) {
  const auto start = text.find(signature);
  EXPECT_NE(start, std::string::npos) << signature;
  const auto body = text.find("{\n", start);
  std::smatch m;
  const std::string rest = text.substr(body);
  EXPECT_TRUE(std::regex_search(rest, m, std::regex(R"(\b([0-9]+\.[0-9]+(e[-+]?[0-9]+)?)(f?)\b)")));
  const std::string changed = fmt::format("{:.17g}", std::stod(m[1].str()) * 1.01);
  text.replace(body + static_cast<size_t>(m.position(0)), static_cast<size_t>(m.length(0)),
               (changed.find('.') == std::string::npos ? changed + ".0" : changed) + m[3].str());
  return text;
}

struct WrongConstant {
  const char* signature;  // where the constant is changed
  const char* function;   // the row of the value check that must fail
};
void PrintTo(const WrongConstant& w, std::ostream* os) { *os << w.function; }

class ValuesWrongConstant : public ::testing::TestWithParam<WrongConstant> {};

// Every emitted function is judged: a wrong constant fails the check in the function that has it,
// whatever its precision or API (before, the normal, the float twins and the batch functions were
// reported only, or not compared at all).
TEST_P(ValuesWrongConstant, FailsTheFunctionThatHasIt) {
  const std::string dir = testing::scratch_dir(std::string("values-wrong-") + GetParam().function);
  const std::string path = write_both_precisions(dir, "gyroid", 2);
  testing::write_text(path, with_wrong_constant(testing::read_text(path), GetParam().signature));
  run::FileMetadata meta = run::read_metadata(path);
  run::CompileOptions options;
  options.optimization = "-O0";
  options.cxx = false;
  run::CompileResult compiled = run::compile_and_load(path, meta, run::find_toolchain(), options);
  ASSERT_TRUE(compiled.ok) << compiled.steps.front().output;
  auto reference = rebuild_reference(meta);
  ValueCheckOptions vo;
  vo.points = 40;
  vo.normal_stride = 1;
  ValueReport r = check_values(compiled.library->functions(), *reference, meta, std::nullopt, vo);
  EXPECT_FALSE(r.pass);
  // The batch loop hands its last n % 8 (16) points to the scalar function, so the batch twin of a
  // scalar function with the wrong constant may fail with it; every other function must pass.
  const std::string wrong = GetParam().function, batch_twin = wrong + "_n";
  for (const auto& f : r.functions) {
    if (f.function == wrong) {
      EXPECT_FALSE(f.pass) << f.function << " max " << f.max_shift << " limit " << f.tolerance;
    } else if (f.function != batch_twin) {
      EXPECT_TRUE(f.pass) << f.function << " max " << f.max_shift << " limit " << f.tolerance;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryKindOfFunction, ValuesWrongConstant,
                         ::testing::Values(WrongConstant{"static inline double gyroid_o2_offset(", "offset"},
                                           WrongConstant{"static inline void gyroid_o2_normal(", "normal"},
                                           WrongConstant{"static inline float gyroid_o2_offsetf(", "offsetf"},
                                           WrongConstant{"static inline float gyroid_o2_shellf(", "shellf"},
                                           WrongConstant{"static inline void gyroid_o2_normalf(", "normalf"},
                                           WrongConstant{"static inline void gyroid_o2_offset_n(", "offset_n"},
                                           WrongConstant{"static inline void gyroid_o2_shellf_n(", "shellf_n"}),
                         [](const auto& param_info) { return std::string(param_info.param.function); });

TEST(Values, ExactConversionKeepsEveryBit) {
  for (double v : {0.1, -1e-300, 0.3333333333333333, 123456.789}) {
    EXPECT_EQ(exact(v).to_double(), v);
    EXPECT_TRUE(exact(v).is_rational());
  }
}

}  // namespace
}  // namespace offsetgen::check
