// The CLI as a user meets it: help, version, list, exit codes, and bad input that loses nothing.
#include "emit/backend.h"
#include "offset/method.h"
#include "surfaces/catalog.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

namespace offsetgen {
namespace {
namespace fs = std::filesystem;
using testing::run_offsetgen;

TEST(Cli, HelpVersionAndList) {
  auto help = run_offsetgen("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("generate"), std::string::npos);
  auto version = run_offsetgen("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find(std::string("offsetgen ") + OFFSETGEN_VERSION), std::string::npos) << version.output;
  auto list = run_offsetgen("list");
  EXPECT_EQ(list.exit_code, 0);
  for (const char* name :
       {"gyroid", "schwarzp", "diamond", "neovius", "iwp", "fischerkoch", "lidinoid", "splitp", "frd"})
    EXPECT_NE(list.output.find(name), std::string::npos) << name;
  EXPECT_EQ(run_offsetgen("").exit_code, 2);
  EXPECT_EQ(run_offsetgen("generate --no-such-option").exit_code, 2);
}

// A calendar date (2026-11-21, 21.11.2026, 11/21/26 style with a 4-digit year), a time of day
// (07:36, 07:36:12) or a month name followed by a day, as `date`, __DATE__ and ISO stamps print them.
const std::regex kDateOrTime(
    R"((\b(19|20)\d\d[-/.]\d\d?[-/.]\d\d?\b)|(\b\d\d?[-/.]\d\d?[-/.](19|20)\d\d\b)|)"
    R"((\b\d\d?:\d\d(:\d\d)?\b)|(\b(Jan|Feb|Mar|Apr|May|Jun|Jul|Aug|Sep|Oct|Nov|Dec) +\d\d?\b))");

TEST(Cli, DatePatternRecognisesTimestamps) {
  for (const char* stamp : {"2026-11-21", "2031/01/05", "21.11.2026", "07:36", "generated at 23:59:59",
                            "Sat Nov 21 07:36:12 UTC 2026", "Nov 21 2026"})
    EXPECT_TRUE(std::regex_search(std::string(stamp), kDateOrTime)) << stamp;
  for (const char* number : {"1.7320525396196846", "6.2831853071795862", "\"order\":2,\"dims\":3", "offsetgen 0.1.0"})
    EXPECT_FALSE(std::regex_search(std::string(number), kDateOrTime)) << number;
}

TEST(Cli, GeneratesAHeaderWithTheDocumentedApiAndNoTimestamp) {
  std::string dir = testing::scratch_dir("cli_generate");
  auto r = run_offsetgen("generate --surface gyroid --order 2 -o " + dir + "/g.h");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string h = testing::read_file(dir + "/g.h");
  for (const char* needle : {"static inline double gyroid_o2_field(double x, double y, double z)",
                             "static inline double gyroid_o2_offset(double x, double y, double z, double h)",
                             "static inline double gyroid_o2_shell(double x, double y, double z, double t)",
                             "static inline void gyroid_o2_normal(double x, double y, double z, double h, double n[3])",
                             "#ifndef OFFSETGEN_GYROID_O2_H", "Total ops: ",
                             "Command: offsetgen generate --surface gyroid --order 2 -o g.h", "offsetgen-metadata"})
    EXPECT_NE(h.find(needle), std::string::npos) << needle;
  EXPECT_EQ(h.find("pow("), std::string::npos);
  std::smatch stamp;
  EXPECT_FALSE(std::regex_search(h, stamp, kDateOrTime)) << "a date or time in the header: " << stamp.str();
}

TEST(Cli, UserExpressionTwoDimensionsAndGradedThickness) {
  std::string dir = testing::scratch_dir("cli_expr");
  auto r = run_offsetgen(
      "generate --expr \"cos(2*Pi*x)*cos(2*Pi*y) + a*sin(2*Pi*z)\" --param a=0.3 --name mysurf "
      "--order 3 --thickness \"0.01 + 0.02*x\" -o " +
      dir + "/mysurf.h");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string h = testing::read_file(dir + "/mysurf.h");
  EXPECT_NE(h.find("static inline double mysurf_graded(double x, double y, double z)"), std::string::npos);
  auto flat = run_offsetgen("generate --expr \"x^2 + y^2 - 0.25\" --name disk --order 2 --lang all --out-dir " + dir);
  ASSERT_EQ(flat.exit_code, 0) << flat.output;
  std::string d = testing::read_file(dir + "/disk.h");
  EXPECT_NE(d.find("static inline double disk_offset(double x, double y, double h)"), std::string::npos);
  EXPECT_NE(testing::read_file(dir + "/disk.glsl").find("highp float disk_offset(highp vec2 p, highp float h)"),
            std::string::npos);
}

struct BadInput {
  const char* args;
  const char* message;
};

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsTwoWithAMessageAndTouchesNoFile) {
  // One directory per case: ctest runs the cases in parallel processes.
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  for (char& c : name) c = c == '/' ? '_' : c;
  std::string dir = testing::scratch_dir("cli_bad_" + name);
  std::string target = dir + "/out.h";
  {
    std::ofstream keep(target);
    keep << "precious";
  }
  std::string args = GetParam().args;
  if (args.find(" -o ") == std::string::npos) args += " -o " + target;
  auto r = run_offsetgen(args);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
  EXPECT_EQ(testing::read_file(target), "precious");
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1u) << "a temporary or partial file was left behind";
}

INSTANTIATE_TEST_SUITE_P(
    EveryCase, CliBadInput,
    ::testing::Values(
        BadInput{"generate --surface gyroide --order 2", "unknown surface 'gyroide'; known surfaces: gyroid, schwarzp"},
        BadInput{"generate --expr \"cos(2*x\" --name s", "cannot parse expression"},
        BadInput{"generate --expr \"3*a\" --param a=2 --name s", "does not depend on x, y or z"},
        BadInput{"generate --expr \"abs(x) + y\" --name s", "non-smooth function 'abs'"},
        BadInput{"generate --expr \"floor(x) + y\" --name s", "non-smooth function 'floor'"},
        BadInput{"generate --expr \"a*x + y\" --name s", "unknown parameter 'a'"},
        BadInput{"generate --expr \"a*x + y\" --param a= --name s", "malformed parameter"},
        BadInput{"generate --surface gyroid --order 0", "order 0 is out of range"},
        BadInput{"generate --surface gyroid --order 13",
                 "order 13 is out of range: the richardson method supports orders 1 to 12"},
        BadInput{"generate --surface gyroid --order 2 -o /nonexistent-dir/x.h", "does not exist"},
        BadInput{"generate --surface gyroid --order 2 --thickness \"0.1 + * x\"", "thickness"},
        BadInput{"generate --expr \"x + y\" --order 2", "--expr needs --name"},
        BadInput{"generate --surface gyroid --lang fortran", "fortran"},
        // Domain errors and expressions GiNaC cannot handle: exit 2, what is wrong, nothing of GiNaC.
        BadInput{"generate --expr \"log(-1-x) + y\" --name s",
                 "at (x, y) = (0.005208, 0.005208) it takes log(-1.00521), "
                 "the logarithm of a negative number"},
        BadInput{"generate --expr \"sqrt(-1)*x + y\" --name s", "is not real: it contains the complex number I"},
        BadInput{"generate --expr \"0^x + y\" --name s", "0^x: zero to a varying power"},
        BadInput{"generate --expr \"(-1)^x + y\" --name s", "(-1)^x: a negative number to a varying power is not real"},
        BadInput{"generate --expr \"x^y^z\" --name s", "write x^(y^z) or (x^y)^z at column 4"},
        BadInput{"generate --expr \"asin(x+2) + y\" --name s", "asin(2.00521), outside [-1, 1]"},
        BadInput{"generate --expr \"sqrt(x - 0.5) + y\" --name s", "the square root of a negative number"},
        BadInput{"generate --expr \"x + y + z - b\" --param b=1e400 --name s", "b=1e400 is beyond the range of double"},
        BadInput{"generate --expr \"x + 1e99999999999999999999\" --name s", "out of range"},
        BadInput{"generate --expr \" z -33333^33333333332\" --name s", "the exponent 33333333332 is too large"},
        BadInput{"generate --expr \"z - 2^(9999*9999)\" --name s", "the exponent 99980001 is too large"},
        BadInput{"generate --expr \"x/(1-1) + y\" --name s", "division by zero"},
        BadInput{"generate --expr \"tan(Pi/2) + x + y\" --name s", "meets a pole at a constant argument"},
        BadInput{"generate --expr \"atan(1e300*x) + y\" --name s", "d2F/dxdx of F is not defined everywhere"},
        BadInput{"generate --expr \"x + 1e211*y\" --name s",
                 "the gradient of F is infinite at every sample of the cell "
                 "[0, 1]^2, or so large that its square overflows"},
        BadInput{"generate --expr \"1e110*z^2 + x + y\" --name s", "an entry exceeds 1e100"},
        BadInput{"generate --expr \"1/x + y - 3\" --name s --precision float", "beyond the float range"},
        BadInput{"generate --expr \"1/x + y - 3\" --name s --lang glsl", "beyond the float range"},
        // Names: accepted functions only, by name; Pi, not pi.
        BadInput{"generate --expr \"hypot(y, x) + z\" --name s",
                 "unknown function 'hypot' at column 1; accepted: acos"},
        BadInput{"generate --expr \"atan2(y) + z\" --name s", "atan2() takes two arguments, atan2(y, x)"},
        BadInput{"generate --expr \"pi*x + y\" --name s", "unknown name 'pi' at column 1: write Pi"},
        BadInput{"generate --expr \"x + y\" --param sin=2 --name s", "parameter name 'sin' is reserved"},
        BadInput{"generate --expr \"x·y + z\" --name s",
                 "unexpected '·' (U+00B7) after a complete expression at column 2"},
        BadInput{"generate --expr \"$(printf 'x + y\\377')\" --name s", "byte 0xFF (not UTF-8)"},
        BadInput{"generate --surface gyroid --name _foo", "names beginning with _ are reserved at file scope in C"},
        BadInput{"generate --surface gyroid --name a__b", "names containing __ are reserved"},
        BadInput{"generate --surface gyroid --name gl_foo --lang glsl",
                 "names beginning with gl_ are reserved in GLSL"},
        BadInput{"generate --surface gyroid --name webgl_x --lang glsl", "reserved in WebGL"},
        BadInput{"generate --surface gyroid --name SV_x --lang hlsl", "names beginning with SV_ are HLSL system-value"},
        BadInput{"generate --surface gyroid --name cudaX --lang cuda", "in a namespace the CUDA toolkit reserves"},
        BadInput{"generate --surface gyroid --name cl_x --lang opencl", "names beginning with cl_ or CL_ are OpenCL's"},
        BadInput{"generate --surface gyroid --name x --lang c,hlsl -o -", "takes one language, not --lang c,hlsl"},
        BadInput{"generate --surface gyroid --lang c,,glsl", "empty language name"},
        // Only the requested targets' rules apply: a__b is refused by HLSL here, not by C.
        BadInput{"generate --surface gyroid --name a__b --lang glsl,hlsl", "cannot be used in GLSL"},
        BadInput{"generate --surface gyroid --lang c,wgsl2", "unknown language 'wgsl2'"},
        BadInput{"generate --surface gyroid --name offsetgen_check", "belong to the header's own helpers"},
        // A graded wall needs t > 0 everywhere, refused before any work.
        BadInput{"generate --surface gyroid --thickness ''",
                 "cannot parse thickness expression: the expression is empty"},
        BadInput{"generate --surface gyroid --thickness 0", "must be a finite wall thickness > 0"},
        BadInput{"generate --surface gyroid --thickness -0.1", "at (x, y, z) = (0.02083, 0.02083, 0.02083) it is -0.1"},
        BadInput{"generate --surface gyroid --thickness \"0.1 - 0.2*x\"", "must be a finite wall thickness > 0"}),
    [](const auto& p) { return "case" + std::to_string(p.index); });

// Error messages carry no broken bytes: a multi-byte character is printed whole, others escaped.
TEST(Cli, UnicodeInAnExpressionIsPrintedWholeInTheError) {
  for (const char* text : {"x·y + z", "x + y\xC2", "x + y\xff", "√x + y"}) {
    const std::string args = std::string("generate --name s --expr '") + text + "'";
    const auto r = run_offsetgen(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    // Valid UTF-8 throughout: every lead byte is followed by its continuation bytes.
    const std::string& m = r.output;
    for (size_t i = 0; i < m.size();) {
      const auto c = static_cast<unsigned char>(m[i]);
      const size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
      ASSERT_NE(n, 0u) << "stray byte in: " << m;
      for (size_t k = 1; k < n; ++k) ASSERT_EQ(static_cast<unsigned char>(m[i + k]) >> 6, 2u) << m;
      i += n;
    }
  }
}

TEST(Cli, FooAndFOOGetDifferentIncludeGuards) {
  const std::string dir = testing::scratch_dir("cli_guards");
  ASSERT_EQ(run_offsetgen("generate --surface gyroid --order 1 --name foo --lang all --out-dir " + dir).exit_code, 0);
  ASSERT_EQ(run_offsetgen("generate --surface gyroid --order 1 --name FOO --lang all --out-dir " + dir).exit_code, 0);
  const std::string lower = testing::read_file(dir + "/foo.h"), upper = testing::read_file(dir + "/FOO.h");
  EXPECT_NE(lower.find("#ifndef OFFSETGEN_FOO_H\n"), std::string::npos);
  EXPECT_NE(upper.find("#ifndef OFFSETGEN_FOO_h\n"), std::string::npos);
  EXPECT_NE(testing::read_file(dir + "/foo.glsl").find("#ifndef OFFSETGEN_FOO_GLSL\n"), std::string::npos);
  EXPECT_NE(testing::read_file(dir + "/FOO.glsl").find("#ifndef OFFSETGEN_FOO_glsl\n"), std::string::npos);
  // Both headers in one translation unit: each guard keeps its own functions.
  const std::string unit = dir + "/both.c";
  {
    std::ofstream out(unit);
    out << "#include \"foo.h\"\n#include \"FOO.h\"\n"
        << "double both(void) { return foo_offset(0.1, 0.2, 0.3, 0.01) + FOO_offset(0.1, 0.2, 0.3, 0.01); }\n";
  }
  EXPECT_EQ(std::system(("cc -std=c99 -pedantic -Wall -Wextra -Werror -c " + unit + " -o " + dir + "/both.o").c_str()),
            0);
}

// A clear limit against blow-ups: nesting depth is bounded, and the size of order m is estimated from
// orders 1 and 2 and refused above the limit within seconds (depth 20 at order 7 would take hours).
TEST(Cli, ExpressionBlowUpsAreRefusedQuicklyWithTheLimit) {
  auto nest = [](int depth) {
    std::string e = "x";
    for (int i = 0; i < depth; ++i) e = "sin(" + e + ")";
    return e + " + y + z";
  };
  const auto start = std::chrono::steady_clock::now();
  const auto deep = run_offsetgen("generate --name s -o - --expr '" + nest(40) + "'");
  EXPECT_EQ(deep.exit_code, 2) << deep.output;
  EXPECT_NE(deep.output.find("nests functions 40 deep; the limit is 32"), std::string::npos) << deep.output;
  const auto big = run_offsetgen("generate --name s -o - --order 7 --expr '" + nest(20) + "'");
  EXPECT_EQ(big.exit_code, 2) << big.output;
  EXPECT_NE(big.output.find("order 7 of this expression would produce about"), std::string::npos) << big.output;
  EXPECT_NE(big.output.find("Orders up to 4 stay within it."), std::string::npos) << big.output;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
}

// The estimate models Richardson's growth; the projection method's size grows linearly with the
// order, so the same expression is built at order 8 and judged on its functions.
TEST(Cli, ProjectionIsNotRefusedByRichardsonsCostEstimate) {
  std::string e = "x";
  for (int i = 0; i < 20; ++i) e = "sin(" + e + ")";
  const auto r = run_offsetgen("generate --name s -o - --method projection --order 8 --expr '" + e + " + y + z'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("static inline double s_offset("), std::string::npos);
}

TEST(Cli, HelpListsTheAcceptedFunctions) {
  const auto help = run_offsetgen("generate --help");
  EXPECT_NE(help.output.find("acos asin atan atan2 cos cosh exp log sin sinh sqrt tan tanh; the constant Pi"),
            std::string::npos)
      << help.output;
}

TEST(Cli, TopLevelHelpNamesEveryTargetAndMethodOfTheRegistries) {
  const auto help = run_offsetgen("--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const Backend* b : backends()) EXPECT_NE(help.output.find(b->title()), std::string::npos) << b->name();
  for (const OffsetMethod* m : offset_methods())
    EXPECT_NE(help.output.find(m->name() + ": " + m->description()), std::string::npos) << m->name();
}

TEST(Cli, ListRegistriesGivesEverySurfaceMethodAndTargetAsData) {
  const auto r = run_offsetgen("list --registries");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto data = nlohmann::json::parse(r.output);
  ASSERT_EQ(data["surfaces"].size(), catalog().size());
  for (size_t i = 0; i < catalog().size(); ++i) EXPECT_EQ(data["surfaces"][i]["name"], catalog()[i].name);
  ASSERT_EQ(data["methods"].size(), offset_methods().size());
  for (size_t i = 0; i < offset_methods().size(); ++i) {
    const OffsetMethod* m = offset_methods()[i];
    EXPECT_EQ(data["methods"][i]["name"], m->name());
    EXPECT_EQ(data["methods"][i]["max_order"], m->max_order());
    EXPECT_EQ(data["methods"][i]["default"], m->name() == kDefaultMethod);
    EXPECT_EQ(data["methods"][i]["orders"].back(), m->effective_order(m->max_order()));
  }
  for (const auto& m : data["methods"]) {
    if (m["name"] == "projection") {
      EXPECT_EQ(m["orders"].front(), 2) << "projection rounds order 1 up to 2";
    }
  }
  ASSERT_EQ(data["targets"].size(), backends().size());
  for (size_t i = 0; i < backends().size(); ++i) {
    EXPECT_EQ(data["targets"][i]["name"], backends()[i]->name());
    EXPECT_EQ(data["targets"][i]["extension"], backends()[i]->extension());
  }
  EXPECT_EQ(run_offsetgen("list --registries --json").exit_code, 2);
}

// CMake reads the registries from cmake/registries.json at configure time (cmake/Install.cmake): it
// must be exactly what the tool prints. To update it on purpose: tools/update_golden.sh.
TEST(Cli, RegistriesJsonIsWhatTheToolPrints) {
  const auto r = run_offsetgen("list --registries");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(fs::path(test_support::source_dir()) / "cmake" / "registries.json", std::ios::binary);
  const std::string committed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(committed == r.output)
      << "cmake/registries.json differs from `offsetgen list --registries`: run tools/update_golden.sh";
}

TEST(Cli, WritesOnlyWhenTheContentChanges) {
  std::string dir = testing::scratch_dir("cli_unchanged");
  std::string file = dir + "/g.h";
  ASSERT_EQ(run_offsetgen("generate --surface schwarzp --order 1 -o " + file).exit_code, 0);
  auto old_time = fs::last_write_time(file) - std::chrono::hours(1);
  fs::last_write_time(file, old_time);
  auto again = run_offsetgen("generate --surface schwarzp --order 1 -o " + file);
  EXPECT_NE(again.output.find("unchanged"), std::string::npos) << again.output;
  EXPECT_EQ(fs::last_write_time(file), old_time);
}

}  // namespace
}  // namespace offsetgen
