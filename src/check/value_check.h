// Item 2 of `offsetgen check`: every emitted function against a 40-digit CLN evaluation of the same
// symbolic model (offset/high_precision.h), at random points, each judged within its precision's
// tolerance: the double scalar functions, their float twins, the batch functions (_n) of both
// precisions, and the GLSL functions run on Mesa llvmpipe. The figure of merit for values is how far
// the deviation moves the zero set, |delta phi| / |grad F| in cell units; for the normal, |delta n|.
#pragma once

#include "check/reference.h"
#include "run/c_library.h"
#include "run/metadata.h"
#include "run/runner.h"

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
  double tolerance = 1e-12;              // double functions: max zero-set shift (cell units)
  double normal_tolerance = 1e-6;        // double normal: max |delta n|
  double float_tolerance = 2e-4;         // float32 (C float twins, GLSL): max zero-set shift
  double float_normal_tolerance = 1e-3;  // float32 normal: max |delta n|
  int digits = 40;
  std::function<void(int done, int total)> progress;  // may be empty
};

struct FunctionDeviation {
  std::string function;  // "offset", "shellf", "offset_n", "glsl offset", ...
  bool is_float = false;
  int points = 0;
  double max_shift = 0;  // max |delta| / |grad F| (cell units); for the normal: max |delta n|
  double mean_shift = 0;
  std::vector<double> worst_point;  // where max_shift occurs (cell units), then h or t when used
  std::string measure;              // how the shift is defined, for the report
  double tolerance = 0;             // the limit it is judged against
  bool pass = false;
};

struct ValueReport {
  std::vector<FunctionDeviation> functions;
  double max_shift_double = 0;  // over field, offset, shell, graded and the batch functions (double)
  double max_normal_double = 0;
  double max_shift_float = 0;  // over the float32 functions (C float, GLSL), normal aside
  double tolerance = 0;
  int digits = 40;
  bool has_double = true;
  bool pass = false;  // every function within its tolerance
};

// What to compare: the C functions loaded into this process (may be null), and the lanes of a
// runner (run/runner.h): one per precision of a shader, module or kernel, rows named
// "<label> <function><suffix>" ("glsl offset", "numpy offset", "cuda offsetf").
struct Implementations {
  const run::LoadedFunctions* c = nullptr;
  std::vector<run::Lane> lanes;
};

// `thickness` is the graded wall's t(x) when the file has a _graded function.
ValueReport check_values(const Implementations& implementations, const Reference& reference,
                         const run::FileMetadata& meta, const std::optional<GiNaC::ex>& thickness,
                         const ValueCheckOptions& options);

// The C functions only (the common case).
ValueReport check_values(const run::LoadedFunctions& functions, const Reference& reference,
                         const run::FileMetadata& meta, const std::optional<GiNaC::ex>& thickness,
                         const ValueCheckOptions& options);

// 200 points up to order 4, 60 for orders 5-6, 16 above: one 40-digit evaluation of phi costs about
// 1 ms at order 4, 20 ms at order 6 and 150 ms at order 8 (GiNaC tree walk).
int default_value_points(int order);

// An exact rational with the value of a double (no rounding, so CLN keeps full precision).
GiNaC::numeric exact(double value);

}  // namespace offsetgen::check
