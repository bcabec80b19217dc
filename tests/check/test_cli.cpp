// `offsetgen check` as a user runs it: exit codes 0 (all pass), 1 (a check failed), 2 (usage or
// input error), the table, --json and --plot.
#include "check_test_support.h"
#include "emit/backend.h"
#include "run/process.h"
#include "run/runner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>

namespace offsetgen::check {
namespace {

const std::vector<std::string> kQuick = {"--h", "0.005,0.01,0.02", "--grid", "6", "--scan", "60", "--points", "10"};

std::vector<std::string> args(std::vector<std::string> a, bool quick = true) {
  if (quick) a.insert(a.end(), kQuick.begin(), kQuick.end());
  return a;
}

class CheckCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::scratch_dir("cli"));
    header_ = new std::string(testing::write_header(*dir_, "gyroid", 2, "0.01*x"));
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete header_;
  }
  static std::string* dir_;
  static std::string* header_;
};
std::string* CheckCli::dir_ = nullptr;
std::string* CheckCli::header_ = nullptr;

TEST_F(CheckCli, AGoodHeaderPassesWithExit0AndEveryNumberInJson) {
  const std::string json = *dir_ + "/out.json";
  auto r = testing::run_offsetgen(args({"check", *header_, "--json", json}));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* text : {"1. Compile", "C99 strict", "2. Values", "3. Wall thickness", "4. Graded wall",
                           "fitted order", "one-sided", "all checks passed"})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
  nlohmann::json j = nlohmann::json::parse(testing::read_text(json));
  EXPECT_EQ(j["pass"], true);
  EXPECT_EQ(j["metadata"]["order"], 2);
  EXPECT_LT(j["values"]["max_shift_double"].get<double>(), 1e-12);
  ASSERT_EQ(j["thickness"]["rows"].size(), 3u);
  EXPECT_EQ(j["thickness"]["rows"][1]["h"], 0.01);
  EXPECT_GT(j["thickness"]["rows"][1]["f_to_phi"]["mean_relative_error"].get<double>(), 0);
  EXPECT_TRUE(j["thickness"]["fits"]["f_to_phi"]["fitted"].get<bool>());
  EXPECT_EQ(j["graded"]["rows"].back()["as_given"], true);
  EXPECT_TRUE(j["graded"]["definitions"].contains("one_sided"));
}

TEST_F(CheckCli, ProgressIsNotWrittenWhenStderrIsNotATerminal) {
  auto r = testing::run_offsetgen(args({"check", *header_, "--no-values"}));
  EXPECT_EQ(r.output.find("[offsetgen check]"), std::string::npos);
  EXPECT_EQ(r.output.find('\r'), std::string::npos);
}

