// Every snippet the real generator writes (all catalog surfaces, orders 1-4, plus the graded one)
// and every committed golden snippet (generated/*.glsl): compiled and linked with
// glslangValidator -l in the four host dialects, and linted for the paste-safety conventions.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "generated_cases.h"
#include "glsl_compile.h"
#include "glsl_source.h"
#include "snippet_conventions.h"

namespace {

namespace fs = std::filesystem;
namespace glsl = offsetgen::glsl;
namespace gt = offsetgen::glsl_test;
using glsl::Target;

std::string target_label(Target t) {
  switch (t) {
    case Target::Es300:
      return "Es300";
    case Target::Gl330:
      return "Gl330";
    case Target::Gl450:
      return "Gl450";
    case Target::Vulkan:
      return "Vulkan";
  }
  return "Unknown";
}

using CompileCase = std::tuple<gt::SnippetFile, Target>;
class SnippetCompiles : public ::testing::TestWithParam<CompileCase> {};

TEST_P(SnippetCompiles, AndLinks) {
  const auto& [file, target] = GetParam();
  const std::string snippet = glsl::read_text_file(file.path);
  const glsl::CompileResult r = glsl::compile_check(snippet, target);
  EXPECT_TRUE(r.ok) << file.path << " fails on " << glsl::target_name(target) << ":\n"
                    << r.message;
}

INSTANTIATE_TEST_SUITE_P(All, SnippetCompiles,
                         ::testing::Combine(::testing::ValuesIn(gt::all_snippet_files()),
                                            ::testing::ValuesIn(glsl::all_targets())),
                         [](const ::testing::TestParamInfo<CompileCase>& p) {
                           return std::get<0>(p.param).label + "_" +
                                  target_label(std::get<1>(p.param));
                         });

class SnippetConventions : public ::testing::TestWithParam<gt::SnippetFile> {
 protected:
  std::string snippet_ = glsl::read_text_file(GetParam().path);
  std::string prefix_ = gt::snippet_prefix(snippet_, fs::path(GetParam().path).stem().string());
};

TEST_P(SnippetConventions, PasteSafe) {
  EXPECT_EQ(gt::describe(gt::convention_violations(snippet_, prefix_)), "") << GetParam().path;
}

TEST_P(SnippetConventions, LygiaStyleHeaderComment) {
  EXPECT_EQ(gt::describe(gt::header_comment_violations(snippet_, prefix_)), "")
      << GetParam().path;
}

// The functions the issue promises, with the promised signatures.
TEST_P(SnippetConventions, DefinesTheDocumentedFunctions) {
  const auto fns = glsl::scan_functions(snippet_);
  auto find = [&](const std::string& name) -> const glsl::GlslFunction* {
    for (const auto& f : fns) {
      if (f.name == prefix_ + "_" + name) return &f;
    }
    return nullptr;
  };
  const std::string vec = snippet_.find("\"dims\":2") != std::string::npos ? "vec2" : "vec3";
  const std::vector<std::tuple<std::string, std::string, std::vector<std::string>>> expected = {
      {"field", "float", {vec}},
      {"offset", "float", {vec, "float"}},
      {"shell", "float", {vec, "float"}},
      {"normal", vec, {vec, "float"}},
  };
  for (const auto& [name, ret, params] : expected) {
    const glsl::GlslFunction* f = find(name);
    ASSERT_NE(f, nullptr) << prefix_ << "_" << name << " missing in " << GetParam().path;
    EXPECT_EQ(f->return_type, ret) << f->name;
    std::vector<std::string> types;
    for (const auto& p : f->params) types.push_back(p.type);
    EXPECT_EQ(types, params) << f->name;
  }
}

INSTANTIATE_TEST_SUITE_P(All, SnippetConventions, ::testing::ValuesIn(gt::all_snippet_files()),
                         [](const ::testing::TestParamInfo<gt::SnippetFile>& p) {
                           return p.param.label;
                         });

// A compile error in a real generated snippet is reported with glslang's text and the snippet
// line it points at.
TEST(GeneratedSnippet, CompileErrorShowsTheSnippetLine) {
  const gt::GeneratedCase& c = gt::generated_cases().back();  // an order-4 snippet
  std::string snippet = glsl::read_text_file(c.snippet);
  const std::string needle = std::string(c.prefix) + "_field(highp vec3 p)\n{\n";
  const auto at = snippet.find(needle);
  ASSERT_NE(at, std::string::npos) << c.snippet;
  const auto body = at + needle.size();
  const auto eol = snippet.find('\n', body);
  const std::string broken_line = "    highp float _broken = undefined_symbol;";
  snippet.replace(body, eol - body, broken_line);
  int line = 1;
  for (std::size_t i = 0; i < body; ++i) line += snippet[i] == '\n' ? 1 : 0;
  for (Target t : glsl::all_targets()) {
    const glsl::CompileResult r = glsl::compile_check(snippet, t);
    ASSERT_FALSE(r.ok) << glsl::target_name(t);
    EXPECT_NE(r.message.find("undefined_symbol"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("snippet line " + std::to_string(line) + ": " + broken_line),
              std::string::npos)
        << r.message;
  }
}

std::string run_capture(const std::string& command, int& status) {
  std::string out;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return out;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) out.append(buf.data(), n);
  const int st = pclose(pipe);
  status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return out;
}

// The build generates every surface the catalog has: a new catalog entry must be added to
// OFFSETGEN_GLSL_SURFACES in tests/glsl/CMakeLists.txt.
TEST(GeneratedCatalog, MatchesOffsetgenList) {
  int status = -1;
  const std::string out = run_capture("'" + gt::offsetgen_executable() + "' list", status);
  ASSERT_EQ(status, 0) << out;
  std::set<std::string> listed;
  static const std::regex kEntry(R"(^([a-z][a-z0-9_]*)\s{2,}\S)");
  std::istringstream in(out);
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_search(l, m, kEntry)) listed.insert(m[1].str());
  }
  const auto tested = gt::catalog_surfaces_under_test();
  EXPECT_EQ(std::set<std::string>(tested.begin(), tested.end()), listed) << out;
  // Four orders of every surface for each method (tests/glsl/CMakeLists.txt OFFSETGEN_GLSL_METHODS).
  std::map<std::string, std::set<std::string>> surfaces_by_method;
  std::map<std::string, std::size_t> cases_by_method;
  for (const gt::GeneratedCase& c : gt::generated_cases()) {
    surfaces_by_method[c.method].insert(c.surface);
    ++cases_by_method[c.method];
  }
  for (const char* method : {"richardson", "projection"}) {
    EXPECT_EQ(surfaces_by_method[method], listed) << method;
    EXPECT_EQ(cases_by_method[method], 4 * tested.size()) << method;
  }
  EXPECT_EQ(gt::generated_cases().size(), 8 * tested.size());
}

// Every golden header in generated/ has its .glsl twin (issue 3: "all of generated/ gets .glsl
// twins"), so the compile and lint tests above cover all of them.
TEST(GoldenFolder, EveryHeaderHasAGlslTwin) {
  std::size_t headers = 0;
  for (const auto& e : fs::directory_iterator(OFFSETGEN_GOLDEN_DIR)) {
    if (e.path().extension() != ".h") continue;
    ++headers;
    fs::path twin = e.path();
    twin.replace_extension(".glsl");
    EXPECT_TRUE(fs::exists(twin)) << e.path() << " has no .glsl twin";
  }
  const auto golden = gt::golden_snippet_paths();
  EXPECT_GE(golden.size(), headers) << "reconfigure: the golden list is taken at configure time";
}

}  // namespace
