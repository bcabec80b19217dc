// CUDA headers: nvcc compiles a host program calling the __host__ __device__ functions on the CPU
// (cuda_host.h; no GPU needed), in double and float.
#include "run/cuda_host.h"
#include "run/runner.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <memory>
#include <stdexcept>

namespace offsetgen::run {
namespace {

// Both precisions of the host program: the float functions get exact float inputs.
std::vector<Lane> host_lanes(const std::shared_ptr<cuda::HostProgram>& program, const FileMetadata& meta) {
  Lane double_lane{"cuda", "", false, meta.has_graded(), nullptr};
  double_lane.evaluate = [program](const std::string& function, const std::vector<Sample>& points, int components) {
    return program->run(function, points, components);
  };
  Lane float_lane{"cuda", "f", true, meta.has_graded(), nullptr};
  float_lane.evaluate = [program](const std::string& function, const std::vector<Sample>& points, int components) {
    return program->run(function + "f", points, components);
  };
  return {double_lane, float_lane};
}

class CudaRunner final : public Runner {
 public:
  std::string backend() const override { return "cuda"; }
  std::string how() const override { return "nvcc compiles it and runs its host path"; }
  ValueWords words() const override {
    return {"values of the host path", "the host path compiled by nvcc (double and float)", "cannot run the functions"};
  }

  Prepared prepare(const std::string& path, const std::string&, const FileMetadata& meta,
                   const ProgressFn& progress) const override {
    Prepared p;
    p.listing = Listing::Compile;
    p.json_key = "compile";
    const std::string nvcc = cuda::find_nvcc();
    try {
      p.toolchain = cuda::describe_nvcc(nvcc, meta);
    } catch (const ToolMissing&) {
      throw;  // no nvcc: not checked, rather than failed
    } catch (const std::runtime_error& e) {
      p.outcomes.push_back({"compile", false, e.what()});
      return p;
    }
    progress("compile", "nvcc: the host path of the CUDA header");
    auto program = std::make_shared<cuda::HostProgram>(nvcc, path, meta);
    p.optimization = program->step().command.size() > 2 ? program->step().command[2] : "";
    p.steps.push_back(program->step());
    p.outcomes.push_back(compile_outcome(p.steps));
    p.ready = program->ok();
    if (!p.ready) return p;
    p.lanes = host_lanes(program, meta);
    if (meta.has_density)
      p.warnings.push_back(
          "the density relations of a cuda file are not checked (check the C header of the same generation)");
    return p;
  }
};

}  // namespace

const Runner& cuda_runner() {
  static const CudaRunner instance;
  return instance;
}

}  // namespace offsetgen::run
