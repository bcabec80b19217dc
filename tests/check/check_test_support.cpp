#include "check_test_support.h"

namespace offsetgen::check::testing {

std::string write_header(const std::string& dir, const std::string& surface, int order, const std::string& thickness,
                         bool glsl) {
  GenerationRequest request;
  request.surface = surface;
  request.order = order;
  request.c = !glsl;
  request.glsl = glsl;
  if (!thickness.empty()) request.thickness = thickness;
  request.command = "check_tests";
  Generation g = generate(request);
  const std::string path = dir + "/" + g.prefix + (glsl ? ".glsl" : ".h");
  write_text(path, glsl ? g.glsl_snippet : g.c_header);
  return path;
}

std::unique_ptr<Compiled> compile_catalog(const std::string& surface, int order, const std::string& thickness) {
  auto c = std::make_unique<Compiled>();
  const std::string dir = scratch_dir(surface + std::to_string(order) + (thickness.empty() ? "" : "g"));
  c->path = write_header(dir, surface, order, thickness);
  c->meta = read_metadata(c->path);
  CompileOptions options;
  options.optimization = "-O0";
  options.cxx = false;
  c->result = compile_and_load(c->path, c->meta, find_toolchain(), options);
  return c;
}


}  // namespace offsetgen::check::testing
