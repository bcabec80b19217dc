// A surface given as the zero set of a function of cell coordinates, evaluated in batches: one of the
// wall's two offset surfaces, phi(p, h) = 0 with h = +t/2 or -t/2 (the emitted C functions).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace offsetgen::step {

// out[i] = g(x[i], y[i], z[i]) for i < n.
using LevelFunction = std::function<void(size_t n, const double* x, const double* y, const double* z, double* out)>;

// The roots of g along n segments a + s (b - a), s in [0, 1], each scanned at `steps` points and
// refined by bisection to full double precision: roots[i] lists the s of segment i's sign changes.
struct Segment {
  double a[3], b[3];
};
std::vector<std::vector<double>> segment_roots(const LevelFunction& g, const std::vector<Segment>& segments, int steps);

}  // namespace offsetgen::step
