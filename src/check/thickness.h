// Item 3 of `offsetgen check`: wall thickness measured the paper's way (section 5.2.1):
//   Algorithm 1: points on G1 = 0 with x, y on the grid {0, 0.05, ..., 1} and z by bracketing +
//                Brent (every root in the cell);
//   Algorithm 2: from each point a ray along the unit normal of G1; the distance h_m at which
//                G2 = 0; relative error |h_m - h| / h.
// For constant h: both ways (F -> phi and phi -> F), and the shell's two walls. For graded walls
// three measures, see GradedRow.
#pragma once

#include "check/convergence.h"
#include "check/reference.h"
#include "run/c_library.h"
#include "support/point.h"

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::check {

// The compiled functions as double-precision callables (float twins stand in when a file has no
// double functions; the measurement then carries float32 rounding).
struct Probe {
  int dims = 3;
  bool float_only = false;
  std::function<double(const double*)> field;
  std::function<double(const double*, double)> offset;
  std::function<double(const double*, double)> shell;
  std::function<void(const double*, double, double*)> normal;
  std::function<double(const double*)> graded;  // empty when the file has none
  // One graded wall with the half thickness s t(.)/2 read where the method reads it (s = +-lambda):
  // an in-process evaluation of the same lowered construction as _graded, for the thickness sweep.
  // Empty: the wall is phi(q, s t(q)/2), the thickness read at q.
  std::function<double(const double*, double)> graded_wall;
};
Probe make_probe(const run::LoadedFunctions& functions);

// Algorithm 1: points on g = 0, the first dims-1 coordinates on a grid of `grid` values in [0, 1],
// the last one every root in [0, 1] (scan of `scan` sub-intervals, Brent in each sign change).
std::vector<Point> sample_zero_set(const std::function<double(const double*)>& g, int dims, int grid, int scan);

// The distance s along p + s n where g changes sign, nearest `expected`, within `reach` of it.
std::optional<double> ray_crossing(const std::function<double(const double*)>& g, const Point& p, const Point& n,
                                   int dims, double expected, double reach);

// Relative errors over all rays of one measurement. Rays without a crossing are counted in `missed`
// and listed (first few) in `missed_at`; they are never dropped silently.
struct ErrorStats {
  int rays = 0;     // rays shot (points used)
  int crossed = 0;  // rays that found the other surface (mean and max are over these)
  int missed = 0;   // rays without a crossing within reach (or with a zero normal)
  int skipped = 0;  // points not used at all, with the reason in `skipped_reason` (e.g. target <= 0)
  std::string skipped_reason;
  int singular = 0;  // points skipped because grad F vanishes where the ray starts or ends (a crossing
                     // or critical point of the zero set: no offset of order m exists there)
  double mean = NAN;
  double max = NAN;
  Point worst{};  // the sample point with the largest error
  std::vector<Point> missed_at;
  double sum = 0;  // running sum, for `mean`
  void add(double relative_error, const Point& where);
  void miss(const Point& where);
  void finish();
};

struct SweepRow {
  double h = 0;         // offset distance (cell units); the shell uses t = 2h
  ErrorStats f_to_phi;  // rays from F = 0 along grad F to phi(., h) = 0, vs h
  ErrorStats phi_to_f;  // rays from phi(., h) = 0 along grad phi to F = 0, vs h
  ErrorStats shell;     // rays from F = 0 both ways to the walls of Phi(., 2h) = 0: total vs t = 2h
};

// Graded wall t(x) (total thickness), h(x) = t(x) / 2, walls W+- = phi(x, +-h(x)) = 0:
//  total:     rays from p on F = 0 along grad F to W+ and W-: |(s+ - s-) - t(p)| / t(p). The
//             first-order parts of the two walls cancel: second order at best (paper section 6).
//  one_sided: the same rays, each wall against h(p): |s+- - h(p)| / h(p). The wall sits where
//             h(wall point) is reached, not h(p): first order whatever m is.
//  paper:     the paper's Figure 8: rays from points q on W+- = 0 along grad W+- (the wall's own
//             normal, through the chain rule including grad h) back to F = 0, vs h(q). Second order.
struct GradedRow {
  double h_max = 0;              // max over the cell of h(x) = lambda t(x) / 2
  double lambda = 1;             // scale applied to the thickness expression
  bool as_given = false;         // lambda = 1: the expression exactly as given
  bool compiled_graded = false;  // `total` measured on the compiled _graded function
  ErrorStats total, one_sided, paper;
};

struct ThicknessOptions {
  std::vector<double> h;  // sweep (cell units)
  int grid = 21;          // points per axis, step 1/(grid-1): 21 is the paper's 0.05
  int scan = 200;         // bracketing sub-intervals along the solved axis
  bool shell = true;
  std::function<void(const std::string&)> progress;  // may be empty
};

// Where |grad F| is below this fraction of its median over the samples on F = 0, a sample is singular.
constexpr double kSingularGradient = 1e-2;

struct ThicknessReport {
  int grid = 0, scan = 0;
  int samples_on_f = 0;
  int singular_on_f = 0;  // samples on F = 0 skipped as singular (all rows)
  std::vector<SweepRow> rows;
  OrderFit fit_f_to_phi, fit_phi_to_f, fit_shell;
};

ThicknessReport measure_constant(const Probe& probe, const ThicknessOptions& options);

struct GradedReport {
  std::string expression;  // total thickness t(x), cell units
  // The orders the file's method promises for the three measures (MethodFacts), and what it reads.
  int expected_total = 2, expected_one_sided = 1, expected_paper = 2;
  std::string method_reads;     // where the method reads the thickness, for the report
  double t_peak = 0;            // max t over the cell
  std::vector<GradedRow> rows;  // the sweep (scaled), then the as-given row
  OrderFit fit_total, fit_one_sided, fit_paper;
};

// `use_compiled_graded`: measure the as-given row's total thickness on the file's _graded function.
GradedReport measure_graded(const Probe& probe, ThicknessFunction& thickness, const std::string& expression,
                            bool use_compiled_graded, const ThicknessOptions& options);

}  // namespace offsetgen::check
