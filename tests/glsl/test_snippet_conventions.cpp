// The paste-safety lint itself: a clean snippet passes, and each rule catches its violation with
// the right line. (The generated snippets are linted in test_generated_compile.cpp.)
#include <gtest/gtest.h>

#include <string>

#include "reference_surfaces.h"
#include "run/glsl_source.h"
#include "snippet_conventions.h"

namespace {

namespace gt = offsetgen::glsl_test;

const std::string kClean =
    "/* demo.glsl: generated, do not edit */\n"                               // 1
    "#ifndef OFFSETGEN_DEMO_O1_GLSL\n"                                        // 2
    "#define OFFSETGEN_DEMO_O1_GLSL\n"                                        // 3
    "// 2 * pi, written 6.28 below; comments may say 'pow(' and '#define'\n"  // 4
    "highp float demo_o1_field(highp vec3 p)\n"                               // 5
    "{\n"                                                                     // 6
    "    highp float _t0 = 6.28318548 * p.x;\n"                               // 7
    "    highp vec3 _t1 = vec3(1.0e-3, .5, 2.0);\n"                           // 8
    "    return sin(_t0) + dot(_t1, p);\n"                                    // 9
    "}\n"                                                                     // 10
    "const highp float demo_o1_scale = 1.0;\n"                                // 11
    "#endif\n";                                                               // 12

// The violations of `rule` only.
std::vector<gt::Violation> of_rule(const std::string& snippet, const std::string& rule) {
  std::vector<gt::Violation> out;
  for (const auto& v : gt::convention_violations(snippet, "demo_o1")) {
    if (v.rule == rule) out.push_back(v);
  }
  return out;
}

// Replaces the first occurrence of `from` with `to`.
std::string with(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

void expect_one(const std::string& snippet, const std::string& rule, int line) {
  const auto v = of_rule(snippet, rule);
  ASSERT_EQ(v.size(), 1u) << gt::describe(gt::convention_violations(snippet, "demo_o1"));
  EXPECT_EQ(v[0].message.rfind("snippet line " + std::to_string(line) + ":", 0), 0u) << v[0].message;
}

TEST(SnippetConventions, CleanSnippetPasses) {
  EXPECT_EQ(gt::describe(gt::convention_violations(kClean, "demo_o1")), "");
}

TEST(SnippetConventions, AVersionLineIsRefused) {
  expect_one(with(kClean, "highp float demo_o1_field", "#version 300 es\nhighp float demo_o1_field"), "version", 5);
}

TEST(SnippetConventions, APrecisionStatementIsRefused) {
  expect_one(with(kClean, "const highp", "precision mediump float;\nconst highp"), "precision", 11);
}

TEST(SnippetConventions, AMissingIncludeGuardIsRefused) {
  const std::string s =
      with(with(kClean, "#ifndef OFFSETGEN_DEMO_O1_GLSL\n", ""), "#define OFFSETGEN_DEMO_O1_GLSL\n", "");
  EXPECT_FALSE(of_rule(s, "guard").empty());
}

TEST(SnippetConventions, GuardMustNameThePrefix) {
  const std::string s = with(with(kClean, "#ifndef OFFSETGEN_DEMO_O1_GLSL", "#ifndef SNIPPET_GLSL"),
                             "#define OFFSETGEN_DEMO_O1_GLSL", "#define SNIPPET_GLSL");
  expect_one(s, "guard", 2);
}

TEST(SnippetConventions, CodeAfterTheGuard) {
  expect_one(kClean + "highp float demo_o1_late(highp float x) { return x; }\n", "guard", 13);
}

TEST(SnippetConventions, AGlobalDefineIsRefused) {
  expect_one(with(kClean, "const highp", "#define PI 3.14159\nconst highp"), "define", 11);
}

TEST(SnippetConventions, AnyOtherDirectiveIsRefused) {
  expect_one(with(kClean, "const highp", "#extension GL_EXT_foo : enable\nconst highp"), "directive", 11);
}

TEST(SnippetConventions, AFloatDeclarationWithoutHighpIsRefused) {
  EXPECT_EQ(of_rule(with(kClean, "highp vec3 _t1", "vec3 _t1"), "highp").size(), 1u);
  EXPECT_EQ(of_rule(with(kClean, "(highp vec3 p)", "(vec3 p)"), "highp").size(), 1u);
}

TEST(SnippetConventions, PowIsRefused) { expect_one(with(kClean, "sin(_t0)", "pow(_t0, 2.0)"), "pow", 9); }

TEST(SnippetConventions, AnIntegerOrUndottedLiteralIsRefused) {
  expect_one(with(kClean, "6.28318548 * p.x", "2 * p.x"), "literal", 7);
  expect_one(with(kClean, "1.0e-3", "1e-3"), "literal", 8);
  EXPECT_TRUE(of_rule(kClean, "literal").empty());  // vec3, _t0, .5, 1.0e-3 are fine
}

TEST(SnippetConventions, UnprefixedTopLevelNames) {
  expect_one(with(kClean, "highp float demo_o1_field(", "highp float field("), "prefix", 5);
  expect_one(with(kClean, "demo_o1_scale", "scale"), "prefix", 11);
  expect_one(with(kClean, "const highp", "struct Helper { highp float a; };\nconst highp"), "prefix", 11);
  // Locals inside a body are not top-level.
  EXPECT_TRUE(of_rule(kClean, "prefix").empty());
}

TEST(SnippetConventions, AHeaderCommentThatOmitsAFunctionIsRefused) {
  const auto v = gt::header_comment_violations(kClean, "demo_o1");
  EXPECT_FALSE(v.empty());
  EXPECT_NE(gt::describe(v).find("use: does not list demo_o1_field"), std::string::npos) << gt::describe(v);
}

// The hand-made fixture was written to the same contract (its header comment is not lygia style).
TEST(SnippetConventions, FixtureFollowsTheConventions) {
  const std::string fixture = offsetgen::glsl::read_text_file(gt::fixture_dir() + "/gyroid_o1.glsl");
  EXPECT_EQ(gt::describe(gt::convention_violations(fixture, "gyroid_o1")), "");
}

}  // namespace
