// C headers: compiled as strict C99 and C++17 by the system compilers and loaded into this process
// (c_library.h), so check can also measure the wall thickness and the densities through them.
#include "run/runner.h"

#include <fmt/format.h>

namespace offsetgen::run {
namespace {

std::string describe(const Toolchain& tools) {
  std::string text = fmt::format("{} (from {})", tools.c.front(), tools.c_origin);
  if (!tools.cxx.empty()) text += fmt::format(", {} (from {})", tools.cxx.front(), tools.cxx_origin);
  return text;
}

// Every step by name: a skipped C++ compile is no failure.
Outcome steps_outcome(const CompileResult& compiled) {
  Outcome o{"compile", compiled.ok, ""};
  for (const auto& step : compiled.steps)
    o.detail += fmt::format("{}{}: {}", o.detail.empty() ? "" : "; ", step.name,
                            step.skipped ? "skipped" : (step.ok ? "ok" : "FAILED"));
  return o;
}

class CRunner final : public Runner {
 public:
  std::string backend() const override { return "c"; }
  std::string how() const override {
    return "a C compiler builds it as C99 and C++17, dlopen loads it; walls and densities too";
  }
  ValueWords words() const override { return {"values", "compiled code", "cannot run the functions"}; }
  bool loads_in_process() const override { return true; }

  Prepared prepare(const std::string& path, const std::string&, const FileMetadata& meta,
                   const ProgressFn& progress) const override {
    const Toolchain tools = find_toolchain();  // throws InputError: nothing to compile with
    Prepared p;
    p.listing = Listing::Compile;
    p.json_key = "compile";
    p.toolchain = describe(tools);
    progress("compile", "C99 strict, C++17 strict, shared object");
    CompileResult compiled = compile_and_load(path, meta, tools);
    p.outcomes.push_back(steps_outcome(compiled));
    p.steps = std::move(compiled.steps);
    p.optimization = compiled.optimization;
    p.note = compiled.note;
    p.library = std::move(compiled.library);
    p.ready = p.library != nullptr;
    return p;
  }
};

}  // namespace

const Runner& c_runner() {
  static const CRunner instance;
  return instance;
}

}  // namespace offsetgen::run
