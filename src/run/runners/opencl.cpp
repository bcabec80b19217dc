// OpenCL C sources: a host program on the ICD loader builds the file on the first OpenCL device
// (opencl_host.h; pocl on Debian) and runs one kernel per function, in float, and in double where the
// device has cl_khr_fp64.
#include "run/opencl_host.h"
#include "run/runner.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <stdexcept>

namespace offsetgen::run {
namespace {

// clBuildProgram as a step of its own: the device, or why there is none.
CompileStep build_on_device(const opencl::HostProgram& program, std::optional<opencl::Device>& device) {
  CompileStep build;
  build.name = "clBuildProgram";
  build.command = {"clBuildProgram", "-cl-std=CL1.2 -Werror"};
  const auto start = std::chrono::steady_clock::now();
  try {
    device = program.build();
    build.ok = true;
    build.output = device->build_log;
  } catch (const ToolMissing&) {
    throw;  // no OpenCL platform: not checked, rather than failed
  } catch (const std::runtime_error& e) {
    build.output = e.what();
  }
  build.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return build;
}

std::string describe(const Toolchain& tools, const std::optional<opencl::Device>& device, bool host_built) {
  const std::string compiler = fmt::format("{} (from {})", tools.c.front(), tools.c_origin);
  if (!host_built) return compiler;
  if (!device) return compiler + "; no OpenCL device";
  return fmt::format("{}; OpenCL: {}, device {}{}", compiler, device->platform, device->name,
                     device->fp64 ? ", cl_khr_fp64" : ", no cl_khr_fp64");
}

// The float kernels always; the double ones where the device computes in double.
std::vector<Lane> device_lanes(const std::shared_ptr<opencl::HostProgram>& program, const FileMetadata& meta,
                               bool fp64) {
  std::vector<Lane> lanes;
  if (fp64) {
    Lane double_lane{"opencl", "", false, meta.has_graded(), nullptr};
    double_lane.evaluate = [program](const std::string& function, const std::vector<Sample>& points, int components) {
      return program->run(function, 8, points, components);
    };
    lanes.push_back(double_lane);
  }
  Lane float_lane{"opencl", "f", true, meta.has_graded(), nullptr};
  float_lane.evaluate = [program](const std::string& function, const std::vector<Sample>& points, int components) {
    return program->run(function + "f", 4, points, components);
  };
  lanes.push_back(float_lane);
  return lanes;
}

class OpenclRunner final : public Runner {
 public:
  std::string backend() const override { return "opencl"; }
  std::string how() const override { return "the OpenCL ICD (pocl here) builds and runs it"; }
  ValueWords words() const override {
    return {"values on the device", "the kernels on the OpenCL device (float, and double with cl_khr_fp64)",
            "cannot run the functions"};
  }

  Prepared prepare(const std::string&, const std::string& text, const FileMetadata& meta,
                   const ProgressFn& progress) const override {
    Prepared p;
    p.listing = Listing::Compile;
    p.json_key = "compile";
    const Toolchain tools = find_toolchain();
    progress("compile", "the OpenCL host program, then the source on the device");
    auto program = std::make_shared<opencl::HostProgram>(tools, text, meta);
    p.steps.push_back(program->step());
    std::optional<opencl::Device> device;
    if (program->step().ok) p.steps.push_back(build_on_device(*program, device));
    p.toolchain = describe(tools, device, program->step().ok);
    p.outcomes.push_back(compile_outcome(p.steps));
    if (!device) return p;
    if (!device->fp64)
      p.warnings.push_back(fmt::format("{} has no cl_khr_fp64: only the float functions are checked", device->name));
    if (meta.has_density)
      p.warnings.push_back(
          "the density relations of a opencl file are not checked (check the C header of the same generation)");
    p.ready = true;
    p.lanes = device_lanes(program, meta, device->fp64);
    return p;
  }
};

}  // namespace

const Runner& opencl_runner() {
  static const OpenclRunner instance;
  return instance;
}

}  // namespace offsetgen::run
