// Host-side comparison of a generated CUDA header (<prefix>.cuh, its __host__ __device__ functions run
// on the host) with the C header of the same generation (<prefix>.h), included into namespace c_ref
// by the driver. Compiled by nvcc (host code: the system C++ compiler) in tests/cuda/run_cuda_case.cmake.
//
// The points lie near the zero set of <prefix>_offset(., h) (tests/support/zero_set_points.h).
// The measure is the zero-set shift, the value difference over |grad F| (offsetgen check's measure):
// _field and _offset at (p, h), _shell at (p, t = 2|h|) over |grad F| (|phi(p, t/2)| + |phi(p, -t/2)|),
// and the largest component difference of the unit normals.
#pragma once

#include <math.h>
#include <stdio.h>

#include "zero_set_points.h"

namespace cuda_test {

template <class Real>
struct Functions {
  Real (*field)(Real, Real, Real);
  Real (*offset)(Real, Real, Real, Real);
  Real (*shell)(Real, Real, Real, Real);
  void (*normal)(Real, Real, Real, Real, Real*);
};

// `v` rounded to Real through memory: GCC 12's SLP vectoriser at -O2 dropped the float rounding of
// `const Real q[3] = {...}; const double at[3] = {q[0], ...}` (docs/neovius_o4_float.md), so the
// reference ran at the unrounded point.
template <class Real>
Real rounded(double v) {
  volatile Real r = static_cast<Real>(v);
  return r;
}

// The shifts of `cuda` (double or float: the arguments rounded to its type) against the C header's
// double functions `ref` over `points` points near the zero set.
template <class Real>
offsetgen::test::ZeroSetShifts compare(const offsetgen::test::CFunctions& ref, const Functions<Real>& cuda,
                                       int points) {
  offsetgen::test::ZeroSetShifts s;
  for (const auto& z : offsetgen::test::near_zero_set_points(ref.field, points)) {
    const Real h = rounded<Real>(z.h), t = 2 * (h < 0 ? -h : h);
    const Real q[3] = {rounded<Real>(z.p[0]), rounded<Real>(z.p[1]), rounded<Real>(z.p[2])};
    const double at[3] = {q[0], q[1], q[2]};
    Real n[3];
    cuda.normal(q[0], q[1], q[2], h, n);
    const double nd[3] = {n[0], n[1], n[2]};
    s.add(ref, at, h, cuda.field(q[0], q[1], q[2]), cuda.offset(q[0], q[1], q[2], h), cuda.shell(q[0], q[1], q[2], t),
          nd);
  }
  return s;
}

// Prints the case's shifts; returns 1 when a limit is exceeded (or a value is NaN), else 0. The limits:
// zero-set shift 1e-12 in double, 2e-5 in float (kFloatShiftLimit, every case); unit normal 1e-12 in
// double, 1e-3 in float (offsetgen check's).
inline int report(const char* prefix, const offsetgen::test::ZeroSetShifts& d,
                  const offsetgen::test::ZeroSetShifts& f) {
  const bool pass = d.largest_shift() <= 1e-12 && d.normal <= 1e-12 &&
                    f.largest_shift() <= offsetgen::test::kFloatShiftLimit && f.normal <= 1e-3;
  printf(
      "%-22s double: field %.2e offset %.2e shell %.2e normal %.2e | float: field %.2e offset %.2e shell %.2e "
      "normal %.2e  %s\n",
      prefix, d.field, d.offset, d.shell, d.normal, f.field, f.offset, f.shell, f.normal, pass ? "ok" : "FAIL");
  return pass ? 0 : 1;
}

}  // namespace cuda_test

#define OFFSETGEN_CUDA_DEVICE_CALLS(P)                                                                             \
  out[k++] = P##_field(p[0], p[1], p[2]) + P##_offset(p[0], p[1], p[2], p[3]) + P##_shell(p[0], p[1], p[2], p[3]); \
  P##_normal(p[0], p[1], p[2], p[3], n);                                                                           \
  out[k++] = n[0] + n[1] + n[2];                                                                                   \
  outf[k++] = P##_fieldf(pf[0], pf[1], pf[2]) + P##_offsetf(pf[0], pf[1], pf[2], pf[3]) +                          \
              P##_shellf(pf[0], pf[1], pf[2], pf[3]);                                                              \
  P##_normalf(pf[0], pf[1], pf[2], pf[3], nf);                                                                     \
  outf[k++] = nf[0] + nf[1] + nf[2];

#define OFFSETGEN_CUDA_COMPARE(P, points)                                                                           \
  do {                                                                                                              \
    (void)&P##_offset_kernel<>; /* instantiates both batch kernels for every -gencode target */                     \
    (void)&P##_offsetf_kernel<>;                                                                                    \
    const offsetgen::test::CFunctions ref = {&c_ref::P##_field, &c_ref::P##_offset, &c_ref::P##_shell,              \
                                             &c_ref::P##_normal};                                                   \
    const cuda_test::Functions<double> cuda = {&P##_field, &P##_offset, &P##_shell, &P##_normal};                   \
    const cuda_test::Functions<float> cudaf = {&P##_fieldf, &P##_offsetf, &P##_shellf, &P##_normalf};               \
    failed += cuda_test::report(#P, cuda_test::compare(ref, cuda, points), cuda_test::compare(ref, cudaf, points)); \
  } while (0)
