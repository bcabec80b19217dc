// HLSL snippets: glslang's HLSL front end (-D -V) turns one compute shader per function into SPIR-V,
// which runs on Mesa's lavapipe, Vulkan on the CPU (vulkan_compute.h), in float32.
#include "run/process.h"
#include "run/runner.h"
#include "surfaces/input_error.h"
#ifdef OFFSETGEN_RUN_HAVE_VULKAN
#include "run/vulkan_compute.h"
#endif

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <memory>

namespace offsetgen::run {
namespace {

namespace fs = std::filesystem;

// The functions every shader file has, and _graded where the file was made with a thickness.
std::vector<std::string> evaluated_functions(const FileMetadata& meta) {
  std::vector<std::string> functions = {"field", "offset", "shell", "normal"};
  if (meta.thickness) functions.push_back("graded");
  return functions;
}

// One point in, one float4 out: the function's value, or its normal, padded with zeros.
std::string compute_shader(const std::string& snippet, const FileMetadata& meta, const std::string& function) {
  const std::string call = shader_call(meta, function, "p.xyz", "p.w", "p.xy", "p.z");
  const std::string value =
      function != "normal" ? call + ", 0.0, 0.0, 0.0" : call + (meta.dims == 3 ? ", 0.0" : ", 0.0, 0.0");
  return fmt::format(
      "{}\n[[vk::binding(0, 0)]] StructuredBuffer<float4> offsetgen_in;\n"
      "[[vk::binding(1, 0)]] RWStructuredBuffer<float4> offsetgen_out;\n"
      "[numthreads(64, 1, 1)]\n"
      "void main(uint3 id : SV_DispatchThreadID)\n{{\n"
      "    float4 p = offsetgen_in[id.x];\n"
      "    offsetgen_out[id.x] = float4({});\n}}\n",
      snippet, value);
}

// The SPIR-V of each function's shader, kept in a scratch directory for the lane.
struct Modules {
  ScratchDir dir{"offsetgen-hlsl"};
  std::map<std::string, fs::path> spirv;
};

CompileStep compile_to_spirv(const std::string& glslang, const std::string& snippet, const FileMetadata& meta,
                             const std::string& function, Modules& modules) {
  const fs::path shader = modules.dir.path() / (function + ".hlsl"), module = modules.dir.path() / (function + ".spv");
  std::ofstream(shader) << compute_shader(snippet, meta, function);
  CompileStep step =
      run_step(fmt::format("{}_{} -> SPIR-V", meta.prefix, function),
               {glslang, "-D", "-V", "-S", "comp", "-e", "main", "-o", module.string(), shader.string()});
  if (step.ok) modules.spirv[function] = module;
  return step;
}

#ifdef OFFSETGEN_RUN_HAVE_VULKAN
Lane lavapipe_lane(std::shared_ptr<Modules> modules, const FileMetadata& meta) {
  Lane lane;
  lane.label = "hlsl";
  lane.graded = meta.thickness.has_value();
  lane.evaluate = [modules](const std::string& function, const std::vector<Sample>& points, int components) {
    const std::vector<std::array<float, 4>> inputs = narrowed(points);
    const vulkan::ComputeRun run =
        vulkan::run_on_lavapipe(vulkan::read_spirv(modules->spirv.at(function).string()), inputs, 1);
    std::vector<double> values;
    for (size_t i = 0; i < points.size(); ++i)
      for (int k = 0; k < components; ++k) values.push_back(run.outputs[4 * i + static_cast<size_t>(k)]);
    return values;
  };
  return lane;
}
#endif

class HlslRunner final : public Runner {
 public:
  std::string backend() const override { return "hlsl"; }
  std::string how() const override { return "glslang makes SPIR-V of it, then Mesa lavapipe runs it"; }
  ValueWords words() const override {
    return {"values on lavapipe", "the shader on Mesa lavapipe (Vulkan compute, float32)", "cannot run the shader"};
  }

  Prepared prepare(const std::string&, const std::string& text, const FileMetadata& meta,
                   const ProgressFn& progress) const override {
    const std::string glslang = find_on_path("glslangValidator");
    if (glslang.empty())
      throw ToolMissing(
          "glslangValidator is not on PATH: an HLSL snippet is checked by compiling it to SPIR-V with glslang's "
          "HLSL front end (Debian: apt-get install glslang-tools)");
    Prepared p;
    p.listing = Listing::Shader;
    p.heading = "HLSL compile (glslangValidator -D -V -S comp, a compute shader per function)";
    p.json_key = "hlsl_compile";
    progress("compile", "glslang: HLSL to SPIR-V");
    auto modules = std::make_shared<Modules>();
    for (const std::string& function : evaluated_functions(meta))
      p.steps.push_back(compile_to_spirv(glslang, text, meta, function, *modules));
    Outcome compiled = compile_outcome(p.steps);
    compiled.name = "glslang HLSL";
    p.outcomes.push_back(compiled);
    p.ready = compiled.pass;
#ifdef OFFSETGEN_RUN_HAVE_VULKAN
    if (p.ready) p.lanes.push_back(lavapipe_lane(modules, meta));
#else
    p.cannot_run =
        "this offsetgen was built without the Vulkan loader, so it cannot run HLSL (Debian: libvulkan-dev "
        "mesa-vulkan-drivers; rebuild)";
#endif
    return p;
  }
};

}  // namespace

const Runner& hlsl_runner() {
  static const HlslRunner instance;
  return instance;
}

}  // namespace offsetgen::run
