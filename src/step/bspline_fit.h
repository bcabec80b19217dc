// Least-squares fitting of clamped uniform cubic B-splines to samples on a regular grid, with the
// boundary fixed first: each boundary curve of the surface is fitted from that boundary's samples
// alone (its end points interpolated), then the interior control points from all samples. So a
// boundary that lies in a plane (a mirror plane of the surface) has its control points in that plane,
// and two patches that share a boundary get the same curve. No OpenCASCADE here.
#pragma once

#include "support/point.h"

#include <array>
#include <cstddef>
#include <vector>

namespace offsetgen::step {

// Control points per patch side tried in turn, fewest first, up to a request's limit (both routes).
inline constexpr int kPatchSides[] = {4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 64};

// The index a * stride + b of a row-major array, in size_t.
inline size_t flat(int a, int stride, int b) {
  return static_cast<size_t>(a) * static_cast<size_t>(stride) + static_cast<size_t>(b);
}

// Clamped uniform knots of a cubic B-spline with n >= 4 control points on [0, 1]: the distinct knots
// 0, 1/(n-3), ..., 1 with multiplicities 4, 1, ..., 1, 4.
struct CubicKnots {
  explicit CubicKnots(int control_points);
  int control_points;
  std::vector<double> distinct;
  std::vector<int> multiplicities;
  // The n basis functions at t in [0, 1].
  std::vector<double> basis(double t) const;
};

// A tensor-product cubic patch: control[i * n + j], i along u, j along v, the same n both ways.
struct CubicPatch {
  int n = 0;
  std::vector<Point> control;
  const Point& at(int i, int j) const { return control[flat(i, n, j)]; }
  Point& at(int i, int j) { return control[flat(i, n, j)]; }
  Point evaluate(double u, double v) const;
};

// Fits an n x n patch to m x m samples (samples[i * m + j] at u = i/(m-1), v = j/(m-1)); m >= n.
// Boundary rows and columns come from the boundary samples only, their ends are the corner samples.
CubicPatch fit_patch(const std::vector<Point>& samples, int m, int n);

}  // namespace offsetgen::step
