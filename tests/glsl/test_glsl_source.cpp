// src/run/glsl_source: scanning a snippet's functions, the highp lint, and host-shader
// assembly with its line mapping (what the executor and render_shell build on).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reference_surfaces.h"
#include "run/glsl_source.h"

namespace {

namespace glsl = offsetgen::glsl;

std::string fixture() { return glsl::read_text_file(offsetgen::glsl_test::fixture_dir() + "/gyroid_o1.glsl"); }

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
            (std::vector<std::string>{"snippet line 2:   vec3 u = 2.0 * p;            // local without highp",
                                      "snippet line 6: float g(in highp float x, mediump float y) { return x + y; }"}));
}

TEST(GlslSource, AssembleKeepsSnippetBytesAndMapsLines) {
  const std::string snippet = "line1\nline2";  // no final newline: one is added after it
  const auto s = glsl::assemble("#version 450\n", snippet, "tail\n");
  EXPECT_EQ(s.text, "#version 450\nline1\nline2\ntail\n");
  EXPECT_EQ(s.snippet_first_line, 2);
  EXPECT_EQ(s.describe_line(3), "snippet line 2: line2");
  EXPECT_EQ(s.describe_line(4), "host line 4: tail");
  EXPECT_EQ(glsl::referenced_lines("ERROR: /tmp/a b.frag:7: 'x' : y\n0:9(3): error: z\n"), (std::vector<int>{7, 9}));
}

}  // namespace
