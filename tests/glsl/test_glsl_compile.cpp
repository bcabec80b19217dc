// Offline compile checks (glslangValidator) of the fixture snippet in the four host dialects.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "glsl_compile.h"
#include "glsl_source.h"
#include "reference_surfaces.h"

namespace {

using offsetgen::glsl::CompileResult;
using offsetgen::glsl::Target;
namespace glsl = offsetgen::glsl;

std::string fixture() {
  return glsl::read_text_file(offsetgen::glsl_test::fixture_dir() + "/gyroid_o1.glsl");
}

// Replaces the first line containing `needle` with `replacement`; returns its 1-based number.
int replace_line(std::string& text, const std::string& needle, const std::string& replacement) {
  const auto at = text.find(needle);
  if (at == std::string::npos) return -1;
  const auto begin = text.rfind('\n', at) + 1;  // npos + 1 == 0 on the first line
  const auto end = text.find('\n', at);
  text.replace(begin, end - begin, replacement);
  int line = 1;
  for (std::size_t i = 0; i < begin; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

class CompileTarget : public ::testing::TestWithParam<Target> {};

TEST_P(CompileTarget, FixtureCompilesAndLinks) {
  const CompileResult r = glsl::compile_check(fixture(), GetParam());
  EXPECT_TRUE(r.ok) << r.message << "\n--- host shader ---\n" << r.source.text;
}

TEST_P(CompileTarget, BrokenSnippetReportsTheSnippetLine) {
  std::string broken = fixture();
  const int line =
      replace_line(broken, "return gyroid_o1_field(p) - h * length(",
                   "    return gyroid_o1_field(p) - h * lenght(gyroid_o1_gradient(p));");
  ASSERT_GT(line, 0) << "fixture changed: update the needle";
  const CompileResult r = glsl::compile_check(broken, GetParam());
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.message.find("snippet line " + std::to_string(line) + ":"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("lenght(gyroid_o1_gradient(p))"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("'lenght'"), std::string::npos) << "compiler text kept:\n" << r.message;
}

INSTANTIATE_TEST_SUITE_P(AllTargets, CompileTarget, ::testing::ValuesIn(glsl::all_targets()),
                         [](const ::testing::TestParamInfo<Target>& param_info) {
                           switch (param_info.param) {
                             case Target::Es300:
                               return std::string("Es300");
                             case Target::Gl330:
                               return std::string("Gl330");
                             case Target::Gl450:
                               return std::string("Gl450");
                             case Target::Vulkan:
                               return std::string("Vulkan");
                           }
                           return std::string("Unknown");
                         });

TEST(GlslCompile, HostCallsEveryFunctionOfTheSnippet) {
  const auto fns = glsl::scan_functions(fixture());
  ASSERT_EQ(fns.size(), 6u);
  const auto host = glsl::host_shader(fixture(), Target::Es300);
  const std::string main_body = host.text.substr(host.text.find("void main()"));
  for (const auto& f : fns) {
    EXPECT_NE(main_body.find(f.name + "("), std::string::npos) << f.name << " not called";
  }
}

TEST(GlslCompile, ErrorInHostCodeIsReportedAsHostLine) {
  // A snippet defining a function with an unsupported parameter type cannot get a host.
  const CompileResult r =
      glsl::compile_check("struct S { float a; };\nfloat f(S s) { return s.a; }\n", Target::Gl450);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("cannot generate an argument of type 'S'"), std::string::npos)
      << r.message;
}

TEST(GlslCompile, MissingValidatorNamesThePackage) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  setenv("PATH", "/nonexistent", 1);
  const CompileResult r = glsl::compile_check(fixture(), Target::Gl450);
  setenv("PATH", saved.c_str(), 1);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message,
            "glslangValidator not found: run tools/install_deps.sh (Debian package glslang-tools)");
}

TEST(GlslSource, ScanSkipsPrototypesCommentsAndBodies) {
  const std::string src =
      "#ifndef G\n#define G\n"
      "highp float a(highp vec3 p);  // prototype only\n"
      "/* highp float fake(vec3 p) { return 0.0; } */\n"
      "highp float a(highp vec3 p) { if (p.x > 0.0) { return 1.0; } return 0.0; }\n"
      "void b(in vec2 q, out float r, inout vec4 s) { r = q.x; s += 1.0; }\n"
      "#endif\n";
  const auto fns = glsl::scan_functions(src);
  ASSERT_EQ(fns.size(), 2u);
  EXPECT_EQ(fns[0].name, "a");
  EXPECT_EQ(fns[0].return_type, "float");
  ASSERT_EQ(fns[0].params.size(), 1u);
  EXPECT_EQ(fns[0].params[0].type, "vec3");
  EXPECT_EQ(fns[1].name, "b");
  ASSERT_EQ(fns[1].params.size(), 3u);
  EXPECT_EQ(fns[1].params[1].qualifier, "out");
  EXPECT_EQ(fns[1].params[2].qualifier, "inout");
  EXPECT_EQ(fns[1].params[2].type, "vec4");
  // out/inout parameters get locals, so this compiles too.
  const CompileResult r = glsl::compile_check(src, Target::Es300);
  EXPECT_TRUE(r.ok) << r.message;
}

// llvmpipe runs mediump in fp32, so only a static check can catch a float without highp.
TEST(GlslSource, FixtureHasHighpOnEveryFloat) {
  EXPECT_EQ(glsl::declarations_without_highp(fixture()), std::vector<std::string>{});
}

TEST(GlslSource, MissingHighpIsReportedWithItsLine) {
  const std::string src =
      "highp float f(highp vec3 p) {\n"
      "  vec3 u = 2.0 * p;            // local without highp\n"
      "  highp float s = dot(u, vec3(1.0));  // constructor: fine\n"
      "  return s;\n"
      "}\n"
      "float g(in highp float x, mediump float y) { return x + y; }\n";
  EXPECT_EQ(glsl::declarations_without_highp(src),
            (std::vector<std::string>{
                "snippet line 2:   vec3 u = 2.0 * p;            // local without highp",
                "snippet line 6: float g(in highp float x, mediump float y) { return x + y; }"}));
}

TEST(GlslSource, AssembleKeepsSnippetBytesAndMapsLines) {
  const std::string snippet = "line1\nline2";  // no final newline: one is added after it
  const auto s = glsl::assemble("#version 450\n", snippet, "tail\n");
  EXPECT_EQ(s.text, "#version 450\nline1\nline2\ntail\n");
  EXPECT_EQ(s.snippet_first_line, 2);
  EXPECT_EQ(s.describe_line(3), "snippet line 2: line2");
  EXPECT_EQ(s.describe_line(4), "host line 4: tail");
  EXPECT_EQ(glsl::referenced_lines("ERROR: /tmp/a b.frag:7: 'x' : y\n0:9(3): error: z\n"),
            (std::vector<int>{7, 9}));
}

}  // namespace
