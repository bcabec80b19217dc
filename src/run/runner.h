// The "run generated code" stage: what turns a generated file into callable code. One Runner per
// target that can be executed on this machine (runners/<backend>.cpp), found by the backend's name
// (runner_registry.cpp) the way the emitters are found in emit/backend_registry.cpp. `offsetgen
// check` prepares a file through its runner and judges what the runner's lanes return; `offsetgen
// mesh` loads its C header through c_library.h, the C runner's loader.
#pragma once

#include "run/c_library.h"
#include "run/metadata.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::run {

// One evaluation point: (x, y, z, h|t) in 3D, (x, y, h|t, 0) in 2D.
using Sample = std::array<double, 4>;

// One precision of a prepared file, evaluated over many points at once. `function` is "field",
// "offset", "shell", "normal" or "graded" (the lane adds its suffix); the result holds
// points.size() * components values, point-major. A float lane is given points that are exact floats
// and returns exact float values. Throws std::runtime_error when the code cannot run.
struct Lane {
  std::string label;     // names the report's rows "<label> <function><suffix>": "glsl", "cuda"
  std::string suffix;    // the file's own suffix for this precision: "" or "f"
  bool is_float = true;  // judged against the float32 limits, else the double ones
  bool graded = false;   // the file has _graded
  std::function<std::vector<double>(const std::string& function, const std::vector<Sample>& points, int components)>
      evaluate;
};

// How the report lists a preparation's steps; each runner picks the layout that fits its toolchain.
enum class Listing {
  Compile,  // "1. Compile (<toolchain>)", each step timed; a failure with its command and output
  Shader,   // "<heading>:", each step ok or FAILED; a failure with its log
  Import,   // "1. Import (<toolchain>)", no steps
};

// One judged result of the preparation ("compile", "import", "glslang GLSL ES 3.00 (fragment)").
struct Outcome {
  std::string name;
  bool pass = false;
  std::string detail;
};

// What preparing a file gave: what ran, what it said, and the code to evaluate, or why there is none.
struct Prepared {
  Listing listing = Listing::Compile;
  std::string heading;    // the Shader listing's heading
  std::string json_key;   // where report_json puts the steps: "compile", "glsl_compile", "python"
  std::string toolchain;  // "/usr/bin/cc (from PATH)", "/usr/bin/python3 with NumPy 1.24.2"
  std::vector<CompileStep> steps;
  std::string optimization;  // "-O2" or "-O0" (Compile listing)
  std::string note;          // why -O0, when it is
  std::vector<Outcome> outcomes;
  std::vector<std::string> warnings;
  bool ready = false;  // prepared without failure: its values can be judged
  std::vector<Lane> lanes;
  std::unique_ptr<LoadedLibrary> library;  // code loaded into this process (C): the thickness,
                                           // Lipschitz and density studies call it
  std::optional<std::string> cannot_run;   // ready, but this build cannot evaluate it: why
};

// The words the report uses for a target's value check.
struct ValueWords {
  std::string verdict;  // "values on llvmpipe"
  std::string source;   // "the snippet on Mesa llvmpipe (float32)"
  std::string failure;  // "cannot run the snippet"
};

using ProgressFn = std::function<void(const std::string& stage, const std::string& what)>;

class Runner {
 public:
  virtual ~Runner() = default;
  virtual std::string backend() const = 0;  // the Backend::name() whose files it runs
  virtual std::string how() const = 0;      // how it runs here, for `check --help`: "nvcc compiles it ..."
  virtual ValueWords words() const = 0;
  // Whether the code is loaded into this process (C headers): check then also measures the wall
  // thickness, the Lipschitz bounds and the densities through Prepared::library.
  virtual bool loads_in_process() const { return false; }
  // Compiles, loads or launches the file at `path` (its text and metadata given). Throws InputError
  // only for what the user must fix first (no C compiler, no glslangValidator); every other failure
  // comes back in Prepared as a failed outcome.
  virtual Prepared prepare(const std::string& path, const std::string& text, const FileMetadata& meta,
                           const ProgressFn& progress) const = 0;
};

// Every runner, in the backend registry's order of their backends.
const std::vector<const Runner*>& runners();

// The runner of the backend named `backend_name`, or nullptr when its files cannot be run.
const Runner* find_runner(const std::string& backend_name);

// The "compile" outcome of a list of steps: "name: ok; name: FAILED (first line of its output)".
Outcome compile_outcome(const std::vector<CompileStep>& steps);

// A lane's float inputs, and its float results widened to double (both exact).
std::vector<std::array<float, 4>> narrowed(const std::vector<Sample>& points);
std::vector<double> widened(const std::vector<float>& values);

// "offset" -> "gyroid_o4_offset(p.xyz, p.w)": the call a shader makes for one function, where `point`
// reads the point ("p.xyz") and `distance` h or t ("p.w"); `point2`/`distance2` are the 2D forms.
std::string shader_call(const FileMetadata& meta, const std::string& function, const std::string& point3,
                        const std::string& distance3, const std::string& point2, const std::string& distance2);

}  // namespace offsetgen::run
