#include "check_test_support.h"

#include "check/process.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace offsetgen::check::testing {

namespace fs = std::filesystem;

std::string scratch_dir(const std::string& name) {
  fs::path dir = fs::path(OFFSETGEN_CHECK_TEST_TMP) / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string write_header(const std::string& dir, const std::string& surface, int order, const std::string& thickness,
                         bool glsl, const std::string& method) {
  GenerationRequest request;
  request.surface = surface;
  request.order = order;
  request.method = method;
  request.c = !glsl;
  request.glsl = glsl;
  if (!thickness.empty()) request.thickness = thickness;
  request.command = "check_tests";
  Generation g = generate(request);
  const std::string path = dir + "/" + g.prefix + (glsl ? ".glsl" : ".h");
  write_text(path, glsl ? g.glsl_snippet : g.c_header);
  return path;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::unique_ptr<Compiled> compile_catalog(const std::string& surface, int order, const std::string& thickness,
                                          const std::string& method) {
  auto c = std::make_unique<Compiled>();
  const std::string dir = scratch_dir(method + "-" + surface + std::to_string(order) + (thickness.empty() ? "" : "g"));
  c->path = write_header(dir, surface, order, thickness, false, method);
  c->meta = read_metadata(c->path);
  CompileOptions options;
  options.optimization = "-O0";
  options.cxx = false;
  c->result = compile_and_load(c->path, c->meta, find_toolchain(), options);
  return c;
}

CliResult run_offsetgen(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {OFFSETGEN_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  ProcessResult r = run_process(argv);
  return {r.exit_code, r.output};
}

}  // namespace offsetgen::check::testing
