#include "glsl_compile.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace offsetgen::glsl {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMissingValidator =
    "glslangValidator not found: run tools/install_deps.sh (Debian package glslang-tools)";

// An argument expression of `type` that depends on the fragment position, so nothing folds away.
std::string argument_for(const std::string& type) {
  if (type == "float") return "q.w";
  if (type == "vec2") return "q.xy";
  if (type == "vec3") return "q.xyz";
  if (type == "vec4") return "q";
  if (type == "int") return "int(q.x)";
  if (type == "uint") return "uint(q.x)";
  if (type == "bool") return "(q.x > q.y)";
  if (type == "mat2" || type == "mat3" || type == "mat4") return type + "(q.x)";
  throw std::runtime_error("cannot generate an argument of type '" + type + "'");
}

// Folds a value of `type` into the float accumulator `acc`.
std::string accumulate(const std::string& type, const std::string& value) {
  if (type == "float") return "acc += " + value + ";";
  if (type == "vec2" || type == "vec3" || type == "vec4") {
    return "acc += dot(" + value + ", " + type + "(1.0));";
  }
  if (type == "int" || type == "uint") return "acc += float(" + value + ");";
  if (type == "bool") return "acc += " + value + " ? 1.0 : 0.0;";
  if (type == "mat2" || type == "mat3" || type == "mat4") return "acc += " + value + "[0][0];";
  throw std::runtime_error("cannot use a value of type '" + type + "'");
}

// main() calling every function of the snippet once; out/inout arguments become locals.
std::string call_everything(const std::vector<GlslFunction>& fns) {
  std::ostringstream os;
  os << "void main() {\n"
     << "  highp vec4 q = vec4(gl_FragCoord.xy * 0.01, 0.3, 0.02);\n"
     << "  highp float acc = 0.0;\n";
  int n = 0;
  for (const GlslFunction& f : fns) {
    std::vector<std::string> args;
    std::vector<std::pair<std::string, std::string>> outs;  // (local name, type)
    os << "  {\n";
    for (const GlslParam& p : f.params) {
      if (p.qualifier == "out" || p.qualifier == "inout") {
        const std::string local = "og_arg" + std::to_string(n++);
        os << "    highp " << p.type << " " << local << " = " << argument_for(p.type) << ";\n";
        args.push_back(local);
        outs.emplace_back(local, p.type);
      } else {
        args.push_back(argument_for(p.type));
      }
    }
    std::string call = f.name + "(";
    for (std::size_t i = 0; i < args.size(); ++i) call += (i ? ", " : "") + args[i];
    call += ")";
    if (f.return_type == "void") {
      os << "    " << call << ";\n";
    } else {
      os << "    " << accumulate(f.return_type, call) << "\n";
    }
    for (const auto& [local, type] : outs) os << "    " << accumulate(type, local) << "\n";
    os << "  }\n";
  }
  os << "  o_color = vec4(acc);\n}\n";
  return os.str();
}

std::string prologue(Target t) {
  switch (t) {
    case Target::Es300:
      return "#version 300 es\nprecision highp float;\nprecision highp int;\n";
    case Target::Gl330:
      return "#version 330 core\n";
    case Target::Gl450:
      return "#version 450 core\n";
    case Target::Vulkan:
      return "#version 450\n";
  }
  return {};
}

std::string output_declaration(Target t) {
  switch (t) {
    case Target::Es300:
      return "out highp vec4 o_color;\n";
    case Target::Vulkan:
      return "layout(location = 0) out vec4 o_color;\n";
    default:
      return "out vec4 o_color;\n";
  }
}

// Runs a command, returning its exit status and combined stdout/stderr.
int run_capture(const std::string& command, std::string& output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    output = "cannot run: " + command;
    return -1;
  }
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) output.append(buf.data(), n);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A unique scratch directory per process, removed at exit.
const fs::path& scratch_dir() {
  struct Dir {
    fs::path path;
    Dir() {
      path = fs::temp_directory_path() / ("offsetgen_glsl_" + std::to_string(::getpid()));
      fs::create_directories(path);
    }
    ~Dir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static Dir dir;
  return dir.path;
}

}  // namespace

const char* target_name(Target t) {
  switch (t) {
    case Target::Es300:
      return "GLSL ES 3.00";
    case Target::Gl330:
      return "GLSL 3.30 core";
    case Target::Gl450:
      return "GLSL 4.50 core";
    case Target::Vulkan:
      return "Vulkan GLSL 450 (SPIR-V)";
  }
  return "?";
}

std::vector<Target> all_targets() {
  return {Target::Es300, Target::Gl330, Target::Gl450, Target::Vulkan};
}

HostedSource host_shader(const std::string& snippet, Target target) {
  const std::string epilogue =
      "\n" + output_declaration(target) + call_everything(scan_functions(snippet));
  return assemble(prologue(target), snippet, epilogue);
}

std::string find_glslang_validator() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / "glslangValidator";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

CompileResult compile_fragment_shader(const HostedSource& source, Target target) {
  CompileResult r;
  r.target = target;
  r.source = source;
  const std::string validator = find_glslang_validator();
  if (validator.empty()) {
    r.message = kMissingValidator;
    return r;
  }
  static std::atomic<int> counter{0};
  const std::string stem = "snippet" + std::to_string(counter++);
  const fs::path frag = scratch_dir() / (stem + ".frag");  // the extension selects the stage
  std::ofstream(frag, std::ios::binary) << r.source.text;
  std::string command = "'" + validator + "' -l";
  if (target == Target::Vulkan)
    command += " -V -o '" + (scratch_dir() / (stem + ".spv")).string() + "'";
  command += " '" + frag.string() + "'";
  std::string log;
  const int status = run_capture(command, log);
  r.ok = status == 0;
  if (!r.ok) {
    r.message = std::string(target_name(target)) + ": glslangValidator exit " +
                std::to_string(status) + "\n" + annotate_log(log, r.source);
  }
  return r;
}

CompileResult compile_check(const std::string& snippet, Target target) {
  if (find_glslang_validator().empty()) {
    CompileResult r;
    r.target = target;
    r.message = kMissingValidator;
    return r;
  }
  HostedSource source;
  try {
    source = host_shader(snippet, target);
  } catch (const std::exception& e) {
    CompileResult r;
    r.target = target;
    r.message = std::string("cannot build a host shader: ") + e.what();
    return r;
  }
  return compile_fragment_shader(source, target);
}

std::vector<CompileResult> compile_check_all(const std::string& snippet) {
  std::vector<CompileResult> results;
  for (Target t : all_targets()) results.push_back(compile_check(snippet, t));
  return results;
}

}  // namespace offsetgen::glsl
