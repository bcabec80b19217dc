// render_shell on real generated snippets: the picture has the requested size, is not blank and
// holds both wall and background pixels; the snippet sits in the shader byte for byte.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "generated_cases.h"
#include "offsetgen_test_support.h"
#include "png_io.h"
#include "run/glsl_source.h"
#include "run/headless_gl.h"
#include "shell_renderer.h"

namespace {

namespace fs = std::filesystem;
namespace gt = offsetgen::glsl_test;

namespace ts = offsetgen::test_support;
using Outcome = ts::CommandResult;

// render_shell with `args` (shell-quoted); stdout and stderr together.
Outcome run_render_shell(const std::string& args) {
  return ts::run_shell(std::string("'") + OFFSETGEN_RENDER_SHELL + "' " + args);
}

const gt::GeneratedCase& gyroid_o4() {
  for (const auto& c : gt::generated_cases()) {
    if (std::string(c.surface) == "gyroid" && c.order == 4) return c;
  }
  throw std::runtime_error("no gyroid_o4 among the generated cases");
}

struct PixelCounts {
  std::size_t background = 0, wall = 0, distinct_wall_colors = 0;
};

PixelCounts classify(const offsetgen::png::Image& img) {
  PixelCounts c;
  std::vector<bool> seen(1u << 15, false);  // 5 bits per channel is enough to see shading
  for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
    const bool bg = img.rgba[i] == offsetgen::render::kBackground[0] &&
                    img.rgba[i + 1] == offsetgen::render::kBackground[1] &&
                    img.rgba[i + 2] == offsetgen::render::kBackground[2];
    if (bg) {
      ++c.background;
      continue;
    }
    ++c.wall;
    const std::size_t key = (static_cast<std::size_t>(img.rgba[i] >> 3) << 10) |
                            (static_cast<std::size_t>(img.rgba[i + 1] >> 3) << 5) |
                            static_cast<std::size_t>(img.rgba[i + 2] >> 3);
    if (!seen[key]) {
      seen[key] = true;
      ++c.distinct_wall_colors;
    }
  }
  return c;
}

void expect_picture(const std::string& name, const std::string& args) {
  const fs::path png =
      fs::temp_directory_path() / ("offsetgen_gen_render_" + std::to_string(::getpid()) + "_" + name + ".png");
  const Outcome o = run_render_shell(args + " --size 160x120 -o '" + png.string() + "'");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  std::cout << "[ measured ] " << o.output;
  const auto img = offsetgen::png::read_rgba(png.string());
  fs::remove(png);
  ASSERT_EQ(img.width, 160);
  ASSERT_EQ(img.height, 120);
  const PixelCounts c = classify(img);
  const double total = 160.0 * 120.0;
  EXPECT_GT(static_cast<double>(c.wall) / total, 0.15) << "too few wall pixels";
  EXPECT_GT(static_cast<double>(c.background) / total, 0.15) << "too few background pixels";
  EXPECT_GT(c.distinct_wall_colors, 20u) << "the wall is flat: shading (normals) missing";
}

TEST(GeneratedRender, GyroidOrder4Shell) {
  const auto& c = gyroid_o4();
  expect_picture("gyroid", std::string("--snippet '") + c.snippet + "' --prefix " + c.prefix + " --thickness 0.1");
}

TEST(GeneratedRender, GyroidOrder4GlHost) {
  const auto& c = gyroid_o4();
  expect_picture("gyroid_gl",
                 std::string("--snippet '") + c.snippet + "' --prefix " + c.prefix + " --thickness 0.08 --api gl");
}

TEST(GeneratedRender, AGradedWallRendersAsItsReferencePicture) {
  const auto& c = gt::graded_case();
  expect_picture("graded",
                 std::string("--snippet '") + c.snippet + "' --prefix " + c.prefix + " --graded --thickness 0.02");
}

// The renderer pastes the file as it is: its bytes appear unchanged in the fragment shader.
TEST(GeneratedRender, SnippetIsPastedByteForByte) {
  const auto& c = gyroid_o4();
  offsetgen::render::Options o;
  o.snippet = offsetgen::glsl::read_text_file(c.snippet);
  o.prefix = c.prefix;
  const auto src = offsetgen::render::fragment_source(o);
  const auto at = src.text.find(o.snippet);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(src.text.find("#version"), 0u);
}

