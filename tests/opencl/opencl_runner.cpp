#include "opencl_runner.h"

#include <fmt/format.h>

#include <stdexcept>

namespace offsetgen::test {
namespace {

void check(cl_int status, const char* call) {
  if (status != CL_SUCCESS) throw std::runtime_error(fmt::format("OpenCL: {} failed with error {}", call, status));
}

std::string platform_info(cl_platform_id platform, cl_platform_info what) {
  size_t size = 0;
  check(clGetPlatformInfo(platform, what, 0, nullptr, &size), "clGetPlatformInfo");
  std::string text(size, '\0');
  check(clGetPlatformInfo(platform, what, size, text.data(), nullptr), "clGetPlatformInfo");
  return text.c_str();
}

std::string device_info(cl_device_id device, cl_device_info what) {
  size_t size = 0;
  check(clGetDeviceInfo(device, what, 0, nullptr, &size), "clGetDeviceInfo");
  std::string text(size, '\0');
  check(clGetDeviceInfo(device, what, size, text.data(), nullptr), "clGetDeviceInfo");
  return text.c_str();
}

}  // namespace

OpenclProgram::OpenclProgram(const std::string& source, const std::string& options) {
  cl_uint platforms = 0;
  if (clGetPlatformIDs(0, nullptr, &platforms) != CL_SUCCESS || platforms == 0)
    throw std::runtime_error(
        "OpenCL: no platform (Debian: pocl-opencl-icd ocl-icd-opencl-dev; run tools/install_deps.sh; `clinfo -l` "
        "lists what the ICD loader finds)");
  cl_platform_id platform = nullptr;
  check(clGetPlatformIDs(1, &platform, nullptr), "clGetPlatformIDs");
  platform_name_ = platform_info(platform, CL_PLATFORM_NAME);
  check(clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 1, &device_, nullptr), "clGetDeviceIDs");
  device_name_ = device_info(device_, CL_DEVICE_NAME);
  has_fp64_ = device_info(device_, CL_DEVICE_EXTENSIONS).find("cl_khr_fp64") != std::string::npos;
  cl_int status = CL_SUCCESS;
  context_ = clCreateContext(nullptr, 1, &device_, nullptr, nullptr, &status);
  check(status, "clCreateContext");
  queue_ = clCreateCommandQueue(context_, device_, 0, &status);
  check(status, "clCreateCommandQueue");
  const char* text = source.c_str();
  program_ = clCreateProgramWithSource(context_, 1, &text, nullptr, &status);
  check(status, "clCreateProgramWithSource");
  const cl_int built = clBuildProgram(program_, 1, &device_, options.c_str(), nullptr, nullptr);
  size_t size = 0;
  clGetProgramBuildInfo(program_, device_, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size);
  std::string log(size, '\0');
  clGetProgramBuildInfo(program_, device_, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
  build_log_ = log.c_str();
  if (built != CL_SUCCESS)
    throw std::runtime_error(
        fmt::format("OpenCL: clBuildProgram ({}) failed with error {}:\n{}", options, built, build_log_));
}

OpenclProgram::~OpenclProgram() {
  if (program_) clReleaseProgram(program_);
  if (queue_) clReleaseCommandQueue(queue_);
  if (context_) clReleaseContext(context_);
}

void OpenclProgram::run(const std::string& name, size_t global_size, std::vector<KernelArg>& args) const {
  cl_int status = CL_SUCCESS;
  cl_kernel kernel = clCreateKernel(program_, name.c_str(), &status);
  check(status, ("clCreateKernel " + name).c_str());
  std::vector<cl_mem> buffers(args.size(), nullptr);
  try {
    for (size_t i = 0; i < args.size(); ++i) {
      KernelArg& a = args[i];
      if (a.kind == KernelArg::Scalar) {
        check(clSetKernelArg(kernel, static_cast<cl_uint>(i), a.bytes.size(), a.bytes.data()), "clSetKernelArg");
        continue;
      }
      const cl_mem_flags flags =
          a.kind == KernelArg::Input ? CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR : CL_MEM_WRITE_ONLY;
      buffers[i] = clCreateBuffer(context_, flags, a.bytes.size(),
                                  a.kind == KernelArg::Input ? a.bytes.data() : nullptr, &status);
      check(status, "clCreateBuffer");
      check(clSetKernelArg(kernel, static_cast<cl_uint>(i), sizeof(cl_mem), &buffers[i]), "clSetKernelArg");
    }
    check(clEnqueueNDRangeKernel(queue_, kernel, 1, nullptr, &global_size, nullptr, 0, nullptr, nullptr),
          ("clEnqueueNDRangeKernel " + name).c_str());
    for (size_t i = 0; i < args.size(); ++i)
      if (args[i].kind == KernelArg::Output)
        check(clEnqueueReadBuffer(queue_, buffers[i], CL_TRUE, 0, args[i].bytes.size(), args[i].bytes.data(), 0,
                                  nullptr, nullptr),
              "clEnqueueReadBuffer");
    check(clFinish(queue_), "clFinish");
  } catch (...) {
    for (cl_mem b : buffers)
      if (b) clReleaseMemObject(b);
    clReleaseKernel(kernel);
    throw;
  }
  for (cl_mem b : buffers)
    if (b) clReleaseMemObject(b);
  clReleaseKernel(kernel);
}

}  // namespace offsetgen::test
