#include "run/opencl_host.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace offsetgen::run::opencl {
namespace {

namespace fs = std::filesystem;

// The host program (C99). argv: source, then "info" (build, print platform, device, fp64 and the build
// log) or "run" kernel real-bytes points components input output (inputs 4 float64 per point).
constexpr const char* kHost = R"(#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void fail(const char *call, cl_int status) { fprintf(stderr, "%s failed with error %d\n", call, (int)status); exit(6); }

int main(int argc, char **argv)
{
  if (argc < 3) return 2;
  FILE *f = fopen(argv[1], "rb");
  if (!f) return 3;
  fseek(f, 0, SEEK_END);
  long size = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *text = calloc((size_t)size + 1, 1);
  if (fread(text, 1, (size_t)size, f) != (size_t)size) return 3;
  fclose(f);

  cl_uint platforms = 0;
  if (clGetPlatformIDs(0, NULL, &platforms) != CL_SUCCESS || platforms == 0) {
    fprintf(stderr, "no OpenCL platform: the ICD loader finds none (Debian: pocl-opencl-icd; `clinfo -l` lists them)\n");
    return 7;
  }
  cl_platform_id platform;
  cl_device_id device;
  cl_int status = clGetPlatformIDs(1, &platform, NULL);
  if (status != CL_SUCCESS) fail("clGetPlatformIDs", status);
  status = clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 1, &device, NULL);
  if (status != CL_SUCCESS) {
    fprintf(stderr, "the first OpenCL platform has no device (clGetDeviceIDs: error %d)\n", (int)status);
    return 7;
  }
  cl_context context = clCreateContext(NULL, 1, &device, NULL, NULL, &status);
  if (status != CL_SUCCESS) fail("clCreateContext", status);
  const char *sources[1] = {text};
  cl_program program = clCreateProgramWithSource(context, 1, sources, NULL, &status);
  if (status != CL_SUCCESS) fail("clCreateProgramWithSource", status);
  const cl_int built = clBuildProgram(program, 1, &device, "-cl-std=CL1.2 -Werror", NULL, NULL);
  size_t log_size = 0;
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, 0, NULL, &log_size);
  char *log = calloc(log_size + 1, 1);
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, log_size, log, NULL);
  if (built != CL_SUCCESS) {
    fprintf(stderr, "clBuildProgram (-cl-std=CL1.2 -Werror) failed with error %d:\n%s\n", (int)built, log);
    return 8;
  }
  if (strcmp(argv[2], "info") == 0) {
    char platform_name[256] = "", device_name[256] = "", *extensions;
    size_t extensions_size = 0;
    clGetPlatformInfo(platform, CL_PLATFORM_NAME, sizeof platform_name - 1, platform_name, NULL);
    clGetDeviceInfo(device, CL_DEVICE_NAME, sizeof device_name - 1, device_name, NULL);
    clGetDeviceInfo(device, CL_DEVICE_EXTENSIONS, 0, NULL, &extensions_size);
    extensions = calloc(extensions_size + 1, 1);
    clGetDeviceInfo(device, CL_DEVICE_EXTENSIONS, extensions_size, extensions, NULL);
    printf("%s\n%s\n%d\n%s", platform_name, device_name, strstr(extensions, "cl_khr_fp64") != NULL, log);
    return 0;
  }
  if (argc != 9 || strcmp(argv[2], "run") != 0) return 2;
  const size_t real = strtoul(argv[4], NULL, 10), n = strtoul(argv[5], NULL, 10), components = strtoul(argv[6], NULL, 10);
  double *in = calloc(4 * n + 1, sizeof(double)), *out = calloc(components * n + 1, sizeof(double));
  unsigned char *in_real = calloc(4 * n + 1, real), *out_real = calloc(components * n + 1, real);
  f = fopen(argv[7], "rb");
  if (!f || fread(in, sizeof(double), 4 * n, f) != 4 * n) return 3;
  fclose(f);
  for (size_t i = 0; i < 4 * n; ++i) {
    if (real == 4) ((float *)in_real)[i] = (float)in[i]; else ((double *)in_real)[i] = in[i];
  }
  cl_command_queue queue = clCreateCommandQueue(context, device, 0, &status);
  if (status != CL_SUCCESS) fail("clCreateCommandQueue", status);
  cl_kernel kernel = clCreateKernel(program, argv[3], &status);
  if (status != CL_SUCCESS) fail("clCreateKernel", status);
  cl_mem source = clCreateBuffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, 4 * n * real + real, in_real, &status);
  if (status != CL_SUCCESS) fail("clCreateBuffer", status);
  cl_mem target = clCreateBuffer(context, CL_MEM_WRITE_ONLY, components * n * real + real, NULL, &status);
  if (status != CL_SUCCESS) fail("clCreateBuffer", status);
  if ((status = clSetKernelArg(kernel, 0, sizeof source, &source)) != CL_SUCCESS) fail("clSetKernelArg", status);
  if ((status = clSetKernelArg(kernel, 1, sizeof target, &target)) != CL_SUCCESS) fail("clSetKernelArg", status);
  if (n > 0 && (status = clEnqueueNDRangeKernel(queue, kernel, 1, NULL, &n, NULL, 0, NULL, NULL)) != CL_SUCCESS)
    fail("clEnqueueNDRangeKernel", status);
  if ((status = clEnqueueReadBuffer(queue, target, CL_TRUE, 0, components * n * real, out_real, 0, NULL, NULL)) != CL_SUCCESS)
    fail("clEnqueueReadBuffer", status);
  for (size_t i = 0; i < components * n; ++i) out[i] = real == 4 ? (double)((float *)out_real)[i] : ((double *)out_real)[i];
  f = fopen(argv[8], "wb");
  if (!f || fwrite(out, sizeof(double), components * n, f) != components * n) return 5;
  return fclose(f) == 0 ? 0 : 5;
}
)";

