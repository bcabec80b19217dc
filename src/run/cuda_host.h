// Running a generated CUDA header (<prefix>.cuh) for `offsetgen check`: nvcc compiles a small host
// program that includes it and calls its __host__ __device__ functions on the CPU (the host path; no
// GPU is needed), one function over points read from a float64 file. Results go back through float64
// files, so no digit is lost on the way (a float result is exact in double).
#pragma once

#include "run/c_library.h"
#include "run/metadata.h"
#include "run/process.h"

#include <array>
#include <string>
#include <vector>

namespace offsetgen::run::cuda {

// $NVCC, else nvcc on PATH, $CUDA_PATH/bin/nvcc, /usr/local/cuda/bin/nvcc; "" when there is none.
std::string find_nvcc();

// "/usr/local/cuda/bin/nvcc (CUDA 12.4)". Throws std::runtime_error naming what is missing and how to
// check the same generation instead (its C header) when `nvcc` is "" or does not run.
std::string describe_nvcc(const std::string& nvcc, const FileMetadata& meta);

// The host program's source: includes `include_name`, runs one function named on its command line.
std::string host_source(const std::string& include_name, const FileMetadata& meta);

class HostProgram {
 public:
  // Compiles the host program for `header_path` with `nvcc` (warnings as errors, host and device
  // front end). Compiler failures come back in step(), never as exceptions.
  HostProgram(const std::string& nvcc, const std::string& header_path, const FileMetadata& meta);
  const CompileStep& step() const { return step_; }
  bool ok() const { return step_.ok; }

  // <prefix>_<function> ("offset", "normalf", ...) at each input (x, y, z, h|t) or (x, y, h|t, 0);
  // returns inputs.size() * components values, point-major. Throws std::runtime_error when it fails.
  std::vector<double> run(const std::string& function, const std::vector<std::array<double, 4>>& inputs,
                          int components) const;

 private:
  ScratchDir dir_{"offsetgen-cuda"};
  CompileStep step_;
};

}  // namespace offsetgen::run::cuda
