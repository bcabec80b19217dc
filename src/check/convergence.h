// Fitting the convergence order: least-squares slope of log(error) against log(h) over the small-h
// part of a sweep, leaving out errors at the double-precision floor.
#pragma once

#include <string>
#include <vector>

namespace offsetgen::check {

// Relative errors below this are treated as roundoff (phi is accurate to ~1e-16 |F|, so the measured
// distance carries ~1e-13 relative noise at h = 0.001): they are not used for slopes.
constexpr double kRoundoffFloor = 1e-11;

struct OrderFit {
  bool fitted = false;
  double slope = 0;
  double h_min = 0, h_max = 0;  // range of h actually used
  int points = 0;
  std::string note;  // why not fitted, or what was left out
};

// Points with h <= sqrt(min h * max h) ("the small-h half", on a log scale) and error above the floor;
// when fewer than 3 such points exist, the 3 smallest h above the floor. Needs >= 2 points.
OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error);

// Least-squares slope of log(y) against log(x); all values must be positive.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace offsetgen::check