TEST_F(CheckCli, APlotIsWrittenWithThePlotScript) {
  if (run::find_on_path("/usr/bin/python3").empty()) GTEST_SKIP() << "no /usr/bin/python3";
  if (run::run_process({"/usr/bin/python3", "-c", "import matplotlib"}).exit_code != 0) GTEST_SKIP() << "no matplotlib";
  const std::string png = *dir_ + "/plot.png";
  auto r = testing::run_offsetgen(args({"check", *header_, "--no-values", "--plot", png}));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  // A new picture gets the mode of any new file, 0666 less the umask (not mkstemp's 0600).
  const mode_t umask_now = ::umask(0);
  ::umask(umask_now);
  struct stat st {};
  ASSERT_EQ(::stat(png.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0666u & ~umask_now);
  auto bad = testing::run_offsetgen(args({"check", *header_, "--plot", png, "--plot-script", "/nonexistent.py"}));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

TEST_F(CheckCli, ACompileErrorExits1WithTheCompilerOutput) {
  std::string text = testing::read_text(*header_);
  const auto body = text.find("{", text.find("static inline double gyroid_o2_shell"));
  text.insert(body + 1, "\n    return undeclared_identifier;");
  const std::string broken = *dir_ + "/broken.h";
  testing::write_text(broken, text);
  auto r = testing::run_offsetgen(args({"check", broken}));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("undeclared_identifier"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("broken.h:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAILED"), std::string::npos) << r.output;
}

TEST(CheckHelp, NamesEveryTargetOfTheRunnerRegistryWithItsExtension) {
  auto r = testing::run_offsetgen(args({"check", "--help"}));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  ASSERT_FALSE(run::runners().empty());
  for (const run::Runner* runner : run::runners()) {
    const std::string line = runner->backend() + " (." + backend(runner->backend()).extension() + "): " + runner->how();
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
  }
}

TEST_F(CheckCli, NumbersOutOfBoundExit1) {
  auto r = testing::run_offsetgen(args({"check", *header_, "--no-thickness", "--tolerance", "1e-30"}));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("FAIL   values"), std::string::npos) << r.output;
}

TEST_F(CheckCli, InputErrorsExit2WithAMessage) {
  const std::string plain = *dir_ + "/plain.h";
  testing::write_text(plain, "#include <math.h>\nstatic double f(double x) { return x; }\n");
  std::string text = testing::read_text(*header_);
  text.replace(text.find("\"order\":2"), 9, "\"order\":\"two\"");
  const std::string damaged = *dir_ + "/damaged.h";
  testing::write_text(damaged, text);
  struct Case {
    std::vector<std::string> argv;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"check", plain}, "not produced by offsetgen"},
      {{"check", damaged}, "damaged"},
      {{"check", *dir_ + "/missing.h"}, "cannot read"},
      {{"check", *header_, "--thickness", "0.1*x+*2"}, "column 7"},
      {{"check", *header_, "--thickness", ""}, "the expression is empty"},
      {{"check", *header_, "--thickness", "0"}, "must be a finite wall thickness > 0"},
      {{"check", *header_, "--thickness", "-0.1"}, "must be a finite wall thickness > 0"},
      {{"check", *header_, "--h", "0.01,abc"}, "'abc' is not a number"},
      {{"check", *header_, "--h", "-0.01"}, "outside (0, 0.5]"},
      {{"check"}, "file is required"},
  };
  for (const auto& c : cases) {
    auto r = testing::run_offsetgen(c.argv);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << "expected '" << c.says << "' in: " << r.output;
  }
}

TEST_F(CheckCli, ADirectoryGetsAClearMessage) {
  auto r = testing::run_offsetgen({"check", *dir_});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is a directory; give one file written by `offsetgen generate`"), std::string::npos)
      << r.output;
}

// --json and --plot are checked before the run (compiling and measuring take seconds to minutes).
TEST_F(CheckCli, AnUnwritableJsonIsRefusedBeforeTheRun) {
  for (const std::string& json : {*dir_ + "/missing-dir/out.json", std::string("/dev/null"), *dir_}) {
    auto r = testing::run_offsetgen(args({"check", *header_, "--json", json}));
    EXPECT_EQ(r.exit_code, 2) << json << ": " << r.output;
    EXPECT_NE(r.output.find("--json: cannot write"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("1. Compile"), std::string::npos) << "the run started: " << r.output;
  }
  auto same = testing::run_offsetgen(args({"check", *header_, "--json", *dir_ + "/x", "--plot", *dir_ + "/./x"}));
  EXPECT_EQ(same.exit_code, 2) << same.output;
  EXPECT_NE(same.output.find("same file"), std::string::npos) << same.output;
}

// The file's kind is in its metadata: a header named .glsl is compiled as C, a snippet named .h is
// run as GLSL.
TEST_F(CheckCli, TheKindComesFromTheMetadataNotTheExtension) {
  const std::string header_named_glsl = *dir_ + "/header.glsl";
  testing::write_text(header_named_glsl, testing::read_text(*header_));
  auto c = testing::run_offsetgen({"check", header_named_glsl, "--no-values", "--no-thickness"});
  EXPECT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("1. Compile"), std::string::npos) << c.output;
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed";
  const std::string snippet_named_h = *dir_ + "/snippet.h";
  testing::write_text(snippet_named_h, testing::read_text(testing::write_header(*dir_, "gyroid", 1, "", true)));
  auto g = testing::run_offsetgen({"check", snippet_named_h, "--no-values"});
  EXPECT_EQ(g.exit_code, 0) << g.output;
  EXPECT_NE(g.output.find("GLSL compile"), std::string::npos) << g.output;
}

