#include "run/runner.h"

#include "emit/backend.h"

#include <fmt/format.h>

#include <algorithm>

namespace offsetgen::run {

// Each runner file defines its one instance (run/runners/<backend>.cpp).
const Runner& c_runner();
const Runner& glsl_runner();
const Runner& hlsl_runner();
const Runner& wgsl_runner();
const Runner& cuda_runner();
const Runner& opencl_runner();
const Runner& numpy_runner();

const std::vector<const Runner*>& runners() {
  static const std::vector<const Runner*> all = {&c_runner(),    &glsl_runner(),   &hlsl_runner(), &wgsl_runner(),
                                                 &cuda_runner(), &opencl_runner(), &numpy_runner()};
  return all;
}

const Runner* find_runner(const std::string& backend_name) {
  for (const Runner* r : runners())
    if (r->backend() == backend_name) return r;
  return nullptr;
}

Outcome compile_outcome(const std::vector<CompileStep>& steps) {
  Outcome o{"compile", true, ""};
  for (const auto& step : steps) {
    const std::string why = step.output.substr(0, step.output.find('\n'));
    o.detail += fmt::format("{}{}: {}", o.detail.empty() ? "" : "; ", step.name,
                            step.ok ? "ok" : (why.empty() ? "FAILED" : "FAILED (" + why + ")"));
    o.pass = o.pass && step.ok;
  }
  return o;
}

std::vector<std::array<float, 4>> narrowed(const std::vector<Sample>& points) {
  std::vector<std::array<float, 4>> out(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t k = 0; k < 4; ++k) out[i][k] = static_cast<float>(points[i][k]);
  return out;
}

std::vector<double> widened(const std::vector<float>& values) { return {values.begin(), values.end()}; }

std::string shader_call(const FileMetadata& meta, const std::string& function, const std::string& point3,
                        const std::string& distance3, const std::string& point2, const std::string& distance2) {
  const bool with_distance = function == "offset" || function == "shell" || function == "normal";
  return fmt::format("{}_{}({}{})", meta.prefix, function, meta.dims == 3 ? point3 : point2,
                     with_distance ? ", " + (meta.dims == 3 ? distance3 : distance2) : "");
}

}  // namespace offsetgen::run
