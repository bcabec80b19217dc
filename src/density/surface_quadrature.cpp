#include "density/surface_quadrature.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::density {
namespace {

// The exponent 2k of the partition of unity w_i = n_i^(2k) / sum_j n_j^(2k).
constexpr int kPartitionPower = 8;
// The first grid of columns per face side, and the shift of the grid.
constexpr long kFirstGrid = 16;
constexpr double kGridShift = 0.0123456789;
// Scan intervals per column before isolation; the Hessian bound decides the rest.
constexpr int kScanIntervals = 16;
// The cell bounds come from a sampled search: a margin keeps the isolation on the safe side.
constexpr double kBoundMargin = 1.5;

int sign_of(double v) { return v < 0 ? -1 : 1; }

class ColumnRoots {
 public:
  ColumnRoots(FieldSampler& field, int axis, const std::array<double, 3>& p)
      : field_(field), curvature_(kBoundMargin * field.hessian_bound()) {
    field_.start_column(axis, p);
  }

  std::vector<double> find() {
    std::vector<ColumnValue> scan(kScanIntervals + 1);
    for (int j = 0; j < kScanIntervals; ++j) scan[static_cast<size_t>(j)] = field_.column(double(j) / kScanIntervals);
    scan[kScanIntervals] = scan[0];  // periodic
    for (int j = 0; j < kScanIntervals; ++j)
      isolate(double(j) / kScanIntervals, double(j + 1) / kScanIntervals, scan[static_cast<size_t>(j)],
              scan[static_cast<size_t>(j + 1)], 0);
    for (double& r : roots_)
      if (r >= 1) r -= 1;
    std::sort(roots_.begin(), roots_.end());
    roots_.erase(std::unique(roots_.begin(), roots_.end(), [](double a, double b) { return b - a < 1e-13; }),
                 roots_.end());
    return roots_;
  }

 private:
  void isolate(double a, double b, ColumnValue fa, ColumnValue fb, int depth) {
    const double w = b - a;
    if (sign_of(fa.value) != sign_of(fb.value)) {
      // One root when the slope keeps its sign over [a, b]: |f'' | <= H.
      if (std::fabs(fa.slope) > curvature_ * w || std::fabs(fb.slope) > curvature_ * w || depth > 50) {
        roots_.push_back(polish(a, b, fa, fb));
        return;
      }
    } else {
      const double s = sign_of(fa.value);
      const double va = s * fa.value, vb = s * fb.value, da = s * fa.slope, db = s * fb.slope;
      // Below |f| along tangent lines bent by the curvature bound, from each end to the middle.
      const double bend = curvature_ * w * w / 8;
      const double lower = std::min({va, va + da * w / 2 - bend, vb, vb - db * w / 2 - bend});
      if (lower > 0 || w < 1e-12) return;  // no root, or a tangency the weights ignore
    }
    const double m = (a + b) / 2;
    const ColumnValue fm = field_.column(m);
    isolate(a, m, fa, fm, depth + 1);
    isolate(m, b, fm, fb, depth + 1);
  }

  // Safeguarded Newton inside a sign-changing bracket.
  double polish(double a, double b, ColumnValue fa, ColumnValue fb) {
    double lo = a, hi = b;  // f(lo) < 0 <= f(hi) after orientation
    if (fa.value >= 0) std::swap(lo, hi);
    double x = fa.value == fb.value ? (a + b) / 2 : a - fa.value * (b - a) / (fb.value - fa.value);
    if (!(x > std::min(a, b) && x < std::max(a, b))) x = (a + b) / 2;
    for (int it = 0; it < 100; ++it) {
      const ColumnValue f = field_.column(x);
      if (f.value == 0) return x;
      (f.value < 0 ? lo : hi) = x;
      double next = f.slope != 0 ? x - f.value / f.slope : NAN;
      const double left = std::min(lo, hi), right = std::max(lo, hi);
      const bool newton = next > left && next < right;
      if (!newton) next = (lo + hi) / 2;
      // Newton converges quadratically: after a step below 1e-9 the next would be below rounding.
      if ((newton && std::fabs(next - x) <= 1e-9) || right - left <= 4e-16) return next;
      x = next;
    }
    return x;
  }

