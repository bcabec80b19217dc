// GLSL snippets: glslangValidator for the four host dialects (glsl_compile.h), then the functions on
// Mesa llvmpipe through headless EGL (glsl_executor.h), in float32.
#include "run/glsl_compile.h"
#include "run/runner.h"
#ifdef OFFSETGEN_RUN_HAVE_GL
#include "run/glsl_executor.h"
#endif

namespace offsetgen::run {
namespace {

std::vector<Outcome> target_outcomes(const std::vector<GlslCompileResult>& compiled) {
  std::vector<Outcome> outcomes;
  for (const auto& r : compiled)
    outcomes.push_back({"glslang " + r.name, r.ok, r.ok ? "compiles and links" : "does not compile"});
  return outcomes;
}

CompileStep as_step(const GlslCompileResult& r) {
  CompileStep step;
  step.name = r.name;
  step.command = r.command;
  step.ok = r.ok;
  step.output = r.output;
  return step;
}

#ifdef OFFSETGEN_RUN_HAVE_GL
// The snippet's functions in a GL 4.3 compute shader: p is (x, y, z, h|t) or (x, y, h|t, 0).
Lane llvmpipe_lane(const std::string& snippet, const FileMetadata& meta) {
  Lane lane;
  lane.label = "glsl";
  lane.graded = meta.thickness.has_value();
  lane.evaluate = [snippet, meta](const std::string& function, const std::vector<Sample>& points, int components) {
    const std::string call = shader_call(meta, function, "p.xyz", "p.w", "p.xy", "p.z");
    return widened(glsl::run(glsl::Path::Compute, snippet, call, narrowed(points), components));
  };
  return lane;
}
#endif

class GlslRunner final : public Runner {
 public:
  std::string backend() const override { return "glsl"; }
  std::string how() const override { return "glslang compiles it, then Mesa llvmpipe runs it"; }
  ValueWords words() const override {
    return {"values on llvmpipe", "the snippet on Mesa llvmpipe (float32)", "cannot run the snippet"};
  }

  Prepared prepare(const std::string& path, const std::string& text, const FileMetadata& meta,
                   const ProgressFn&) const override {
    Prepared p;
    p.listing = Listing::Shader;
    p.heading = "GLSL compile (glslangValidator -l, host fragment shader calling every function)";
    p.json_key = "glsl_compile";
    const std::vector<GlslCompileResult> compiled = compile_glsl(text, meta, path);  // InputError: no glslang
    p.outcomes = target_outcomes(compiled);
    p.ready = true;
    for (const auto& r : compiled) {
      p.steps.push_back(as_step(r));
      p.ready = p.ready && r.ok;
    }
#ifdef OFFSETGEN_RUN_HAVE_GL
    if (p.ready) p.lanes.push_back(llvmpipe_lane(text, meta));
#else
    p.cannot_run =
        "this offsetgen was built without EGL, so it cannot run GLSL (Debian: libegl-dev libgl1-mesa-dri; rebuild)";
#endif
    return p;
  }
};

}  // namespace

const Runner& glsl_runner() {
  static const GlslRunner instance;
  return instance;
}

}  // namespace offsetgen::run
