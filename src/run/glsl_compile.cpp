#include "run/glsl_compile.h"

#include "run/process.h"
#include "surfaces/input_error.h"
#include "surfaces/surface.h"

#include <fmt/format.h>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace offsetgen::run {
namespace {

namespace fs = std::filesystem;

std::string prologue(GlslTarget t) {
  switch (t) {
    case GlslTarget::Es300:
      return "#version 300 es\nprecision highp float;\nprecision highp int;\nout highp vec4 o_color;\n";
    case GlslTarget::Gl330:
      return "#version 330 core\nout vec4 o_color;\n";
    case GlslTarget::Gl450:
      return "#version 450 core\nout vec4 o_color;\n";
    case GlslTarget::Vulkan:
      return "#version 450\nlayout(location = 0) out vec4 o_color;\n";
  }
  return "";
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// "ERROR: 0:57: ..." -> the same line, followed by "  (snippet line 53)" when it falls in the snippet.
std::string annotate(const std::string& log, int first, int snippet_lines, const std::string& name) {
  static const std::regex location(R"((?:ERROR|WARNING): .*?:(\d+):)");
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    out += line;
    std::smatch m;
    if (std::regex_search(line, m, location)) {
      const int host = std::stoi(m[1].str());
      const int snippet = host - first + 1;
      if (snippet >= 1 && snippet <= snippet_lines) out += fmt::format("   [{} line {}]", name, snippet);
    }
    out += "\n";
  }
  return out;
}

}  // namespace

std::string glsl_target_name(GlslTarget t) {
  switch (t) {
    case GlslTarget::Es300:
      return "GLSL ES 3.00 (WebGL2)";
    case GlslTarget::Gl330:
      return "GLSL 3.30 core";
    case GlslTarget::Gl450:
      return "GLSL 4.50 core";
    case GlslTarget::Vulkan:
      return "Vulkan GLSL 450 -> SPIR-V";
  }
  return "?";
}

std::string glsl_host_shader(const std::string& snippet, const FileMetadata& meta, GlslTarget target,
                             int* snippet_first_line) {
  std::string s = prologue(target);
  if (snippet_first_line) *snippet_first_line = count_lines(s) + 1;
  s += snippet;
  if (!snippet.empty() && snippet.back() != '\n') s += "\n";
  const std::string& p = meta.prefix;
  const std::string point = meta.dims == 3 ? "vec3(q.xy, q.z)" : "q.xy";
  s += "\nvoid main() {\n";
  s += "  highp vec4 q = vec4(gl_FragCoord.xy * 0.01, 0.3, 0.02);\n";
  s += "  highp float acc = 0.0;\n";
  s += fmt::format("  acc += {}_field({});\n", p, point);
  s += fmt::format("  acc += {}_offset({}, q.w);\n", p, point);
  s += fmt::format("  acc += {}_shell({}, q.w);\n", p, point);
  s += fmt::format("  acc += dot({}_normal({}, q.w), {}(1.0));\n", p, point, meta.dims == 3 ? "vec3" : "vec2");
  if (meta.has_graded()) s += fmt::format("  acc += {}_graded({});\n", p, point);
  if (meta.wall_density) s += fmt::format("  acc += {}_wall({});\n", p, point);
  if (meta.has_density)
    for (const char* f : {"density", "thickness_for_density", "network_density", "offset_for_density"})
      s += fmt::format("  acc += {}_{}(q.w);\n", p, f);
  s += "  o_color = vec4(acc);\n}\n";
  return s;
}

std::vector<GlslCompileResult> compile_glsl(const std::string& snippet, const FileMetadata& meta,
                                            const std::string& display_name) {
  const std::string validator = find_on_path("glslangValidator");
  if (validator.empty())
    throw ToolMissing(
        "glslangValidator is not on PATH: `offsetgen check` compiles GLSL snippets with it "
        "(Debian: apt-get install glslang-tools)");
  std::string dir_pattern = (fs::temp_directory_path() / "offsetgen-glsl-XXXXXX").string();
  if (::mkdtemp(dir_pattern.data()) == nullptr) throw std::runtime_error("cannot create a scratch directory");
  const fs::path dir = dir_pattern;
  std::vector<GlslCompileResult> results;
  const int snippet_lines = count_lines(snippet) + (snippet.empty() || snippet.back() == '\n' ? 0 : 1);
  for (GlslTarget t : {GlslTarget::Es300, GlslTarget::Gl330, GlslTarget::Gl450, GlslTarget::Vulkan}) {
    GlslCompileResult r;
    r.target = t;
    r.name = glsl_target_name(t);
    int first = 1;
    const std::string host = glsl_host_shader(snippet, meta, t, &first);
    const fs::path frag = dir / fmt::format("host{}.frag", static_cast<int>(t));
    std::ofstream(frag, std::ios::binary) << host;
    r.command = {validator, "-l"};
    if (t == GlslTarget::Vulkan) {
      r.command.push_back("-V");
      r.command.push_back("-o");
      r.command.push_back((dir / "host.spv").string());
    }
    r.command.push_back(frag.string());
    ProcessResult pr = run_process(r.command);
    r.ok = pr.started && pr.exit_code == 0;
    r.output = r.ok ? pr.output : annotate(pr.output, first, snippet_lines, display_name);
    results.push_back(r);
  }
  if (std::getenv("OFFSETGEN_CHECK_KEEP") == nullptr) {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  return results;
}

}  // namespace offsetgen::run