// Where two branches of the zero set cross (cos(2 pi x) + cos(2 pi y) = 0 at (0.5, 0), ...) no offset
// exists; rays from there are skipped as singular and counted in the report, not failed.
TEST_F(CheckCli, ATwoDimensionalSurfaceWithCrossingsPasses) {
  const std::string dir = *dir_ + "/wave";
  std::filesystem::create_directories(dir);
  auto gen = testing::run_offsetgen({"generate", "--expr", "cos(2*Pi*x)+cos(2*Pi*y)", "--name", "wave2", "--order", "3",
                                     "--out-dir", dir, "--quiet"});
  ASSERT_EQ(gen.exit_code, 0) << gen.output;
  const std::string json = dir + "/wave2.json";
  auto r = testing::run_offsetgen({"check", dir + "/wave2.h", "--json", json});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("singular samples skipped"), std::string::npos) << r.output;
  nlohmann::json j = nlohmann::json::parse(testing::read_text(json));
  EXPECT_EQ(j["thickness"]["singular_on_f"], 4);  // (0, 0.5), (0.5, 0), (0.5, 1), (1, 0.5)
}

// Nothing to compile with: the header is not judged (exit 4, "not checked"), rather than failed.
TEST_F(CheckCli, NoCompilerOnPathIsNotCheckedExit4) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  const char* old_cc = std::getenv("CC");
  const std::string saved_cc = old_cc ? old_cc : "";
  ::setenv("PATH", "/nonexistent-offsetgen-test", 1);
  ::unsetenv("CC");
  auto r = testing::run_offsetgen(args({"check", *header_}));
  ::setenv("PATH", saved.c_str(), 1);
  if (old_cc) ::setenv("CC", saved_cc.c_str(), 1);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("offsetgen check: not checked: no C compiler on PATH"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("FAIL"), std::string::npos) << r.output;
}

TEST_F(CheckCli, GlslFilesAreCompiledForFourTargets) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed";
  const std::string glsl = testing::write_header(*dir_, "schwarzp", 3, "", true);
  auto r = testing::run_offsetgen({"check", glsl});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* t : {"GLSL ES 3.00", "GLSL 3.30", "GLSL 4.50", "Vulkan"})
    EXPECT_NE(r.output.find(t), std::string::npos);
  std::string text = testing::read_text(glsl);
  text.insert(text.find("{\n", text.find("schwarzp_o3_field(")) + 2, "    oops;\n");
  testing::write_text(*dir_ + "/bad.glsl", text);
  auto bad = testing::run_offsetgen({"check", *dir_ + "/bad.glsl"});
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
}

