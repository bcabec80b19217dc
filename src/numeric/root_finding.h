// The project's own root finder: Brent's method (inverse quadratic interpolation, secant and
// bisection, always keeping a bracket), plus the bracketing searches the measurements need.
#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace offsetgen::numeric {

using ScalarFunction = std::function<double(double)>;

// A root of f in [a, b], given fa = f(a) and fb = f(b) of opposite signs (or one of them zero).
// Converges to the bracket's last representable width (no user tolerance needed); at most
// `max_iterations` function evaluations.
double brent_root(const ScalarFunction& f, double a, double b, double fa, double fb, int max_iterations = 200);

// Every root of f in [lo, hi], found by scanning `intervals` equal sub-intervals for sign changes and
// refining each with brent_root. Exact zeros at scan nodes count once. Roots of even multiplicity
// (touching, no sign change) are not found; that is inherent to bracketing.
std::vector<double> roots_in_interval(const ScalarFunction& f, double lo, double hi, int intervals);

// The root of f closest to `expected` within [expected - reach, expected + reach], searched in
// growing windows around `expected` (from 1e-8 * reach to reach) until one side changes sign.
// nullopt when no sign change is found inside the reach: the caller counts that as "no crossing".
std::optional<double> root_near(const ScalarFunction& f, double expected, double reach);

}  // namespace offsetgen::numeric