// offsetgen_check_<name><f>(in, out): <prefix>_<name><f> at each point of `in` (4 reals per point).
std::string kernel(const FileMetadata& meta, const std::string& real, const std::string& f, const std::string& name,
                   bool with_extra) {
  const std::string point =
      meta.dims == 3 ? fmt::format("({}3)(q[0], q[1], q[2])", real) : fmt::format("({}2)(q[0], q[1])", real);
  const std::string args = with_extra ? fmt::format("{}, q[{}]", point, meta.dims) : point;
  std::string body;
  if (name == "normal") {
    body = fmt::format("    const {0}{1} v = {2}_normal{3}({4});\n", real, meta.dims, meta.prefix, f, args);
    const char* lanes = "xyz";
    for (int k = 0; k < meta.dims; ++k)
      body += fmt::format("    out[{0} * i + {1}] = v.{2};\n", meta.dims, k, lanes[k]);
  } else {
    body = fmt::format("    out[i] = {}_{}{}({});\n", meta.prefix, name, f, args);
  }
  return fmt::format(
      "__kernel void offsetgen_check_{0}{1}(__global const {2} *in, __global {2} *out)\n{{\n"
      "    const size_t i = get_global_id(0);\n    __global const {2} *q = in + 4 * i;\n{3}}}\n",
      name, f, real, body);
}

std::string kernels(const FileMetadata& meta, const std::string& real, const std::string& f) {
  std::string s = kernel(meta, real, f, "field", false) + kernel(meta, real, f, "offset", true) +
                  kernel(meta, real, f, "shell", true) + kernel(meta, real, f, "normal", true);
  if (meta.has_graded()) s += kernel(meta, real, f, "graded", false);
  return s;
}

}  // namespace

std::string program_source(const std::string& file_text, const FileMetadata& meta) {
  return file_text + "\n/* offsetgen check: one kernel per function. */\n" + kernels(meta, "float", "f") +
         "#ifdef cl_khr_fp64\n#pragma OPENCL EXTENSION cl_khr_fp64 : enable\n" + kernels(meta, "double", "") +
         "#endif\n";
}

HostProgram::HostProgram(const Toolchain& tools, const std::string& file_text, const FileMetadata& meta) {
  const fs::path host = dir_.path() / "offsetgen_check_host.c", source = dir_.path() / "program.cl";
  for (const auto& [path, text] : {std::pair{host, std::string(kHost)}, {source, program_source(file_text, meta)}}) {
    std::ofstream out(path);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  std::vector<std::string> command = tools.c;
  command.insert(command.end(), {"-std=c99", "-O2", host.string(), "-o", (dir_.path() / "host").string(), "-lOpenCL"});
  step_ = run_step("host program (-lOpenCL)", command);
  if (!step_.ok)
    step_.output +=
        "\nthe OpenCL host program needs the OpenCL headers and the ICD loader (Debian: opencl-headers "
        "ocl-icd-opencl-dev)\n";
}

Device HostProgram::build() const {
  if (!step_.ok) throw std::runtime_error("the host program did not compile");
  const ProcessResult r = run_process({(dir_.path() / "host").string(), (dir_.path() / "program.cl").string(), "info"});
  if (r.started && r.exit_code == 7) throw ToolMissing(r.output);  // no OpenCL platform or device
  if (!r.started || r.exit_code != 0) throw std::runtime_error(r.output);
  std::istringstream in(r.output);
  Device d;
  std::string fp64;
  std::getline(in, d.platform);
  std::getline(in, d.name);
  std::getline(in, fp64);
  d.fp64 = fp64 == "1";
  std::ostringstream rest;
  rest << in.rdbuf();
  d.build_log = rest.str();
  return d;
}

std::vector<double> HostProgram::run(const std::string& function, int real_bytes,
                                     const std::vector<std::array<double, 4>>& inputs, int components) const {
  return run_on_points(
      {(dir_.path() / "host").string(), (dir_.path() / "program.cl").string(), "run", "offsetgen_check_" + function,
       std::to_string(real_bytes), std::to_string(inputs.size()), std::to_string(components)},
      dir_.path(), inputs, inputs.size() * static_cast<size_t>(components));
}

}  // namespace offsetgen::run::opencl