  FieldSampler& field_;
  double curvature_;
  std::vector<double> roots_;
};

// The sum of the integrand over the roots of one column, times the partition weight w_axis / |n_axis|.
class ColumnIntegrator {
 public:
  ColumnIntegrator(FieldSampler& field, const SurfaceIntegrand& integrand, size_t components)
      : field_(field), integrand_(integrand), components_(components), scratch_(components) {}

  void add(int axis, std::array<double, 3> p, std::vector<double>& total) {
    ++columns;
    const std::vector<double> roots = ColumnRoots(field_, axis, p).find();  // also starts the column
    for (double t : roots) {
      p[static_cast<size_t>(axis)] = t;
      SurfacePoint s;
      s.p = p;
      s.jet = field_.column_jet(t);
      double g2 = 0;
      for (double g : s.jet.gradient) g2 += g * g;
      s.gradient_norm = std::sqrt(g2);
      if (!(s.gradient_norm > 0)) continue;  // a singular point of F = 0: no normal, no weight
      double sum = 0;
      for (size_t i = 0; i < 3; ++i) {
        s.normal[i] = s.jet.gradient[i] / s.gradient_norm;
        sum += std::pow(s.normal[i] * s.normal[i], kPartitionPower / 2);
      }
      const double partition = std::pow(std::fabs(s.normal[static_cast<size_t>(axis)]), kPartitionPower - 1) / sum;
      std::fill(scratch_.begin(), scratch_.end(), 0.0);
      integrand_(s, scratch_);
      ++points;
      for (size_t c = 0; c < components_; ++c) total[c] += partition * scratch_[c];
    }
  }

  long columns = 0, points = 0;

 private:
  FieldSampler& field_;
  const SurfaceIntegrand& integrand_;
  size_t components_;
  std::vector<double> scratch_;
};

}  // namespace

QuadratureResult integrate_over_surface(FieldSampler& field, const SurfaceIntegrand& integrand,
                                        const QuadratureOptions& options) {
  const size_t n = options.tolerance.size();
  ColumnIntegrator columns(field, integrand, n);
  // Column positions s + i / N on each face: the grid of N / 2 is a subset of the grid of N, so each
  // doubling only adds columns. The shift keeps columns off the symmetry planes of the catalog.
  auto position = [](long i, long grid) { return kGridShift + double(i) / double(grid); };
  std::vector<double> sum(n, 0.0), previous, differences;
  QuadratureResult result;
  for (long grid = kFirstGrid; grid <= options.max_grid; grid *= 2) {
    const long step = grid == kFirstGrid ? 1 : 2;  // odd (i, j) pairs are new after a doubling
    for (int axis = 0; axis < 3; ++axis) {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      for (long i = 0; i < grid; ++i)
        for (long j = 0; j < grid; ++j) {
          if (step == 2 && i % 2 == 0 && j % 2 == 0) continue;
          std::array<double, 3> p{};
          p[static_cast<size_t>(a1)] = position(i, grid);
          p[static_cast<size_t>(a2)] = position(j, grid);
          columns.add(axis, p, sum);
        }
    }
    std::vector<double> value(n);
    for (size_t c = 0; c < n; ++c) value[c] = sum[c] / double(grid * grid);
    result.grid = grid;
    if (!previous.empty()) {
      // The difference d of two successive grids bounds the coarser one's error. The finer one's
      // error, with the geometric (or faster) convergence of the trapezoid rule on smooth periodic
      // integrands, is about d times the ratio of the last two differences.
      result.error.assign(n, 0.0);
      result.converged = grid >= options.min_grid;
      for (size_t c = 0; c < n; ++c) {
        const double d = std::fabs(value[c] - previous[c]);
        const double ratio = differences.empty() || !(differences[c] > 0) ? 1.0 : std::min(1.0, d / differences[c]);
        result.error[c] = d * ratio;
        result.converged = result.converged && result.error[c] <= options.tolerance[c];
      }
      if (options.accept) result.converged = result.converged && options.accept(value);
      differences.assign(n, 0.0);
      for (size_t c = 0; c < n; ++c) differences[c] = std::fabs(value[c] - previous[c]);
    }
    result.value = value;
    previous = value;
    if (result.converged) break;
  }
  result.columns = columns.columns;
  result.points = columns.points;
  return result;
}

}  // namespace offsetgen::density
