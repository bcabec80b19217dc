// The OpenCL C source's float functions on pocl against the C header's double functions at the
// float-rounded points of tests/support/zero_set_points.h: the largest zero-set shift of _offsetf and
// _shellf, as float_vs_double.cpp measures the C header's own float functions. Build (from the root):
//   g++ -O2 -std=c++17 -I. -Itests/support -Itests/opencl -DP=neovius_o4 -o pocl_fvd
//       docs/neovius_o4_float/pocl_float_vs_double.cpp tests/opencl/opencl_runner.cpp -lOpenCL -lfmt
// run with `SEED=n ./pocl_fvd 2000`.
#include "opencl_runner.h"
#include "zero_set_points.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#define STR2(a) #a
#define STR(a) STR2(a)
#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
#define FN(s) CAT(P, s)

#include STR(generated/P.h)

using namespace offsetgen::test;

int main(int argc, char** argv) {
  const int n = argc > 1 ? atoi(argv[1]) : 2000;
  const unsigned seed = getenv("SEED") ? static_cast<unsigned>(atoi(getenv("SEED"))) : 20261123u;
  std::ifstream file(STR(generated/P.cl));
  std::stringstream source;
  source << file.rdbuf();
  source << "__kernel void fvd(const ulong n, __global const float *in, __global float *out) {\n"
            "  const size_t i = get_global_id(0);\n"
            "  if (i >= n) return;\n"
            "  const float3 p = (float3)(in[4 * i], in[4 * i + 1], in[4 * i + 2]);\n"
            "  const float h = in[4 * i + 3];\n"
            "  out[2 * i] = " STR(P) "_offsetf(p, h);\n"
            "  out[2 * i + 1] = " STR(P) "_shellf(p, 2.0f * fabs(h));\n"
            "}\n";
  const OpenclProgram program(source.str(), "-cl-std=CL1.2");
  const auto points = near_zero_set_points(&FN(_field), n, NAN, seed);
  std::vector<float> in;
  for (const auto& z : points)
    for (double v : {z.p[0], z.p[1], z.p[2], z.h}) in.push_back(static_cast<float>(v));
  std::vector<KernelArg> args = {KernelArg::scalar<cl_ulong>(points.size()), KernelArg::input(in),
                                 KernelArg::output<float>(2 * points.size())};
  program.run("fvd", points.size(), args);
  const std::vector<float> out = args[2].values<float>();
  double worst_offset = 0, worst_shell = 0;
  int over = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double q[3] = {in[4 * i], in[4 * i + 1], in[4 * i + 2]}, h = in[4 * i + 3], t = 2 * std::fabs(h);
    double g[3];
    field_gradient(&FN(_field), q, g);
    const double scale = length(g);
    const double offset = std::fabs(out[2 * i] - FN(_offset)(q[0], q[1], q[2], h)) / scale;
    const double shell_scale =
        scale * (std::fabs(FN(_offset)(q[0], q[1], q[2], t / 2)) + std::fabs(FN(_offset)(q[0], q[1], q[2], -t / 2)));
    const double shell = std::fabs(out[2 * i + 1] - FN(_shell)(q[0], q[1], q[2], t)) / shell_scale;
    worst_offset = std::fmax(worst_offset, offset);
    worst_shell = std::fmax(worst_shell, shell);
    if (offset > 2e-5 || shell > 2e-5) ++over;
  }
  std::printf("%s seed %u: offsetf %.2e, shellf %.2e; points over 2e-5: %d of %d\n", program.device_name().c_str(),
              seed, worst_offset, worst_shell, over, n);
}
