// Item 2 of `offsetgen check`: the compiled functions against a 40-digit CLN evaluation of the same
// symbolic model (offset/high_precision.h), at random points. The figure of merit is how far the
// rounding moves the zero set: |delta phi| / |grad F| in cell units.
#pragma once

#include "check/compile.h"
#include "check/metadata.h"
#include "check/reference.h"

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
  double tolerance = 1e-12;  // max zero-set shift of the double functions (cell units)
  int digits = 40;
  std::function<void(int done, int total)> progress;  // may be empty
};

struct FunctionDeviation {
  std::string function;  // "offset", "shellf", ...
  bool is_float = false;
  int points = 0;
  double max_shift = 0;  // max |delta| / |grad| (cell units); for the normal: max |delta n|
  double mean_shift = 0;
  std::vector<double> worst_point;  // where max_shift occurs (cell units), then h or t when used
  std::string measure;              // how the shift is defined, for the report
};

struct ValueReport {
  std::vector<FunctionDeviation> functions;
  double max_shift_double = 0;  // over field, offset, shell, graded (double)
  double max_normal_double = 0;
  double max_shift_float = 0;  // informational: float32 cannot meet 1e-12
  double tolerance = 0;
  int digits = 40;
  bool has_double = true;  // false for float-only files: nothing is judged
  bool pass = false;
};

// `thickness` is the graded wall's t(x) when the file has a _graded function.
ValueReport check_values(const LoadedFunctions& functions, const Reference& reference, const FileMetadata& meta,
                         const std::optional<GiNaC::ex>& thickness, const ValueCheckOptions& options);

// 200 points up to order 4, 60 for orders 5-6, 16 above: one 40-digit evaluation of phi costs about
// 1 ms at order 4, 20 ms at order 6 and 150 ms at order 8 (GiNaC tree walk).
int default_value_points(int order);

// An exact rational with the value of a double (no rounding, so CLN keeps full precision).
GiNaC::numeric exact(double value);

}  // namespace offsetgen::check
