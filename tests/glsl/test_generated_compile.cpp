// Every snippet the real generator writes (all catalog surfaces, orders 1-4, the graded one and two
// --expr ones): compiled and linked in the four host dialects with `offsetgen check`'s glslang
// stage (run::compile_glsl), and linted for the paste-safety conventions. The committed golden
// snippets are the build-time ones, byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "generated_cases.h"
#include "offsetgen_test_support.h"
#include "run/glsl_compile.h"
#include "run/glsl_source.h"
#include "run/metadata.h"
#include "snippet_conventions.h"

namespace {

namespace fs = std::filesystem;
namespace run = offsetgen::run;
namespace glsl = offsetgen::glsl;
namespace gt = offsetgen::glsl_test;
namespace ts = offsetgen::test_support;

run::FileMetadata metadata_of(const std::string& snippet) { return run::parse_metadata(snippet); }

class SnippetCompiles : public ::testing::TestWithParam<gt::SnippetFile> {};

TEST_P(SnippetCompiles, AndLinksInTheFourHostDialects) {
  const std::string snippet = glsl::read_text_file(GetParam().path);
  const auto results = run::compile_glsl(snippet, metadata_of(snippet), fs::path(GetParam().path).filename().string());
  ASSERT_EQ(results.size(), 4u);
  for (const auto& r : results) EXPECT_TRUE(r.ok) << GetParam().path << " fails on " << r.name << ":\n" << r.output;
}

INSTANTIATE_TEST_SUITE_P(All, SnippetCompiles, ::testing::ValuesIn(gt::all_snippet_files()),
                         [](const ::testing::TestParamInfo<gt::SnippetFile>& p) { return p.param.label; });

// Snippets of different surfaces and methods pasted into one shader, one of them twice: each brings
// its own <prefix>_sin/_cos, and nothing they declare may clash.
TEST(SnippetsOfDifferentSurfaces, CompileTogetherInOneShader) {
  std::map<std::string, std::string> by_prefix;
  for (const auto& c : gt::generated_cases()) by_prefix[c.prefix] = c.snippet;
  std::string together;
  for (const char* prefix : {"gyroid_o4", "schwarzp_o2", "neovius_proj_o4", "gyroid_o4"})
    together += glsl::read_text_file(by_prefix.at(prefix)) + "\n";
  // The host calls the first snippet's functions (one metadata block: check refuses pasted files).
  const auto results =
      run::compile_glsl(together, metadata_of(glsl::read_text_file(by_prefix.at("gyroid_o4"))), "together.glsl");
  ASSERT_EQ(results.size(), 4u);
  for (const auto& r : results) EXPECT_TRUE(r.ok) << "fails on " << r.name << ":\n" << r.output;
}

class SnippetConventions : public ::testing::TestWithParam<gt::SnippetFile> {
 protected:
  std::string snippet_ = glsl::read_text_file(GetParam().path);
  run::FileMetadata meta_ = metadata_of(snippet_);
};

TEST_P(SnippetConventions, EveryGeneratedSnippetIsPasteSafe) {
  EXPECT_EQ(gt::describe(gt::convention_violations(snippet_, meta_.prefix)), "") << GetParam().path;
}

TEST_P(SnippetConventions, LygiaStyleHeaderComment) {
  EXPECT_EQ(gt::describe(gt::header_comment_violations(snippet_, meta_.prefix)), "") << GetParam().path;
}

// The functions the issue promises, with the promised signatures.
TEST_P(SnippetConventions, DefinesTheDocumentedFunctions) {
  const auto fns = glsl::scan_functions(snippet_);
  auto find = [&](const std::string& name) -> const glsl::GlslFunction* {
    for (const auto& f : fns) {
      if (f.name == meta_.prefix + "_" + name) return &f;
    }
    return nullptr;
  };
  const std::string vec = meta_.dims == 2 ? "vec2" : "vec3";
  const std::vector<std::tuple<std::string, std::string, std::vector<std::string>>> expected = {
      {"field", "float", {vec}},
      {"offset", "float", {vec, "float"}},
      {"shell", "float", {vec, "float"}},
      {"normal", vec, {vec, "float"}},
  };
  for (const auto& [name, ret, params] : expected) {
    const glsl::GlslFunction* f = find(name);
    ASSERT_NE(f, nullptr) << meta_.prefix << "_" << name << " missing in " << GetParam().path;
    EXPECT_EQ(f->return_type, ret) << f->name;
    std::vector<std::string> types;
    for (const auto& p : f->params) types.push_back(p.type);
    EXPECT_EQ(types, params) << f->name;
  }
}

INSTANTIATE_TEST_SUITE_P(All, SnippetConventions, ::testing::ValuesIn(gt::all_snippet_files()),
                         [](const ::testing::TestParamInfo<gt::SnippetFile>& p) { return p.param.label; });

// A compile error in a real generated snippet is reported with glslang's text and the snippet
// line it points at, on every target.
TEST(GeneratedSnippet, CompileErrorShowsTheSnippetLine) {
  const gt::GeneratedCase& c = gt::generated_cases().back();  // an order-4 snippet
  std::string snippet = glsl::read_text_file(c.snippet);
  const std::string needle = std::string(c.prefix) + "_field(highp vec3 p)\n{\n";
  const auto at = snippet.find(needle);
  ASSERT_NE(at, std::string::npos) << c.snippet;
  const auto body = at + needle.size();
  const auto eol = snippet.find('\n', body);
  snippet.replace(body, eol - body, "    highp float _broken = undefined_symbol;");
  int line = 1;
  for (std::size_t i = 0; i < body; ++i) line += snippet[i] == '\n' ? 1 : 0;
  const std::string name = std::string(c.prefix) + ".glsl";
  for (const auto& r : run::compile_glsl(snippet, metadata_of(snippet), name)) {
    ASSERT_FALSE(r.ok) << r.name;
    EXPECT_NE(r.output.find("undefined_symbol"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("[" + name + " line " + std::to_string(line) + "]"), std::string::npos) << r.output;
  }
}

// The build generates every surface the catalog has: a new catalog entry must be added to
// OFFSETGEN_GLSL_SURFACES in tests/glsl/CMakeLists.txt.
TEST(GeneratedCatalog, MatchesOffsetgenList) {
  const ts::CommandResult r = ts::run_offsetgen(std::vector<std::string>{"list"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::set<std::string> listed;
  static const std::regex kEntry(R"(^([a-z][a-z0-9_]*)\s{2,}\S)");
  std::istringstream in(r.output);
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_search(l, m, kEntry)) listed.insert(m[1].str());
  }
  const auto tested = gt::catalog_surfaces_under_test();
  EXPECT_EQ(std::set<std::string>(tested.begin(), tested.end()), listed) << r.output;
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
// twins"), and every golden snippet is, byte for byte, the snippet this build generated for the
// same surface and order, so the compile, lint and execution tests above cover all of them.
TEST(GoldenSnippets, AreTheBuildTimeSnippets) {
  std::size_t headers = 0;
  for (const auto& e : fs::directory_iterator(ts::source_dir() + "/generated")) {
    if (e.path().extension() != ".h") continue;
    ++headers;
    fs::path twin = e.path();
    twin.replace_extension(".glsl");
    EXPECT_TRUE(fs::exists(twin)) << e.path() << " has no .glsl twin";
  }
  const auto golden = gt::golden_snippet_paths();
  EXPECT_EQ(golden.size(), headers) << "reconfigure: the golden list is taken at configure time";
  for (const std::string& path : golden) {
    const std::string prefix = fs::path(path).stem().string();
    const gt::GeneratedCase* match = nullptr;
    for (const auto& c : gt::generated_cases())
      if (prefix == c.prefix) match = &c;
    ASSERT_NE(match, nullptr) << path << ": no build-time snippet " << prefix;
    EXPECT_TRUE(glsl::read_text_file(path) == glsl::read_text_file(match->snippet))
        << path << " differs from " << match->snippet;
  }
}

}  // namespace
