#include "run/cuda_host.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace offsetgen::run::cuda {
namespace {

namespace fs = std::filesystem;

// One `if` per function of one precision: the point's coordinates and h|t rounded to `real`.
std::string dispatch(const FileMetadata& meta, const std::string& real, const std::string& f) {
  const std::string p = meta.prefix;
  const std::string point =
      meta.dims == 3 ? fmt::format("({0})q[0], ({0})q[1], ({0})q[2]", real) : fmt::format("({0})q[0], ({0})q[1]", real);
  const std::string extra = fmt::format("({})q[{}]", real, meta.dims);
  std::string s;
  auto scalar = [&](const std::string& name, const std::string& args) {
    s += fmt::format(
        "  if (std::strcmp(fn, \"{1}{2}\") == 0) {{\n    out.assign(n, 0.0);\n    for (size_t i = 0; i < n; ++i) {{\n"
        "      const double *q = &in[4 * i];\n      out[i] = {0}_{1}{2}({3});\n    }}\n    return 0;\n  }}\n",
        p, name, f, args);
  };
  scalar("field", point);
  scalar("offset", point + ", " + extra);
  scalar("shell", point + ", " + extra);
  if (meta.has_graded()) scalar("graded", point);
  s += fmt::format(
      "  if (std::strcmp(fn, \"normal{2}\") == 0) {{\n    out.assign(n * {4}, 0.0);\n    for (size_t i = 0; i < n; "
      "++i) {{\n"
      "      const double *q = &in[4 * i];\n      {3} v[{4}];\n      {0}_normal{2}({1}, {5}, v);\n"
      "      for (int k = 0; k < {4}; ++k) out[i * {4} + k] = v[k];\n    }}\n    return 0;\n  }}\n",
      p, point, f, real, meta.dims, extra);
  return s;
}

}  // namespace

std::string find_nvcc() {
  if (const char* env = std::getenv("NVCC"); env != nullptr && *env != '\0') return find_on_path(env);
  if (std::string on_path = find_on_path("nvcc"); !on_path.empty()) return on_path;
  if (const char* cuda = std::getenv("CUDA_PATH"); cuda != nullptr && *cuda != '\0')
    if (std::string found = find_on_path(std::string(cuda) + "/bin/nvcc"); !found.empty()) return found;
  return find_on_path("/usr/local/cuda/bin/nvcc");
}

std::string describe_nvcc(const std::string& nvcc, const FileMetadata& meta) {
  const std::string instead = fmt::format(
      "; to check this generation without CUDA, check its C header instead (the same `offsetgen generate` "
      "command with --lang c, then `offsetgen check {}.h`)",
      meta.prefix);
  if (nvcc.empty())
    throw ToolMissing(
        "no nvcc found ($NVCC, PATH, $CUDA_PATH/bin, /usr/local/cuda/bin): a CUDA header is checked by "
        "compiling its host path with the CUDA toolkit's nvcc; install the toolkit or set $NVCC" +
        instead);
  const ProcessResult r = run_process({nvcc, "--version"});
  if (!r.started || r.exit_code != 0)
    throw std::runtime_error(fmt::format("{} --version fails: {}{}", nvcc, r.output, instead));
  // The last line that names the release: "Cuda compilation tools, release 12.4, V12.4.131".
  const auto at = r.output.rfind("release ");
  const std::string release =
      at == std::string::npos ? "" : r.output.substr(at + 8, r.output.find_first_of(",\n", at) - at - 8);
  return release.empty() ? nvcc : fmt::format("{} (CUDA {})", nvcc, release);
}

std::string host_source(const std::string& include_name, const FileMetadata& meta) {
  std::string s = fmt::format(
      "// offsetgen check: the host path of {0}. argv: function, points, input (4 float64 per point), output.\n"
      "#include \"{0}\"\n#include \"{0}\" // a second time: the include guard must hold\n\n"
      "#include <cstdio>\n#include <cstdlib>\n#include <cstring>\n#include <vector>\n\n"
      "static int run(const char *fn, size_t n, const std::vector<double> &in, std::vector<double> &out)\n{{\n",
      include_name);
  s += dispatch(meta, "double", "");
  s += dispatch(meta, "float", "f");
  s += "  return 1;\n}\n\n";
  s += R"(int main(int argc, char **argv)
{
  if (argc != 5) return 2;
  const size_t n = std::strtoull(argv[2], nullptr, 10);
  std::vector<double> in(4 * n), out;
  std::FILE *source = std::fopen(argv[3], "rb");
  if (!source || std::fread(in.data(), sizeof(double), in.size(), source) != in.size()) return 3;
  std::fclose(source);
  if (run(argv[1], n, in, out) != 0) {
    std::fprintf(stderr, "no function %s\n", argv[1]);
    return 4;
  }
  std::FILE *target = std::fopen(argv[4], "wb");
  if (!target || std::fwrite(out.data(), sizeof(double), out.size(), target) != out.size()) return 5;
  return std::fclose(target) == 0 ? 0 : 5;
}
)";
  return s;
}

HostProgram::HostProgram(const std::string& nvcc, const std::string& header_path, const FileMetadata& meta) {
  const fs::path header = fs::absolute(header_path);
  std::string include_name = header.filename().string();
  if (include_name.find_first_of("\"\\\n") != std::string::npos) {  // cannot be spelled in #include "..."
    fs::copy_file(header, dir_.path() / "checked_header.cuh");
    include_name = "checked_header.cuh";
  }
  const fs::path source = dir_.path() / "offsetgen_check_host.cu";
  {
    std::ofstream out(source);
    out << host_source(include_name, meta);
    if (!out) throw std::runtime_error("cannot write " + source.string());
  }
  // As compile.cpp: -O0 for very large functions, where the host compiler needs minutes at -O2.
  int largest = 0;
  for (const auto& [name, ops] : meta.ops) largest = std::max(largest, ops);
  const std::string opt = largest > kLargeFunctionOps ? "-O0" : "-O2";
  step_ = run_step("nvcc host program",
                   {nvcc, "-std=c++17", opt, "-Wno-deprecated-gpu-targets", "-Werror", "all-warnings", "-Xcompiler",
                    "-Wall,-Wextra,-Werror,-ffp-contract=off", "-I" + header.parent_path().string(),
                    "-I" + dir_.path().string(), source.string(), "-o", (dir_.path() / "host").string()});
}

std::vector<double> HostProgram::run(const std::string& function, const std::vector<std::array<double, 4>>& inputs,
                                     int components) const {
  if (!ok()) throw std::runtime_error("the host program did not compile");
  return run_on_points({(dir_.path() / "host").string(), function, std::to_string(inputs.size())}, dir_.path(), inputs,
                       inputs.size() * static_cast<size_t>(components));
}

}  // namespace offsetgen::run::cuda
