// Item 2 of `offsetgen check`: every emitted function against a 40-digit CLN evaluation of the same
// symbolic model (offset/high_precision.h), at random points, each judged within its precision's
// tolerance: the double scalar functions, their float twins, the batch functions (_n) of both
// precisions, and the GLSL functions run on Mesa llvmpipe. The figure of merit for values is how far
// the deviation moves the zero set, |delta phi| / |grad F| in cell units; for the normal, |delta n|.
#pragma once

#include "check/compile.h"
#include "check/metadata.h"
#include "check/reference.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::check {

struct ValueCheckOptions {
  int points = 0;            // random points per function; 0: default_value_points(order)
  int normal_stride = 4;     // the normal (2 * dims extra 40-digit evaluations) at every n-th point
  unsigned seed = 20210415;  // fixed, so runs are reproducible
  double h_max = 0.1;        // h (and t/2) drawn uniformly from [-h_max, h_max] (cell units)
  // The limits, from the largest deviations over the 9 catalog surfaces at orders 1-4, five of them at
  // orders 5-6 and five user expressions (README, "Checking accuracy"), with a margin of 8x or more:
  // double values 1.7e-14, double normal 7.9e-9, float32 values 2.5e-5, float32 normal 8.3e-5.
  double tolerance = 1e-12;               // double functions: max zero-set shift (cell units)
  double normal_tolerance = 1e-6;         // double normal: max |delta n|
  double float_tolerance = 2e-4;          // float32 (C float twins, GLSL): max zero-set shift
  double float_normal_tolerance = 1e-3;   // float32 normal: max |delta n|
  int digits = 40;
  std::function<void(int done, int total)> progress;  // may be empty
};

struct FunctionDeviation {
  std::string function;         // "offset", "shellf", "offset_n", "glsl offset", ...
  bool is_float = false;
  int points = 0;
  double max_shift = 0;         // max |delta| / |grad F| (cell units); for the normal: max |delta n|
  double mean_shift = 0;
  std::vector<double> worst_point;  // where max_shift occurs (cell units), then h or t when used
  std::string measure;          // how the shift is defined, for the report
  double tolerance = 0;         // the limit it is judged against
  bool pass = false;
};

struct ValueReport {
  std::vector<FunctionDeviation> functions;
  double max_shift_double = 0;  // over field, offset, shell, graded and the batch functions (double)
  double max_normal_double = 0;
  double max_shift_float = 0;   // over the float32 functions (C float, GLSL), normal aside
  double tolerance = 0;
  int digits = 40;
  bool has_double = true;
  bool pass = false;            // every function within its tolerance
};

// A float32 implementation evaluated at many points at once (the GLSL snippet on llvmpipe):
// `function` is "field", "offset", "shell", "normal" or "graded"; each input is (x, y, z, h|t) in 3D,
// (x, y, h|t, 0) in 2D; returns inputs.size() * components floats. Throws std::runtime_error when it
// cannot run.
using Float32Runner = std::function<std::vector<float>(const std::string& function,
                                                       const std::vector<std::array<float, 4>>& inputs,
                                                       int components)>;

// The same for a float64 implementation (a NumPy module under python3), judged at double tolerances.
using Float64Runner = std::function<std::vector<double>(
    const std::string& function, const std::vector<std::array<double, 4>>& inputs, int components)>;

// What to compare: the loaded C functions (may be null), a float32 runner and a float64 runner (each
// may be empty). A runner's rows are named "<label> <function><suffix>": "glsl offset", "numpy offset",
// "cuda offsetf" (the suffix of the file's own float names).
struct Implementations {
  const LoadedFunctions* c = nullptr;
  Float32Runner float32;  // GLSL on llvmpipe; the float functions of CUDA and OpenCL files
  std::string float32_label = "glsl";
  std::string float32_suffix;
  bool float32_graded = false;  // the file has _graded
  Float64Runner float64;        // NumPy; the double functions of CUDA and OpenCL files
  std::string float64_label = "numpy";
  bool float64_graded = false;
};

// `thickness` is the graded wall's t(x) when the file has a _graded function.
ValueReport check_values(const Implementations& implementations, const Reference& reference,
                         const FileMetadata& meta, const std::optional<GiNaC::ex>& thickness,
                         const ValueCheckOptions& options);

// The C functions only (the common case).
ValueReport check_values(const LoadedFunctions& functions, const Reference& reference, const FileMetadata& meta,
                         const std::optional<GiNaC::ex>& thickness, const ValueCheckOptions& options);

// 200 points up to order 4, 60 for orders 5-6, 16 above: one 40-digit evaluation of phi costs about
// 1 ms at order 4, 20 ms at order 6 and 150 ms at order 8 (GiNaC tree walk).
int default_value_points(int order);

// An exact rational with the value of a double (no rounding, so CLN keeps full precision).
GiNaC::numeric exact(double value);

}  // namespace offsetgen::check
