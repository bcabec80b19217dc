// The CLI as a user meets it: help, version, list, exit codes, and bad input that loses nothing.
#include "test_support.h"

#include <gtest/gtest.h>

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
const std::regex kDateOrTime(R"((\b(19|20)\d\d[-/.]\d\d?[-/.]\d\d?\b)|(\b\d\d?[-/.]\d\d?[-/.](19|20)\d\d\b)|)"
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
  auto r = run_offsetgen("generate --expr \"cos(2*Pi*x)*cos(2*Pi*y) + a*sin(2*Pi*z)\" --param a=0.3 --name mysurf "
                         "--order 3 --thickness \"0.01 + 0.02*x\" -o " + dir + "/mysurf.h");
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
    ::testing::Values(BadInput{"generate --surface gyroide --order 2",
                               "unknown surface 'gyroide'; known surfaces: gyroid, schwarzp"},
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
                      BadInput{"generate --surface gyroid --lang fortran", "fortran"}),
    [](const auto& p) { return "case" + std::to_string(p.index); });

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
