#include "check_test_support.h"

#include <utility>

namespace offsetgen::check::testing {

std::string write_header(const std::string& dir, const std::string& surface, int order, const std::string& thickness,
                         bool glsl, const std::string& method) {
  GenerationRequest request;
  request.surface = surface;
  request.order = order;
  request.method = method;
  request.languages = {glsl ? "glsl" : "c"};
  if (!thickness.empty()) request.thickness = thickness;
  request.command = "check_tests";
  Generation g = generate(request);
  const std::string path = dir + "/" + g.prefix + (glsl ? ".glsl" : ".h");
  write_text(path, glsl ? g.glsl_snippet() : g.c_header());
  return path;
}

std::unique_ptr<Compiled> compile_catalog(const std::string& surface, int order, const std::string& thickness,
                                          const std::string& method) {
  auto c = std::make_unique<Compiled>();
  const std::string dir = scratch_dir(method + "-" + surface + std::to_string(order) + (thickness.empty() ? "" : "g"));
  c->path = write_header(dir, surface, order, thickness, false, method);
  c->meta = run::read_metadata(c->path);
  run::CompileOptions options;
  options.optimization = "-O0";
  options.cxx = false;
  c->result = run::compile_and_load(c->path, c->meta, run::find_toolchain(), options);
  return c;
}

ThicknessOptions thickness_options(std::vector<double> h, int grid) {
  ThicknessOptions o;
  o.h = std::move(h);
  o.grid = grid;
  o.scan = 100;
  return o;
}

std::vector<double> column(const ThicknessReport& r, ErrorStats SweepRow::*member) {
  std::vector<double> v;
  for (const auto& row : r.rows) v.push_back((row.*member).mean);
  return v;
}

}  // namespace offsetgen::check::testing
