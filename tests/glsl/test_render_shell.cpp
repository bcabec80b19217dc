// Runs the render_shell executable on the fixture and inspects the PNG it writes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "offsetgen_test_support.h"
#include "png_io.h"
#include "reference_surfaces.h"
#include "shell_renderer.h"

namespace {

namespace fs = std::filesystem;

namespace ts = offsetgen::test_support;
using Outcome = ts::CommandResult;

// render_shell with `args` (shell-quoted); stdout and stderr together.
Outcome run_render_shell(const std::string& args) {
  return ts::run_shell(std::string("'") + OFFSETGEN_RENDER_SHELL + "' " + args);
}

std::string fixture_args() {
  return "--snippet '" + offsetgen::glsl_test::fixture_dir() + "/gyroid_o1.glsl' --prefix gyroid_o1";
}

fs::path scratch_png(const std::string& name) {
  return fs::temp_directory_path() / ("offsetgen_render_" + std::to_string(::getpid()) + "_" + name + ".png");
}

struct PixelCounts {
  std::size_t background = 0;
  std::size_t wall = 0;
};

PixelCounts classify(const offsetgen::png::Image& img) {
  PixelCounts c;
  for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
    const bool bg = img.rgba[i] == offsetgen::render::kBackground[0] &&
                    img.rgba[i + 1] == offsetgen::render::kBackground[1] &&
                    img.rgba[i + 2] == offsetgen::render::kBackground[2];
    (bg ? c.background : c.wall) += 1;
  }
  return c;
}

// Renders at 128x128 with `extra` options and checks size, content and both pixel kinds.
void expect_reasonable_picture(const std::string& name, const std::string& extra) {
  const fs::path png = scratch_png(name);
  const Outcome o = run_render_shell(fixture_args() + " --size 128x128 " + extra + " -o '" + png.string() + "'");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  std::cout << "[ measured ] " << o.output;
  const auto img = offsetgen::png::read_rgba(png.string());
  fs::remove(png);
  ASSERT_EQ(img.width, 128);
  ASSERT_EQ(img.height, 128);
  const PixelCounts c = classify(img);
  const double total = 128.0 * 128.0;
  // The box covers roughly half of the frame and the gyroid wall most of the box.
  EXPECT_GT(static_cast<double>(c.wall) / total, 0.15) << "too few wall pixels";
  EXPECT_GT(static_cast<double>(c.background) / total, 0.15) << "too few background pixels";
}

TEST(RenderShell, EsHostOneCell) { expect_reasonable_picture("es", "--thickness 0.1"); }
TEST(RenderShell, GlHostTwoCells) { expect_reasonable_picture("gl", "--thickness 0.08 --cells 2 --api gl"); }
TEST(RenderShell, AGradedWallRendersAReasonablePicture) {
  expect_reasonable_picture("graded", "--graded --thickness 0.04");
}

TEST(RenderShell, BoxAndViewDirection) {
  expect_reasonable_picture("box", "--thickness 0.08 --box 2x1x1 --view 0.2 -0.95 0.3");
}

TEST(RenderShell, BadBoxAndViewAreRejected) {
  const std::string png = " -o '" + scratch_png("badbox").string() + "'";
  Outcome o = run_render_shell(fixture_args() + " --box 2x1" + png);
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("bad --box '2x1'"), std::string::npos) << o.output;
  o = run_render_shell(fixture_args() + " --box 0x1x1" + png);
  EXPECT_EQ(o.exit_code, 1) << o.output;
  EXPECT_NE(o.output.find("box cells must be in 1..16"), std::string::npos) << o.output;
  o = run_render_shell(fixture_args() + " --view 0 0 1" + png);
  EXPECT_EQ(o.exit_code, 1) << o.output;
  EXPECT_NE(o.output.find("not vertical"), std::string::npos) << o.output;
}

TEST(RenderShell, WrongPrefixListsTheSnippetFunctions) {
  const Outcome o = run_render_shell(fixture_args() + "x -o '" + scratch_png("bad").string() + "'");
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_NE(o.output.find("defines no gyroid_o1x_field"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("gyroid_o1_shell"), std::string::npos) << o.output;
}

// Thicker walls cover more of the picture: a cheap check that the thickness reaches the shader.
TEST(RenderShell, ThickerWallsCoverMorePixels) {
  offsetgen::render::Options o;
  o.snippet = offsetgen::glsl::read_text_file(offsetgen::glsl_test::fixture_dir() + "/gyroid_o1.glsl");
  o.prefix = "gyroid_o1";
  o.width = o.height = 96;
  o.thickness = 0.03;
  const auto thin = classify(offsetgen::render::render(o));
  o.thickness = 0.2;
  const auto thick = classify(offsetgen::render::render(o));
  EXPECT_GT(thick.wall, thin.wall);
}

}  // namespace
