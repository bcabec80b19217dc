// Compiling an emitted C header with the system compilers and loading it: strict C99
// (-std=c99 -pedantic -Wall -Wextra -Werror), C++17 with the same warnings, then a shared object
// opened with dlopen. Compiler output is kept verbatim for the report.
#pragma once

#include "run/metadata.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace offsetgen::run {

struct Toolchain {
  std::vector<std::string> c;    // e.g. {"/usr/bin/cc"}, or $CC split into words
  std::vector<std::string> cxx;  // empty when no C++ compiler is found
  std::string c_origin;          // "$CC" or "PATH"
  std::string cxx_origin;
};

// $CC (else cc, gcc, clang on PATH) and $CXX (else c++, g++, clang++). Throws InputError
// "no C compiler on PATH ..." when there is no C compiler, or when $CC names a missing program.
Toolchain find_toolchain();

struct CompileStep {
  std::string name;                  // "C99 strict", "C++17 strict", "shared object", "dlopen"
  std::vector<std::string> command;  // empty for dlopen
  bool ok = false;
  bool skipped = false;  // e.g. no C++ compiler
  std::string output;    // compiler output, verbatim
  double seconds = 0;
};

// Runs one compiler command through run_process (process.h), timing it; never throws.
CompileStep run_step(const std::string& name, std::vector<std::string> command);

// A batch function (_offset_n, _shell_n) through its wrapper: z is ignored in 2D.
template <typename T>
using BatchFunction = void (*)(size_t n, const T* x, const T* y, const T* z, const T* h_or_t, T* out);

// The loaded code, through exported wrappers taking the coordinates as an array (dims entries).
// Members are null where the file lacks the function (float twins, _graded, batch functions).
struct LoadedFunctions {
  int dims = 3;
  double (*field)(const double* p) = nullptr;
  double (*offset)(const double* p, double h) = nullptr;
  double (*shell)(const double* p, double t) = nullptr;
  void (*normal)(const double* p, double h, double* n) = nullptr;
  double (*graded)(const double* p) = nullptr;
  float (*fieldf)(const float* p) = nullptr;
  float (*offsetf)(const float* p, float h) = nullptr;
  float (*shellf)(const float* p, float t) = nullptr;
  void (*normalf)(const float* p, float h, float* n) = nullptr;
  float (*gradedf)(const float* p) = nullptr;
  BatchFunction<double> offset_n = nullptr, shell_n = nullptr;
  BatchFunction<float> offsetf_n = nullptr, shellf_n = nullptr;
  // With density functions (null otherwise): _wall and the relations, double and float.
  double (*wall)(const double* p) = nullptr;
  double (*density)(double t) = nullptr;
  double (*thickness_for_density)(double rho) = nullptr;
  double (*network_density)(double h) = nullptr;
  double (*offset_for_density)(double rho) = nullptr;
  float (*densityf)(float t) = nullptr;
  float (*thickness_for_densityf)(float rho) = nullptr;
  float (*network_densityf)(float h) = nullptr;
  float (*offset_for_densityf)(float rho) = nullptr;
};

// A shared object opened with dlopen (RTLD_NOW | RTLD_LOCAL), closed when this goes.
class SharedObject {
 public:
  // Throws std::runtime_error with dlerror()'s message when it cannot be opened.
  explicit SharedObject(const std::string& path);
  ~SharedObject();
  SharedObject(const SharedObject&) = delete;
  SharedObject& operator=(const SharedObject&) = delete;
  // The exported function `name`, or nullptr when there is none.
  template <typename T>
  T symbol(const std::string& name) const {
    return reinterpret_cast<T>(address(name));
  }

 private:
  void* address(const std::string& name) const;
  void* handle_;
};

// Compiles the C99 translation unit `source` into the shared object `library` with the C compiler of
// `tools` and `flags` (-fPIC -shared -ffp-contract=off -lm added), then opens it. Throws
// std::runtime_error with the compiler's output when either fails.
std::unique_ptr<SharedObject> build_shared_object(const Toolchain& tools, const std::vector<std::string>& flags,
                                                  const std::string& source, const std::string& library);

class LoadedLibrary {
 public:
  LoadedLibrary(std::unique_ptr<SharedObject> object, LoadedFunctions functions)
      : object_(std::move(object)), functions_(functions) {}
  const LoadedFunctions& functions() const { return functions_; }

 private:
  std::unique_ptr<SharedObject> object_;
  LoadedFunctions functions_;
};

// Above this many ops in one function the shared object is built at -O0 (see compile.cpp).
constexpr int kLargeFunctionOps = 5000;

struct CompileResult {
  std::vector<CompileStep> steps;
  std::string optimization;                // "-O2" or "-O0"
  std::string note;                        // why -O0, when it is
  bool ok = false;                         // every step that ran succeeded and the code is loaded
  std::unique_ptr<LoadedLibrary> library;  // set when ok
};

// The C translation unit that includes the header (twice: the include guard must hold) and exports
// one wrapper per function with unmangled names; `batch`: the header has the _n batch functions.
std::string wrapper_source(const std::string& include_name, const FileMetadata& meta, bool batch = false);

struct CompileOptions {
  std::string optimization;  // "" picks -O2, or -O0 above kLargeFunctionOps; tests force "-O0" for speed
  bool cxx = true;           // also the strict C++17 compile
};

// Compiles `header_path` (strict C99, strict C++17, shared object) in a fresh scratch directory and
// loads it. Never throws for compiler failures: they come back as failed steps.
CompileResult compile_and_load(const std::string& header_path, const FileMetadata& meta, const Toolchain& tools,
                               const CompileOptions& options = {});

}  // namespace offsetgen::run
