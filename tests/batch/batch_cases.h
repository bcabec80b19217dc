// The batch functions under test: every `_n` function of the headers generated for tests/batch,
// with its scalar twin and the field, behind one (x, y, z, w) interface (z is ignored in 2D).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace offsetgen::batch_test {

template <class T>
struct BatchFunction {
  std::string header;    // generated header stem, e.g. "gyroid_o4"
  std::string function;  // "offset" or "shell"
  std::string build;     // how the case TU was compiled: "fast", "omp" or "generic"
  int dims = 3;
  int order = 1;
  bool periodic = true;  // a catalog TPMS (its gradient bound holds everywhere)
  std::function<T(T, T, T, T)> scalar;
  std::function<void(std::size_t, const T*, const T*, const T*, const T*, T*)> batch;
  std::function<T(T, T, T)> field;
  // The same program in more precision: the long double twin (double cases) or the double
  // function of the same header (float cases).
  std::function<long double(T, T, T, T)> reference;

  std::string label() const { return header + "_" + function + (sizeof(T) == 4 ? "f" : "") + "_" + build; }
};

struct Cases {
  std::vector<BatchFunction<double>> doubles;
  std::vector<BatchFunction<float>> floats;
};

const Cases& all_cases();

template <class T>
const std::vector<BatchFunction<T>>& cases_of();
template <>
inline const std::vector<BatchFunction<double>>& cases_of<double>() {
  return all_cases().doubles;
}
template <>
inline const std::vector<BatchFunction<float>>& cases_of<float>() {
  return all_cases().floats;
}

// Facts from a generated header's metadata block (read by src/run/metadata.h).
struct HeaderFacts {
  double gradient_bound = 0;  // max |grad F| in natural units (X = scale * x)
  double scale = 1;
};
HeaderFacts header_facts(const std::string& header);

// One per case translation unit.
void add_gyroid_o4(Cases&);
void add_gyroid_o4_omp(Cases&);
void add_gyroid_o4_generic(Cases&);
void add_gyroid_o6(Cases&);
void add_neovius_o3(Cases&);
void add_schwarzp_o2(Cases&);
void add_wave2d_o3(Cases&);
void add_expo_o2(Cases&);

}  // namespace offsetgen::batch_test

// Entries for a generated prefix. SFX is empty (double) or f (float); REF is the prefix of the
// reference functions (ld_<prefix> for double, <prefix> for float).
#define OFFSETGEN_BATCH_CASE3(T, PREFIX, FN, SFX, BUILD, ORDER, PERIODIC, REF)                                \
  ::offsetgen::batch_test::BatchFunction<T> {                                                                 \
#PREFIX, #FN, BUILD, 3, ORDER, PERIODIC, [](T x, T y, T z, T w) { return PREFIX##_##FN##SFX(x, y, z, w); }, \
        [](std::size_t n, const T* x, const T* y, const T* z, const T* w, T* out) {                        \
          PREFIX##_##FN##SFX##_n(n, x, y, z, w, out);                                                      \
        },                                                                                                 \
        [](T x, T y, T z) { return PREFIX##_field##SFX(x, y, z); },                                        \
        [](T x, T y, T z, T w) -> long double { return REF##_##FN(x, y, z, w); } \
  }
#define OFFSETGEN_BATCH_CASE2(T, PREFIX, FN, SFX, BUILD, ORDER, PERIODIC, REF)                              \
  ::offsetgen::batch_test::BatchFunction<T> {                                                               \
#PREFIX, #FN, BUILD, 2, ORDER, PERIODIC, [](T x, T y, T, T w) { return PREFIX##_##FN##SFX(x, y, w); },    \
        [](std::size_t n, const T* x, const T* y, const T*, const T* w, T* out) {                          \
          PREFIX##_##FN##SFX##_n(n, x, y, w, out);                                                         \
        },                                                                                                 \
        [](T x, T y, T) { return PREFIX##_field##SFX(x, y); },                                             \
        [](T x, T y, T, T w) -> long double { return REF##_##FN(x, y, w); } \
  }