// A snippet's names are checked against GLSL's rules only: offsetgen_* is reserved in C (the header's helpers), not in
// GLSL.
TEST_F(CheckCli, ASnippetWithANameOnlyCReservesIsChecked) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed";
  const std::string dir = *dir_ + "/underscore";
  std::filesystem::create_directories(dir);
  auto gen = testing::run_offsetgen({"generate", "--surface", "gyroid", "--order", "1", "--lang", "glsl", "--name",
                                     "offsetgen_g1", "--out-dir", dir, "-q"});
  ASSERT_EQ(gen.exit_code, 0) << gen.output;
  auto r = testing::run_offsetgen({"check", dir + "/offsetgen_g1.glsl", "--points", "20"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// The snippet runs on Mesa llvmpipe and each function is judged against the 40-digit reference:
// a wrong constant that still compiles fails (before, GLSL was compiled only).
TEST_F(CheckCli, AGlslSnippetWithAWrongConstantFailsOnLlvmpipe) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed";
  const std::string glsl = testing::write_header(*dir_, "gyroid", 2, "", true);
  auto good = testing::run_offsetgen({"check", glsl, "--points", "40"});
  EXPECT_EQ(good.exit_code, 0) << good.output;
  for (const char* row : {"glsl field", "glsl offset", "glsl shell", "glsl normal"})
    EXPECT_NE(good.output.find(row), std::string::npos) << row << "\n" << good.output;
  std::string text = testing::read_text(glsl);
  const auto at = text.find("6.28318548", text.find("highp float gyroid_o2_offset("));
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 10, "6.38318548");
  testing::write_text(*dir_ + "/wrong.glsl", text);
  auto wrong = testing::run_offsetgen({"check", *dir_ + "/wrong.glsl", "--points", "40"});
  EXPECT_EQ(wrong.exit_code, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("out of tolerance: glsl offset"), std::string::npos) << wrong.output;
}

// A shader of `lang` for the gyroid at order 2, written by the CLI as users get it; and the same
// file with 2 pi misprinted (6.28318548 -> 6.38318548) in the first line of _offset only, so it still
// compiles.
struct ShaderPair {
  std::string good, wrong;
};

ShaderPair shader_pair(const std::string& dir, const std::string& lang) {
  const std::string good = dir + "/gyroid_o2." + lang;
  auto generated = testing::run_offsetgen({"generate", "-s", "gyroid", "--order", "2", "--lang", lang, "-o", good});
  EXPECT_EQ(generated.exit_code, 0) << generated.output;
  std::string text = testing::read_text(good);
  const auto function =
      text.find(lang == "hlsl" ? "\nfloat gyroid_o2_offset(" : "\nfn gyroid_o2_offset(");  // the definition
  const auto at = text.find("6.28318548", function);
  EXPECT_NE(function, std::string::npos);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, 10, "6.38318548");
  const std::string wrong = dir + "/wrong_gyroid_o2." + lang;
  testing::write_text(wrong, text);
  return {good, wrong};
}

// The snippet becomes SPIR-V (glslang's HLSL front end) and runs on lavapipe: its values are judged
// against the 40-digit reference, so a wrong constant that still compiles fails.
TEST_F(CheckCli, AnHlslSnippetRunsOnLavapipeAndAWrongConstantFails) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed";
  const ShaderPair hlsl = shader_pair(*dir_, "hlsl");
  auto good = testing::run_offsetgen({"check", hlsl.good, "--points", "40"});
  EXPECT_EQ(good.exit_code, 0) << good.output;
  for (const char* row : {"hlsl field", "hlsl offset", "hlsl shell", "hlsl normal", "PASS   values on lavapipe"})
    EXPECT_NE(good.output.find(row), std::string::npos) << row << "\n" << good.output;
  auto wrong = testing::run_offsetgen({"check", hlsl.wrong, "--points", "40"});
  EXPECT_EQ(wrong.exit_code, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("FAIL   values on lavapipe         out of tolerance: hlsl offset"), std::string::npos)
      << wrong.output;
}