// The complete host shader of docs/glsl.md ("Pasting it"), with the real gyroid_o4.glsl pasted at
// its marker line: it compiles (glslang, Mesa), links and draws both wall faces and background.
offsetgen::glsl::HostedSource docs_example() {
  const std::string md = offsetgen::glsl::read_text_file(OFFSETGEN_DOCS_DIR "/glsl.md");
  const auto begin = md.find("<!-- host-shader-begin -->");
  const auto end = md.find("<!-- host-shader-end -->");
  if (begin == std::string::npos || end == std::string::npos) {
    throw std::runtime_error("docs/glsl.md lost its host-shader markers");
  }
  const std::string block = md.substr(begin, end - begin);
  const auto code = block.find("```glsl\n") + 8;
  const std::string shader = block.substr(code, block.rfind("```") - code);
  const std::string marker = "// ---- paste gyroid_o4.glsl here, unchanged ----\n";
  const auto at = shader.find(marker);
  if (at == std::string::npos) throw std::runtime_error("docs example lost its paste marker");
  const std::string snippet = offsetgen::glsl::read_text_file(gyroid_o4().snippet);
  return offsetgen::glsl::assemble(shader.substr(0, at + marker.size()), snippet, shader.substr(at + marker.size()));
}

TEST(DocsExample, HostShaderCompilesLinksAndDraws) {
  namespace gl = offsetgen::gl;
  const auto source = docs_example();
  // glslang first: stricter about GLSL ES than Mesa.
  const std::string frag = ts::scratch_dir("docs_example") + "/host.frag";  // the extension selects the stage
  ts::write_file(frag, source.text);
  const ts::CommandResult glslang = ts::run_command({"glslangValidator", "-l", frag});
  ASSERT_EQ(glslang.exit_code, 0) << glslang.output;

  const gl::Functions& f = gl::make_current(gl::Api::Es30);
  const std::string vs =
      "#version 300 es\nvoid main() {\n"
      "  vec2 v = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);\n"
      "  gl_Position = vec4(v, 0.0, 1.0);\n}\n";
  const GLuint program =
      gl::build_program(f, {{GL_VERTEX_SHADER, offsetgen::glsl::assemble(vs, "", "")}, {GL_FRAGMENT_SHADER, source}});
  constexpr int kSize = 96;
  GLuint rbo = 0, fbo = 0, vao = 0;
  f.GenRenderbuffers(1, &rbo);
  f.BindRenderbuffer(GL_RENDERBUFFER, rbo);
  f.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
  f.GenFramebuffers(1, &fbo);
  f.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  f.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbo);
  f.GenVertexArrays(1, &vao);
  f.BindVertexArray(vao);
  f.Viewport(0, 0, kSize, kSize);
  f.UseProgram(program);
  f.Uniform2f(f.GetUniformLocation(program, "u_resolution"), kSize, kSize);
  f.Uniform3f(f.GetUniformLocation(program, "u_eye"), 0.5f + 2.6f * 0.70f, 0.5f + 2.6f * 0.46f, 0.5f + 2.6f * 0.55f);
  f.Uniform1f(f.GetUniformLocation(program, "u_thickness"), 0.1f);
  f.DrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<std::uint8_t> px(static_cast<std::size_t>(kSize) * kSize * 4);
  f.PixelStorei(GL_PACK_ALIGNMENT, 1);
  f.ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  gl::check_error(f, "docs example draw");
  f.DeleteVertexArrays(1, &vao);
  f.DeleteFramebuffers(1, &fbo);
  f.DeleteRenderbuffers(1, &rbo);
  f.DeleteProgram(program);

  std::size_t background = 0, orange = 0, blue = 0;
  for (std::size_t i = 0; i < px.size(); i += 4) {
    const int r8 = px[i], g8 = px[i + 1], b8 = px[i + 2];
    if (r8 == 255 && g8 == 255 && b8 == 255)
      ++background;
    else if (r8 > b8 + 20)
      ++orange;  // F > 0 face
    else if (b8 > r8 + 20)
      ++blue;  // F < 0 face
  }
  const double total = kSize * kSize;
  EXPECT_GT(static_cast<double>(background) / total, 0.1);
  EXPECT_GT(static_cast<double>(orange) / total, 0.02);
  EXPECT_GT(static_cast<double>(blue) / total, 0.02);
}

}  // namespace
