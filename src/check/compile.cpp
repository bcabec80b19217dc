#include "check/compile.h"

#include "check/process.h"
#include "surfaces/surface.h"

#include <dlfcn.h>
#include <unistd.h>

#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>

namespace offsetgen::check {
namespace {

namespace fs = std::filesystem;

const char* const kStrictWarnings[] = {"-pedantic", "-Wall", "-Wextra", "-Werror"};

std::vector<std::string> first_found(const char* env, std::initializer_list<const char*> names, std::string& origin,
                                     bool required, const char* what) {
  if (const char* value = std::getenv(env); value != nullptr && *value != '\0') {
    std::vector<std::string> words = split_words(value);
    if (!words.empty()) {
      std::string exe = find_on_path(words[0]);
      if (exe.empty()) {
        if (required)
          throw InputError(
              fmt::format("${} is set to '{}', but '{}' is not an executable on PATH", env, value, words[0]));
        return {};
      }
      origin = std::string("$") + env;
      return words;
    }
  }
  for (const char* name : names) {
    std::string exe = find_on_path(name);
    if (!exe.empty()) {
      origin = "PATH";
      return {exe};
    }
  }
  if (required) {
    std::string tried;
    for (const char* name : names) tried += std::string(tried.empty() ? "" : ", ") + name;
    throw InputError(
        fmt::format("no {} on PATH (looked for {}; set ${} to choose one). `offsetgen check` compiles "
                    "the header with the system compiler; install one with `apt-get install gcc`.",
                    what, tried, env));
  }
  return {};
}

template <typename T>
T symbol(void* handle, const std::string& name) {
  void* p = ::dlsym(handle, name.c_str());
  return reinterpret_cast<T>(p);
}

}  // namespace

CompileStep run_step(const std::string& name, std::vector<std::string> command) {
  CompileStep step;
  step.name = name;
  step.command = command;
  auto start = std::chrono::steady_clock::now();
  ProcessResult r = run_process(command);
  step.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  step.ok = r.started && r.exit_code == 0;
  step.output = r.output;
  if (!r.started && step.output.empty()) step.output = "could not run " + command.at(0);
  return step;
}

LoadedLibrary::~LoadedLibrary() {
  if (handle_ != nullptr) ::dlclose(handle_);
}

Toolchain find_toolchain() {
  Toolchain t;
  t.c = first_found("CC", {"cc", "gcc", "clang"}, t.c_origin, true, "C compiler");
  t.cxx = first_found("CXX", {"c++", "g++", "clang++"}, t.cxx_origin, false, "C++ compiler");
  return t;
}

std::string wrapper_source(const std::string& include_name, const FileMetadata& meta, bool batch) {
  const std::string& p = meta.prefix;
  const std::string args = meta.dims == 3 ? "p[0], p[1], p[2]" : "p[0], p[1]";
  std::string s;
  s += "/* offsetgen check: exports the header's static inline functions for dlopen. */\n";
  s += fmt::format("#include \"{}\"\n#include \"{}\" /* a second time: the include guard must hold */\n\n",
                   include_name, include_name);
  s += "#ifdef __cplusplus\nextern \"C\" {\n#endif\n";
  auto emit = [&](const std::string& type, const char* suffix) {
    const std::string t = type;
    const std::string fs = type == "float" ? "f" : "";
    s += fmt::format("{0} offsetgen_check_field{1}(const {0}* p);\n", t, fs);
    s += fmt::format("{0} offsetgen_check_field{1}(const {0}* p) {{ return {2}_field{1}({3}); }}\n", t, fs, p, args);
    s += fmt::format("{0} offsetgen_check_offset{1}(const {0}* p, {0} h);\n", t, fs);
    s += fmt::format("{0} offsetgen_check_offset{1}(const {0}* p, {0} h) {{ return {2}_offset{1}({3}, h); }}\n", t, fs,
                     p, args);
    s += fmt::format("{0} offsetgen_check_shell{1}(const {0}* p, {0} t);\n", t, fs);
    s += fmt::format("{0} offsetgen_check_shell{1}(const {0}* p, {0} t) {{ return {2}_shell{1}({3}, t); }}\n", t, fs, p,
                     args);
    s += fmt::format("void offsetgen_check_normal{1}(const {0}* p, {0} h, {0}* n);\n", t, fs);
    s += fmt::format("void offsetgen_check_normal{1}(const {0}* p, {0} h, {0}* n) {{ {2}_normal{1}({3}, h, n); }}\n", t,
                     fs, p, args);
    if (meta.has_graded()) {
      s += fmt::format("{0} offsetgen_check_graded{1}(const {0}* p);\n", t, fs);
      s +=
          fmt::format("{0} offsetgen_check_graded{1}(const {0}* p) {{ return {2}_graded{1}({3}); }}\n", t, fs, p, args);
    }
    if (batch) {
      const std::string z = meta.dims == 3 ? "z, " : "";
      for (const char* fn : {"offset", "shell"}) {
        const std::string params = fmt::format("size_t n, const {0}* x, const {0}* y, const {0}* z, const {0}* v, {0}* out", t);
        s += fmt::format("void offsetgen_check_{0}{1}_n({2});\n", fn, fs, params);
        s += fmt::format("void offsetgen_check_{0}{1}_n({2}) {{ (void)z; {3}_{0}{1}_n(n, x, y, {4}v, out); }}\n", fn,
                         fs, params, p, z);
      }
    }
    (void)suffix;
  };
  if (meta.has_double) emit("double", "");
  // The density relations and _wall (files with density functions).
  auto emit_density = [&](const std::string& t, const std::string& fs) {
    if (meta.wall_density) {
      s += fmt::format("{0} offsetgen_check_wall{1}(const {0}* p);\n", t, fs);
      s += fmt::format("{0} offsetgen_check_wall{1}(const {0}* p) {{ return {2}_wall{1}({3}); }}\n", t, fs, p, args);
    }
    for (const char* f : {"density", "thickness_for_density", "network_density", "offset_for_density"}) {
      s += fmt::format("{0} offsetgen_check_{1}{2}({0} v);\n", t, f, fs);
      s += fmt::format("{0} offsetgen_check_{1}{2}({0} v) {{ return {3}_{1}{2}(v); }}\n", t, f, fs, p);
    }
  };
  if (meta.has_double && meta.has_density) emit_density("double", "");
  if (meta.has_float) emit("float", "f");
  if (meta.has_float && meta.has_density) emit_density("float", "f");
  s += "#ifdef __cplusplus\n}\n#endif\n";
  return s;
}

CompileResult compile_and_load(const std::string& header_path, const FileMetadata& meta, const Toolchain& tools,
                               const CompileOptions& options) {
  CompileResult result;
  ScratchDir scratch("offsetgen-check");
  const fs::path header = fs::absolute(header_path);
  const std::string include_dir = header.parent_path().string();
  std::string include_name = header.filename().string();
  if (include_name.find_first_of("\"\\\n") != std::string::npos) {  // cannot be spelled in #include "..."
    fs::copy_file(header, scratch.path() / "checked_header.h");
    include_name = "checked_header.h";
  }
  const fs::path source = scratch.path() / "offsetgen_check_wrapper.c";
  const fs::path library = scratch.path() / "offsetgen_check_wrapper.so";
  bool batch = false;
  {
    std::ifstream in(header, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    batch = text.find(meta.prefix + "_offset_n(") != std::string::npos;
  }
  {
    std::ofstream out(source);
    out << wrapper_source(include_name, meta, batch);
    if (!out) throw std::runtime_error("cannot write " + source.string());
  }

  // Optimisation: -O2 as users build, except for very large functions (order >= 7), where gcc -O2
  // needs minutes while -O0 gives the same IEEE results (no -ffast-math, no contraction) in seconds.
  int largest = 0;
  for (const auto& [name, ops] : meta.ops) largest = std::max(largest, ops);
  const std::string opt =
      !options.optimization.empty() ? options.optimization : (largest > kLargeFunctionOps ? "-O0" : "-O2");
  result.optimization = opt;
  if (opt == "-O0" && options.optimization.empty())
    result.note =
        fmt::format("built at -O0: the largest function has {} ops (gcc -O2 takes minutes at this size)", largest);

  // 1. Strict C99; this step also builds the shared object that gets loaded. 2. Strict C++17
  // (compiled, not linked). The two run in parallel.
  std::vector<std::string> c = tools.c;
  c.insert(c.end(), {"-std=c99"});
  c.insert(c.end(), std::begin(kStrictWarnings), std::end(kStrictWarnings));
  c.insert(c.end(), {opt, "-ffp-contract=off", "-fPIC", "-shared", "-I" + include_dir, "-I" + scratch.path().string(),
                     source.string(), "-o", library.string(), "-lm"});
  auto c_step = std::async(std::launch::async, [c] { return run_step("C99 strict + shared object", c); });
  CompileStep cxx_step;
  if (tools.cxx.empty() || !options.cxx) {
    CompileStep skipped;
    skipped.name = "C++17 strict";
    skipped.skipped = true;
    skipped.ok = true;
    skipped.output = options.cxx ? "no C++ compiler on PATH (looked for $CXX, c++, g++, clang++): C++17 check skipped"
                                 : "not requested";
    cxx_step = skipped;
  } else {
    std::vector<std::string> cxx = tools.cxx;
    cxx.insert(cxx.end(), {"-std=c++17"});
    cxx.insert(cxx.end(), std::begin(kStrictWarnings), std::end(kStrictWarnings));
    cxx.insert(cxx.end(), {opt, "-I" + include_dir, "-I" + scratch.path().string(), "-x", "c++", "-c", source.string(),
                           "-o", (scratch.path() / "cxx17.o").string()});
    cxx_step = run_step("C++17 strict", cxx);
  }
  result.steps.push_back(c_step.get());
  result.steps.push_back(cxx_step);
  const bool ok = result.steps[0].ok && result.steps[1].ok;
  if (!result.steps.front().ok) return result;

  // 3. Load.
  CompileStep load;
  load.name = "dlopen";
  void* handle = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* err = ::dlerror();
    load.output = err ? err : "dlopen failed";
    result.steps.push_back(load);
    return result;
  }
  LoadedFunctions f;
  f.dims = meta.dims;
  if (meta.has_double) {
    f.field = symbol<decltype(f.field)>(handle, "offsetgen_check_field");
    f.offset = symbol<decltype(f.offset)>(handle, "offsetgen_check_offset");
    f.shell = symbol<decltype(f.shell)>(handle, "offsetgen_check_shell");
    f.normal = symbol<decltype(f.normal)>(handle, "offsetgen_check_normal");
    if (meta.has_graded()) f.graded = symbol<decltype(f.graded)>(handle, "offsetgen_check_graded");
    if (meta.has_density) {
      if (meta.wall_density) f.wall = symbol<decltype(f.wall)>(handle, "offsetgen_check_wall");
      f.density = symbol<decltype(f.density)>(handle, "offsetgen_check_density");
      f.thickness_for_density =
          symbol<decltype(f.thickness_for_density)>(handle, "offsetgen_check_thickness_for_density");
      f.network_density = symbol<decltype(f.network_density)>(handle, "offsetgen_check_network_density");
      f.offset_for_density = symbol<decltype(f.offset_for_density)>(handle, "offsetgen_check_offset_for_density");
    }
    if (batch) {
      f.offset_n = symbol<decltype(f.offset_n)>(handle, "offsetgen_check_offset_n");
      f.shell_n = symbol<decltype(f.shell_n)>(handle, "offsetgen_check_shell_n");
    }
  }
  if (meta.has_float) {
    f.fieldf = symbol<decltype(f.fieldf)>(handle, "offsetgen_check_fieldf");
    f.offsetf = symbol<decltype(f.offsetf)>(handle, "offsetgen_check_offsetf");
    f.shellf = symbol<decltype(f.shellf)>(handle, "offsetgen_check_shellf");
    f.normalf = symbol<decltype(f.normalf)>(handle, "offsetgen_check_normalf");
    if (meta.has_graded()) f.gradedf = symbol<decltype(f.gradedf)>(handle, "offsetgen_check_gradedf");
    if (meta.has_density) {
      f.densityf = symbol<decltype(f.densityf)>(handle, "offsetgen_check_densityf");
      f.thickness_for_densityf =
          symbol<decltype(f.thickness_for_densityf)>(handle, "offsetgen_check_thickness_for_densityf");
      f.network_densityf = symbol<decltype(f.network_densityf)>(handle, "offsetgen_check_network_densityf");
      f.offset_for_densityf = symbol<decltype(f.offset_for_densityf)>(handle, "offsetgen_check_offset_for_densityf");
    }
    if (batch) {
      f.offsetf_n = symbol<decltype(f.offsetf_n)>(handle, "offsetgen_check_offsetf_n");
      f.shellf_n = symbol<decltype(f.shellf_n)>(handle, "offsetgen_check_shellf_n");
    }
  }
  result.library = std::make_unique<LoadedLibrary>(handle, f);
  load.ok = true;
  load.output = library.filename().string() + " loaded";
  result.steps.push_back(load);
  result.ok = ok;
  return result;
}

}  // namespace offsetgen::check