// The snippet runs on Dawn (OFFSETGEN_WEBGPU: the webgpu package the wgsl tests install); a wrong
// constant fails its value check.
TEST_F(CheckCli, AWgslSnippetRunsOnDawnAndAWrongConstantFails) {
  if (run::find_on_path("node").empty()) GTEST_SKIP() << "node not installed";
  ::setenv("OFFSETGEN_WEBGPU", OFFSETGEN_WEBGPU_DIR, 1);
  const ShaderPair wgsl = shader_pair(*dir_, "wgsl");
  auto good = testing::run_offsetgen({"check", wgsl.good, "--points", "40"});
  EXPECT_EQ(good.exit_code, 0) << good.output;
  for (const char* row : {"wgsl field", "wgsl offset", "wgsl shell", "wgsl normal", "PASS   values on Dawn"})
    EXPECT_NE(good.output.find(row), std::string::npos) << row << "\n" << good.output;
  auto wrong = testing::run_offsetgen({"check", wgsl.wrong, "--points", "40"});
  EXPECT_EQ(wrong.exit_code, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("FAIL   values on Dawn             out of tolerance: wgsl offset"), std::string::npos)
      << wrong.output;
}

// Without Dawn's bindings the snippet is not judged: "not checked" naming what to install (exit 4),
// not FAILED.
TEST_F(CheckCli, AWgslSnippetWithoutDawnIsNotCheckedNamingIt) {
  if (run::find_on_path("node").empty()) GTEST_SKIP() << "node not installed";
  const ShaderPair wgsl = shader_pair(*dir_, "wgsl");
  ::setenv("OFFSETGEN_WEBGPU", (*dir_ + "/no-webgpu-here").c_str(), 1);
  auto r = testing::run_offsetgen({"check", wgsl.good, "--points", "10"});
  ::setenv("OFFSETGEN_WEBGPU", OFFSETGEN_WEBGPU_DIR, 1);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("offsetgen check: not checked: $OFFSETGEN_WEBGPU is"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no-webgpu-here"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("FAIL"), std::string::npos) << r.output;
}

// Without $OFFSETGEN_WEBGPU, check finds the bindings tools/install_deps.sh installed (in the source
// tree offsetgen was built from) and runs the snippet.
TEST_F(CheckCli, AWgslSnippetFindsTheInstalledDawnWithoutAnEnvironmentVariable) {
  if (run::find_on_path("node").empty()) GTEST_SKIP() << "node not installed";
  const ShaderPair wgsl = shader_pair(*dir_, "wgsl");
  ::unsetenv("OFFSETGEN_WEBGPU");
  auto r = testing::run_offsetgen({"check", wgsl.good, "--points", "10"});
  ::setenv("OFFSETGEN_WEBGPU", OFFSETGEN_WEBGPU_DIR, 1);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("PASS   values on Dawn"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace offsetgen::check

namespace offsetgen::check {
namespace {

// A mapped file (--map) is checked in a cube inside its domain, in physical units: its walls converge
// at the method's order there, and a misprinted 2 pi / 5 (the radial cells' wave number) fails.
TEST(CheckMapped, AMappedHeaderIsMeasuredInItsDomainAndAMisprintFails) {
  const std::string dir = testing::scratch_dir("check-mapped");
  const std::string header = dir + "/tube.h";
  auto g = testing::run_offsetgen({"generate", "--surface", "gyroid", "--map", "cylindrical:12,5,5", "--domain",
                                   "10,-5,0:20,5,10", "--order", "4", "-o", header});
  ASSERT_EQ(g.exit_code, 0) << g.output;
  auto r = testing::run_offsetgen({"check", header});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("order shell"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("all checks passed"), std::string::npos) << r.output;
  // 2 pi / 5 -> 2.0025 pi / 5, the first occurrence in _offset's body only.
  std::string text = testing::read_text(header);
  const size_t body = text.find("gyroid_cylindrical_o4_offset(double");
  ASSERT_NE(body, std::string::npos);
  const size_t at = text.find("1.2566370614359172", body);
  ASSERT_NE(at, std::string::npos) << "no 2 pi / 5 in _offset";
  text.replace(at, 18, "1.2582078577627121");
  const std::string bad = dir + "/bad.h";
  std::ofstream(bad) << text;
  r = testing::run_offsetgen({"check", bad});
  EXPECT_EQ(r.exit_code, 1) << r.output;
}

}  // namespace
}  // namespace offsetgen::check
