#include "run/c_library.h"

#include "run/process.h"
#include "surfaces/input_error.h"
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
#include <stdexcept>
#include <type_traits>

namespace offsetgen::run {
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
    throw ToolMissing(
        fmt::format("no {} on PATH (looked for {}; set ${} to choose one). `offsetgen check` compiles "
                    "the header with the system compiler; install one with `apt-get install gcc`.",
                    what, tried, env));
  }
  return {};
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

SharedObject::SharedObject(const std::string& path) : handle_(::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
  if (handle_ == nullptr) {
    const char* error = ::dlerror();
    throw std::runtime_error(error ? error : "dlopen failed");
  }
}

SharedObject::~SharedObject() { ::dlclose(handle_); }

void* SharedObject::address(const std::string& name) const { return ::dlsym(handle_, name.c_str()); }

std::unique_ptr<SharedObject> build_shared_object(const Toolchain& tools, const std::vector<std::string>& flags,
                                                  const std::string& source, const std::string& library) {
  std::vector<std::string> command = tools.c;
  command.insert(command.end(), flags.begin(), flags.end());
  command.insert(command.end(), {"-std=c99", "-ffp-contract=off", "-fPIC", "-shared", source, "-o", library, "-lm"});
  const ProcessResult compiled = run_process(command);
  if (!compiled.started || compiled.exit_code != 0)
    throw std::runtime_error(fmt::format("compiling {} failed ({}):\n{}", source, command.front(), compiled.output));
  return std::make_unique<SharedObject>(library);
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
        const std::string params =
            fmt::format("size_t n, const {0}* x, const {0}* y, const {0}* z, const {0}* v, {0}* out", t);
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

namespace {

// The header as the wrapper includes it: its own directory and name, or a copy in `scratch` when the
// name cannot be spelled in #include "...".
struct StagedHeader {
  std::string include_dir, include_name;
  bool batch = false;  // it has the _n batch functions
};

StagedHeader stage_header(const std::string& header_path, const FileMetadata& meta, const fs::path& scratch) {
  const fs::path header = fs::absolute(header_path);
  StagedHeader staged{header.parent_path().string(), header.filename().string(), false};
  if (staged.include_name.find_first_of("\"\\\n") != std::string::npos) {
    fs::copy_file(header, scratch / "checked_header.h");
    staged.include_name = "checked_header.h";
  }
  std::ifstream in(header, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  staged.batch = text.find(meta.prefix + "_offset_n(") != std::string::npos;
  return staged;
}

// -O2 as users build, except for very large functions (order >= 7), where gcc -O2 needs minutes while
// -O0 gives the same IEEE results (no -ffast-math, no contraction) in seconds.
void choose_optimization(const FileMetadata& meta, const CompileOptions& options, CompileResult& result) {
  int largest = 0;
  for (const auto& [name, ops] : meta.ops) largest = std::max(largest, ops);
  result.optimization =
      !options.optimization.empty() ? options.optimization : (largest > kLargeFunctionOps ? "-O0" : "-O2");
  if (result.optimization == "-O0" && options.optimization.empty())
    result.note =
        fmt::format("built at -O0: the largest function has {} ops (gcc -O2 takes minutes at this size)", largest);
}

// Strict C++17 (compiled, not linked), or a skipped step saying why not.
CompileStep strict_cxx_step(const Toolchain& tools, const CompileOptions& options, const std::string& opt,
                            const std::vector<std::string>& includes, const fs::path& source, const fs::path& object) {
  if (tools.cxx.empty() || !options.cxx) {
    CompileStep skipped;
    skipped.name = "C++17 strict";
    skipped.skipped = true;
    skipped.ok = true;
    skipped.output = options.cxx ? "no C++ compiler on PATH (looked for $CXX, c++, g++, clang++): C++17 check skipped"
                                 : "not requested";
    return skipped;
  }
  std::vector<std::string> cxx = tools.cxx;
  cxx.insert(cxx.end(), {"-std=c++17"});
  cxx.insert(cxx.end(), std::begin(kStrictWarnings), std::end(kStrictWarnings));
  cxx.push_back(opt);
  cxx.insert(cxx.end(), includes.begin(), includes.end());
  cxx.insert(cxx.end(), {"-x", "c++", "-c", source.string(), "-o", object.string()});
  return run_step("C++17 strict", cxx);
}

// The wrapper's exports, one per function the metadata promises (null where the file lacks one).
LoadedFunctions exported_functions(const SharedObject& so, const FileMetadata& meta, bool batch) {
  LoadedFunctions f;
  f.dims = meta.dims;
  auto get = [&so](auto& member, const char* name) {
    member = so.symbol<std::remove_reference_t<decltype(member)>>(std::string("offsetgen_check_") + name);
  };
  if (meta.has_double) {
    get(f.field, "field"), get(f.offset, "offset"), get(f.shell, "shell"), get(f.normal, "normal");
    if (meta.has_graded()) get(f.graded, "graded");
    if (meta.has_density) {
      if (meta.wall_density) get(f.wall, "wall");
      get(f.density, "density"), get(f.thickness_for_density, "thickness_for_density");
      get(f.network_density, "network_density"), get(f.offset_for_density, "offset_for_density");
    }
    if (batch) get(f.offset_n, "offset_n"), get(f.shell_n, "shell_n");
  }
  if (meta.has_float) {
    get(f.fieldf, "fieldf"), get(f.offsetf, "offsetf"), get(f.shellf, "shellf"), get(f.normalf, "normalf");
    if (meta.has_graded()) get(f.gradedf, "gradedf");
    if (meta.has_density) {
      get(f.densityf, "densityf"), get(f.thickness_for_densityf, "thickness_for_densityf");
      get(f.network_densityf, "network_densityf"), get(f.offset_for_densityf, "offset_for_densityf");
    }
    if (batch) get(f.offsetf_n, "offsetf_n"), get(f.shellf_n, "shellf_n");
  }
  return f;
}

}  // namespace

CompileResult compile_and_load(const std::string& header_path, const FileMetadata& meta, const Toolchain& tools,
                               const CompileOptions& options) {
  CompileResult result;
  ScratchDir scratch("offsetgen-check");
  const StagedHeader header = stage_header(header_path, meta, scratch.path());
  const fs::path source = scratch.path() / "offsetgen_check_wrapper.c";
  const fs::path library = scratch.path() / "offsetgen_check_wrapper.so";
  {
    std::ofstream out(source);
    out << wrapper_source(header.include_name, meta, header.batch);
    if (!out) throw std::runtime_error("cannot write " + source.string());
  }
  choose_optimization(meta, options, result);
  const std::string& opt = result.optimization;
  const std::vector<std::string> includes = {"-I" + header.include_dir, "-I" + scratch.path().string()};

  // 1. Strict C99; this step also builds the shared object that gets loaded. 2. Strict C++17. In parallel.
  std::vector<std::string> c = tools.c;
  c.insert(c.end(), {"-std=c99"});
  c.insert(c.end(), std::begin(kStrictWarnings), std::end(kStrictWarnings));
  c.insert(c.end(), {opt, "-ffp-contract=off", "-fPIC", "-shared"});
  c.insert(c.end(), includes.begin(), includes.end());
  c.insert(c.end(), {source.string(), "-o", library.string(), "-lm"});
  auto c_step = std::async(std::launch::async, [c] { return run_step("C99 strict + shared object", c); });
  const CompileStep cxx_step = strict_cxx_step(tools, options, opt, includes, source, scratch.path() / "cxx17.o");
  result.steps.push_back(c_step.get());
  result.steps.push_back(cxx_step);
  if (!result.steps.front().ok) return result;

  // 3. Load.
  CompileStep load;
  load.name = "dlopen";
  std::unique_ptr<SharedObject> object;
  try {
    object = std::make_unique<SharedObject>(library.string());
  } catch (const std::runtime_error& e) {
    load.output = e.what();
    result.steps.push_back(load);
    return result;
  }
  const LoadedFunctions functions = exported_functions(*object, meta, header.batch);
  result.library = std::make_unique<LoadedLibrary>(std::move(object), functions);
  load.ok = true;
  load.output = library.filename().string() + " loaded";
  result.steps.push_back(load);
  result.ok = result.steps[0].ok && result.steps[1].ok;
  return result;
}

}  // namespace offsetgen::run
