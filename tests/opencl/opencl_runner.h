// A minimal OpenCL host for the tests: the first device of the first platform (pocl's CPU device in
// the test setup), one program built from source with the given options, kernels run over 1D ranges
// with buffer and scalar arguments. Errors throw std::runtime_error naming the call (and the build
// log when the program does not build).
#pragma once

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include <cstring>
#include <string>
#include <vector>

namespace offsetgen::test {

// One kernel argument: an input buffer (bytes copied in), an output buffer (size bytes, read back
// into `bytes`), or a scalar (bytes as is).
struct KernelArg {
  enum Kind { Input, Output, Scalar } kind;
  std::vector<unsigned char> bytes;

  template <class T>
  static KernelArg input(const std::vector<T>& values) {
    return {Input, to_bytes(values.data(), values.size() * sizeof(T))};
  }
  template <class T>
  static KernelArg output(size_t count) {
    return {Output, std::vector<unsigned char>(count * sizeof(T))};
  }
  template <class T>
  static KernelArg scalar(T value) {
    return {Scalar, to_bytes(&value, sizeof value)};
  }
  template <class T>
  std::vector<T> values() const {
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
  }

 private:
  static std::vector<unsigned char> to_bytes(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    return std::vector<unsigned char>(p, p + size);
  }
};

class OpenclProgram {
 public:
  OpenclProgram(const std::string& source, const std::string& options);
  ~OpenclProgram();
  OpenclProgram(const OpenclProgram&) = delete;
  OpenclProgram& operator=(const OpenclProgram&) = delete;

  std::string platform_name() const { return platform_name_; }
  std::string device_name() const { return device_name_; }
  bool has_fp64() const { return has_fp64_; }
  // The build log (warnings), empty when the compiler said nothing.
  const std::string& build_log() const { return build_log_; }
  // Runs `kernel` over `global_size` work items; output arguments come back filled in.
  void run(const std::string& kernel, size_t global_size, std::vector<KernelArg>& args) const;

 private:
  cl_context context_ = nullptr;
  cl_command_queue queue_ = nullptr;
  cl_program program_ = nullptr;
  cl_device_id device_ = nullptr;
  std::string platform_name_, device_name_, build_log_;
  bool has_fp64_ = false;
};

}  // namespace offsetgen::test
