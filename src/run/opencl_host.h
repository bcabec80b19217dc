// Running a generated OpenCL C source (<prefix>.cl) for `offsetgen check`: the system C compiler builds
// a small host program linked with the OpenCL ICD loader (-lOpenCL); it takes the first device of the
// first platform (pocl's CPU device on Debian), builds the file (-cl-std=CL1.2 -Werror) with one check
// kernel per function appended, and runs one of them over points read from a float64 file. Results go
// back as float64, so no digit is lost on the way.
#pragma once

#include "run/c_library.h"
#include "run/metadata.h"
#include "run/process.h"

#include <array>
#include <string>
#include <vector>

namespace offsetgen::run::opencl {

// The file's text followed by offsetgen_check_<function> kernels, one per function and precision (the
// double ones under #ifdef cl_khr_fp64, like the file's own).
std::string program_source(const std::string& file_text, const FileMetadata& meta);

// What the host program found when it built the source.
struct Device {
  std::string platform, name;
  bool fp64 = false;
  std::string build_log;  // the OpenCL compiler's output, empty when it said nothing
};

class HostProgram {
 public:
  // Compiles the host program with the C compiler of `tools` (never throws for compiler failures:
  // see step()).
  HostProgram(const Toolchain& tools, const std::string& file_text, const FileMetadata& meta);
  const CompileStep& step() const { return step_; }

  // Builds the source on the device. Throws std::runtime_error naming what is missing when there is
  // no OpenCL platform or device, with the build log when the source does not build.
  Device build() const;

  // offsetgen_check_<function> ("offsetf", "normal", ...) at each input (x, y, z, h|t) or
  // (x, y, h|t, 0); `real_bytes` 4 runs it in float, 8 in double. Returns inputs.size() * components
  // values, point-major. Throws std::runtime_error when it fails.
  std::vector<double> run(const std::string& function, int real_bytes, const std::vector<std::array<double, 4>>& inputs,
                          int components) const;

 private:
  ScratchDir dir_{"offsetgen-opencl"};
  CompileStep step_;
};

}  // namespace offsetgen::run::opencl
