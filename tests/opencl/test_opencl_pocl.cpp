// The generated OpenCL C sources run on pocl's CPU device: each builds with -Werror (OpenCL C 1.2);
// its batch kernels and a kernel that calls every function run on points near the zero set, and the
// values are compared with the C header's double functions as zero-set shifts (zero_set_points.h):
// within 2e-5 in float (kFloatShiftLimit, every case) and 1e-12 in double (where the device reports
// cl_khr_fp64); the unit normals within 1e-3 in float (offsetgen check's float limit) and 1e-12 in double.
#include "opencl_cases.h"
#include "opencl_runner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

namespace offsetgen::test {
namespace {

constexpr int kPoints = 2000;
constexpr double kDoubleTolerance = 1e-12;
constexpr double kFloatNormalTolerance = 1e-3, kDoubleNormalTolerance = 1e-12;
constexpr double kBatchH = 0.05;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A test kernel per precision that writes field, offset, shell(2|h|) and the normal's components for
// points (x, y, z, h); P_ stands for the prefix.
const char* kEveryFunctionKernels = R"(
__kernel void offsetgen_test_every_functionf(const ulong n, __global const float *in, __global float *out)
{
    const size_t i = get_global_id(0);
    if (i >= n) return;
    const float3 p = (float3)(in[4 * i], in[4 * i + 1], in[4 * i + 2]);
    const float h = in[4 * i + 3];
    const float3 normal = P_normalf(p, h);
    out[6 * i] = P_fieldf(p);
    out[6 * i + 1] = P_offsetf(p, h);
    out[6 * i + 2] = P_shellf(p, 2.0f * fabs(h));
    out[6 * i + 3] = normal.x;
    out[6 * i + 4] = normal.y;
    out[6 * i + 5] = normal.z;
}
#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
__kernel void offsetgen_test_every_function(const ulong n, __global const double *in, __global double *out)
{
    const size_t i = get_global_id(0);
    if (i >= n) return;
    const double3 p = (double3)(in[4 * i], in[4 * i + 1], in[4 * i + 2]);
    const double h = in[4 * i + 3];
    const double3 normal = P_normal(p, h);
    out[6 * i] = P_field(p);
    out[6 * i + 1] = P_offset(p, h);
    out[6 * i + 2] = P_shell(p, 2.0 * fabs(h));
    out[6 * i + 3] = normal.x;
    out[6 * i + 4] = normal.y;
    out[6 * i + 5] = normal.z;
}
#endif
)";

std::string with_test_kernels(const OpenclCase& c) {
  std::string kernels = kEveryFunctionKernels;
  for (size_t at = kernels.find("P_"); at != std::string::npos; at = kernels.find("P_", at + c.prefix.size()))
    kernels.replace(at, 2, c.prefix + "_");
  return read_text(c.source_path) + kernels;
}

// Every function through the test kernel, in Real.
template <class Real>
ZeroSetShifts every_function(const OpenclProgram& program, const OpenclCase& c, const char* kernel) {
  const auto points = near_zero_set_points(c.c.field, kPoints);
  std::vector<Real> in;
  for (const auto& z : points)
    for (double v : {z.p[0], z.p[1], z.p[2], z.h}) in.push_back(static_cast<Real>(v));
  std::vector<KernelArg> args = {KernelArg::scalar<cl_ulong>(points.size()), KernelArg::input(in),
                                 KernelArg::output<Real>(6 * points.size())};
  program.run(kernel, points.size(), args);
  const std::vector<Real> out = args[2].values<Real>();
  ZeroSetShifts s;
  for (size_t i = 0; i < points.size(); ++i) {
    const double q[3] = {in[4 * i], in[4 * i + 1], in[4 * i + 2]},
                 n[3] = {out[6 * i + 3], out[6 * i + 4], out[6 * i + 5]};
    s.add(c.c, q, in[4 * i + 3], out[6 * i], out[6 * i + 1], out[6 * i + 2], n);
  }
  return s;
}

// The batch kernel <prefix>_offset[f]_kernel at h = kBatchH: the largest zero-set shift of its values.
template <class Real>
double batch_shift(const OpenclProgram& program, const OpenclCase& c, const std::string& kernel) {
  const auto points = near_zero_set_points(c.c.field, kPoints, kBatchH);
  std::vector<Real> x, y, z;
  for (const auto& p : points) {
    x.push_back(static_cast<Real>(p.p[0]));
    y.push_back(static_cast<Real>(p.p[1]));
    z.push_back(static_cast<Real>(p.p[2]));
  }
  const Real h = static_cast<Real>(kBatchH);
  std::vector<KernelArg> args = {KernelArg::scalar<cl_ulong>(points.size()),
                                 KernelArg::input(x),
                                 KernelArg::input(y),
                                 KernelArg::input(z),
                                 KernelArg::scalar(h),
                                 KernelArg::output<Real>(points.size())};
  program.run(kernel, points.size(), args);
  const std::vector<Real> out = args[5].values<Real>();
  double worst = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double q[3] = {x[i], y[i], z[i]};
    double g[3];
    field_gradient(c.c.field, q, g);
    const double shift = std::fabs(out[i] - c.c.offset(q[0], q[1], q[2], h)) / length(g);
    worst = std::isnan(shift) ? INFINITY : std::fmax(worst, shift);
  }
  return worst;
}

