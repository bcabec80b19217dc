// What the evaluation benchmark measures: every implementation of phi^(m) (and the shell) that the
// benchmark executable was built with, registered by surface and order.
//   ours   the generated header (scalar functions and the batch API, double and float)
//   sympy  tools/sympy_baseline.py's C (offset only; its shell is two offset calls)
//   ad     runtime nested forward-mode AD (nested_dual.h; offset only)
//   libm_trig  ours built with OFFSETGEN_LIBM_TRIG (libm's sin/cos instead of the inline ones),
//              scalar double only
//   methods    ours generated with each offset method (--method), for the side-by-side comparison
//              (bench_methods only)
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace offsetgen::bench {

using Scalar = double (*)(double, double, double, double);
using Batch = void (*)(std::size_t, const double*, const double*, const double*, const double*, double*);
using ScalarF = float (*)(float, float, float, float);
using BatchF = void (*)(std::size_t, const float*, const float*, const float*, const float*, float*);

struct OursFunctions {
  Scalar offset, shell;
  Batch offset_n, shell_n;
  ScalarF offsetf, shellf;
  BatchF offsetf_n, shellf_n;
};

using Key = std::pair<std::string, int>;  // surface, order

struct Registry {
  std::map<Key, OursFunctions> ours;
  std::map<Key, Scalar> sympy;
  std::map<Key, Scalar> ad;
  std::map<Key, std::pair<Scalar, Scalar>> libm_trig;            // offset, shell calling libm's sin/cos
  std::map<std::pair<std::string, Key>, OursFunctions> methods;  // (method, (surface, order))
};

Registry& registry();

inline bool register_ours(const char* surface, int order, OursFunctions f) {
  registry().ours[{surface, order}] = f;
  return true;
}
inline bool register_method(const char* method, const char* surface, int order, OursFunctions f) {
  registry().methods[{method, {surface, order}}] = f;
  return true;
}
inline bool register_sympy(const char* surface, int order, Scalar offset) {
  registry().sympy[{surface, order}] = offset;
  return true;
}
inline bool register_libm_trig(const char* surface, int order, Scalar offset, Scalar shell) {
  registry().libm_trig[{surface, order}] = {offset, shell};
  return true;
}
inline bool register_ad(const char* surface, int order, Scalar offset) {
  registry().ad[{surface, order}] = offset;
  return true;
}

}  // namespace offsetgen::bench
