// The CUDA header's float functions on the host (nvcc) against the C header's double functions at the
// float-rounded points of tests/support/zero_set_points.h: the largest zero-set shift of _offsetf and
// _shellf, as float_vs_double.cpp measures the C header's own float functions. Build (from the root):
//   nvcc -O2 -std=c++17 -I. -Itests/support -DP=neovius_o4 -o cuda_fvd docs/neovius_o4_float/cuda_float_vs_double.cu
// run with `SEED=n ./cuda_fvd 2000`.
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STR2(a) #a
#define STR(a) STR2(a)
#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
#define FN(s) CAT(P, s)

namespace c_ref {
#include STR(generated/P.h)
}
#include STR(generated/P.cuh)
#include "zero_set_points.h"

using namespace offsetgen::test;

// Through memory, so the compiler keeps the rounding to float (docs/neovius_o4_float.md, pitfall).
static float rounded(double v) {
  volatile float r = static_cast<float>(v);
  return r;
}

int main(int argc, char** argv) {
  const int n = argc > 1 ? atoi(argv[1]) : 2000;
  const unsigned seed = getenv("SEED") ? static_cast<unsigned>(atoi(getenv("SEED"))) : 20261123u;
  double worst_offset = 0, worst_shell = 0;
  int over = 0;
  for (const auto& z : near_zero_set_points(&c_ref::FN(_field), n, NAN, seed)) {
    const float x = rounded(z.p[0]), y = rounded(z.p[1]), w = rounded(z.p[2]), h = rounded(z.h);
    const double q[3] = {x, y, w};
    double g[3];
    field_gradient(&c_ref::FN(_field), q, g);
    const double scale = length(g), t = 2 * fabs(static_cast<double>(h));
    const double offset = fabs(FN(_offsetf)(x, y, w, h) - c_ref::FN(_offset)(q[0], q[1], q[2], h)) / scale;
    const double shell_scale = scale * (fabs(c_ref::FN(_offset)(q[0], q[1], q[2], t / 2)) +
                                        fabs(c_ref::FN(_offset)(q[0], q[1], q[2], -t / 2)));
    const double shell =
        fabs(FN(_shellf)(x, y, w, static_cast<float>(t)) - c_ref::FN(_shell)(q[0], q[1], q[2], t)) / shell_scale;
    worst_offset = fmax(worst_offset, offset);
    worst_shell = fmax(worst_shell, shell);
    if (offset > 2e-5 || shell > 2e-5) ++over;
  }
  printf("seed %u: offsetf %.2e, shellf %.2e; points over 2e-5: %d of %d\n", seed, worst_offset, worst_shell, over, n);
}