std::string describe(const ZeroSetShifts& s) {
  std::ostringstream out;
  out << "field " << s.field << ", offset " << s.offset << ", shell " << s.shell << ", normal " << s.normal;
  return out.str();
}

class OpenclOnPocl : public testing::TestWithParam<OpenclCase> {};

TEST_P(OpenclOnPocl, BuildsWithWarningsAsErrorsAndMatchesTheCHeader) {
  const OpenclCase& c = GetParam();
  const OpenclProgram program(with_test_kernels(c), "-cl-std=CL1.2 -Werror");
  const ZeroSetShifts f = every_function<float>(program, c, "offsetgen_test_every_functionf");
  const double batch_f = batch_shift<float>(program, c, c.prefix + "_offsetf_kernel");
  std::cout << c.prefix << " on " << program.device_name() << ": float " << describe(f) << ", batch kernel " << batch_f
            << "\n";
  EXPECT_LE(f.largest_shift(), kFloatShiftLimit) << c.prefix << " float: " << describe(f);
  EXPECT_LE(f.normal, kFloatNormalTolerance) << c.prefix << " float: " << describe(f);
  EXPECT_LE(batch_f, kFloatShiftLimit) << c.prefix << "_offsetf_kernel";
  if (!program.has_fp64()) {
    std::cout << c.prefix << ": " << program.device_name() << " has no cl_khr_fp64, double not run\n";
    return;
  }
  const ZeroSetShifts d = every_function<double>(program, c, "offsetgen_test_every_function");
  const double batch_d = batch_shift<double>(program, c, c.prefix + "_offset_kernel");
  std::cout << c.prefix << ": double " << describe(d) << ", batch kernel " << batch_d << "\n";
  EXPECT_LE(d.largest_shift(), kDoubleTolerance) << c.prefix << " double: " << describe(d);
  EXPECT_LE(d.normal, kDoubleNormalTolerance) << c.prefix << " double: " << describe(d);
  EXPECT_LE(batch_d, kDoubleTolerance) << c.prefix << "_offset_kernel";
}

INSTANTIATE_TEST_SUITE_P(Generated, OpenclOnPocl, testing::ValuesIn(opencl_cases()),
                         [](const testing::TestParamInfo<OpenclCase>& param) { return param.param.prefix; });

// Without cl_khr_fp64 the double half of the file must vanish, not break the build: the same source
// built with the extension macro undefined (a device without double), float still within tolerance.
// A second program build per case: under the `slow` label.
class OpenclWithoutFp64 : public testing::TestWithParam<OpenclCase> {};

TEST_P(OpenclWithoutFp64, BuildsAndRunsInFloat) {
  const OpenclCase& c = GetParam();
  const OpenclProgram program("#undef cl_khr_fp64\n" + with_test_kernels(c), "-cl-std=CL1.2 -Werror");
  const ZeroSetShifts f = every_function<float>(program, c, "offsetgen_test_every_functionf");
  EXPECT_LE(f.largest_shift(), kFloatShiftLimit) << describe(f);
  EXPECT_LE(f.normal, kFloatNormalTolerance) << describe(f);
}

INSTANTIATE_TEST_SUITE_P(SlowGenerated, OpenclWithoutFp64, testing::ValuesIn(opencl_cases()),
                         [](const testing::TestParamInfo<OpenclCase>& param) { return param.param.prefix; });

}  // namespace
}  // namespace offsetgen::test
