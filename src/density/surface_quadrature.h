// Integrals over the surface F = 0 in one periodic cell [0, 1)^3, to a requested accuracy.
//
// Columns parallel to each axis are intersected with the surface (every root along the column,
// isolated rigorously with the Hessian bound, then polished by safeguarded Newton). A smooth
// partition of unity over the three axes, w_i = n_i^8 / (n_x^8 + n_y^8 + n_z^8), splits the
// integrand so that each axis only sees surface points where the surface is steep against it:
//
//     integral g dA = sum_i  integral over face i of  sum_(roots on the column) g w_i / |n_i|
//
// w_i / |n_i| vanishes like |n_i|^7 where a column grazes the surface, so each face integrand is
// periodic and smooth (C^6 at the folds), and the trapezoid rule on a uniform grid of columns
// converges fast. The grid doubles until the error estimate is within the tolerance: the difference
// d_N of the last two grids times the ratio d_N / d_(N/2) of the last two differences (geometric
// convergence; the trapezoid rule on such integrands converges at least that fast).
#pragma once

#include "density/field_sampler.h"

#include <array>
#include <functional>
#include <vector>

namespace offsetgen::density {

struct SurfacePoint {
  std::array<double, 3> p{};       // on F = 0, in [0, 1)^3
  FieldJet jet;                    // cell units
  std::array<double, 3> normal{};  // grad F / |grad F|
  double gradient_norm = 0;
};

// Adds the integrand's components at one surface point to `out` (out.size() components).
using SurfaceIntegrand = std::function<void(const SurfacePoint&, std::vector<double>& out)>;

struct QuadratureOptions {
  std::vector<double> tolerance;  // absolute, per component (infinity: judged by `accept` alone)
  // An extra convergence test on the values (e.g. that integral(K dA) / 2 pi is an integer).
  std::function<bool(const std::vector<double>& value)> accept;
  long min_grid = 64;    // columns per face side before convergence may be declared
  long max_grid = 1024;  // budget; the result states its error either way
};

struct QuadratureResult {
  std::vector<double> value;
  std::vector<double> error;  // estimated absolute error per component
  long grid = 0;              // columns per face side of the last grid
  long columns = 0;           // columns intersected
  long points = 0;            // surface points evaluated
  bool converged = false;     // every error within its tolerance
};

QuadratureResult integrate_over_surface(FieldSampler& field, const SurfaceIntegrand& integrand,
                                        const QuadratureOptions& options);

}  // namespace offsetgen::density
