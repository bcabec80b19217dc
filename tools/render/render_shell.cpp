// render_shell: headless picture of a generated shell snippet.
//   render_shell --snippet gyroid_o4.glsl --prefix gyroid_o4 --thickness 0.1 -o out.png
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <regex>
#include <string>
#include <vector>

#include "shell_renderer.h"

namespace {

// "512x384" -> (512, 384); a single number means a square image.
bool parse_size(const std::string& text, int& w, int& h) {
  std::smatch m;
  static const std::regex kSize(R"((\d{1,5})(?:[xX](\d{1,5}))?)");
  if (!std::regex_match(text, m, kSize)) return false;
  w = std::stoi(m[1].str());
  h = m[2].matched ? std::stoi(m[2].str()) : w;
  return true;
}

// "3x1x1" -> {3, 1, 1}.
bool parse_box(const std::string& text, int box[3]) {
  std::smatch m;
  static const std::regex kBox(R"((\d{1,2})[xX](\d{1,2})[xX](\d{1,2}))");
  if (!std::regex_match(text, m, kBox)) return false;
  for (int i = 0; i < 3; ++i) box[i] = std::stoi(m[static_cast<std::size_t>(i) + 1].str());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  namespace r = offsetgen::render;
  CLI::App app{
      "Ray-march the shell of a generated offsetgen GLSL snippet headless (Mesa llvmpipe) to PNG"};
  std::string snippet_path, output = "shell.png", size = "512x512", api = "es";
  r::Options o;
  app.add_option("--snippet", snippet_path, "generated .glsl snippet (pasted verbatim)")
      ->required();
  app.add_option("--prefix", o.prefix, "function prefix, e.g. gyroid_o4")->required();
  app.add_option(
         "--thickness", o.thickness,
         "total wall thickness t, cell length 1 (with --graded: thinnest wall, sets the step)")
      ->capture_default_str();
  app.add_flag("--graded", o.graded,
               "draw <prefix>_graded(p) < 0 (thickness baked into the snippet)");
  app.add_option("--cells", o.cells, "render the box [0,N]^3")->capture_default_str();
  std::string box;
  app.add_option("--box", box, "render the box [0,X]x[0,Y]x[0,Z], given as XxYxZ cells (e.g. 3x1x1)");
  std::vector<double> view;
  app.add_option("--view", view, "direction from the box centre to the eye: X Y Z (default 0.70 0.46 0.55)")
      ->expected(3);
  app.add_option("--size", size, "WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--samples", o.samples, "NxN supersampling per pixel")->capture_default_str();
  app.add_option("--step", o.step, "ray-march step (default 0.4 * thickness)");
  app.add_option("--api", api, "es (GLSL ES 3.00 host) or gl (GL 4.3 core host)")
      ->check(CLI::IsMember({"es", "gl"}))
      ->capture_default_str();
  app.add_option("-o,--output", output, "PNG file to write")->capture_default_str();
  bool print_shader = false;
  app.add_flag("--print-shader", print_shader, "print the fragment shader and exit");
  CLI11_PARSE(app, argc, argv);

  try {
    if (!parse_size(size, o.width, o.height)) {
      std::fprintf(stderr, "render_shell: bad --size '%s' (want WIDTHxHEIGHT)\n", size.c_str());
      return 2;
    }
    if (!box.empty() && !parse_box(box, o.box)) {
      std::fprintf(stderr, "render_shell: bad --box '%s' (want XxYxZ, e.g. 3x1x1)\n", box.c_str());
      return 2;
    }
    if (!view.empty()) std::copy(view.begin(), view.end(), o.view);
    o.api = api == "gl" ? offsetgen::gl::Api::Desktop43 : offsetgen::gl::Api::Es30;
    o.snippet = offsetgen::glsl::read_text_file(snippet_path);
    if (print_shader) {
      std::fputs(r::fragment_source(o).text.c_str(), stdout);
      return 0;
    }
    r::Timing timing;
    const auto image = r::render(o, &timing);
    offsetgen::png::write_rgba(output, image);
    int cells[3];
    r::box_cells(o, cells);
    std::printf("render_shell: %s %dx%d, %dx%dx%d cell(s), on %s: compile %.2f s, render %.2f s\n",
                output.c_str(), o.width, o.height, cells[0], cells[1], cells[2],
                offsetgen::gl::renderer().c_str(), timing.compile_s, timing.render_s);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_shell: %s\n", e.what());
    return 1;
  }
}
