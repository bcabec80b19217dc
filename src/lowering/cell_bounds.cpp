#include "lowering/cell_bounds.h"

#include "lowering/catalog_sweeps.h"
#include "lowering/point_program.h"
#include "lowering/sample_region.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

namespace offsetgen {
namespace {

// Largest |eigenvalue| of a symmetric 2x2 or 3x3 matrix (row-major), in closed form.
double symmetric_spectral_norm(const std::vector<double>& a, int dims) {
  if (dims == 2) {
    const double mean = (a[0] + a[3]) / 2, radius = std::hypot((a[0] - a[3]) / 2, a[1]);
    return std::fabs(mean) + radius;
  }
  const double off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
  const double q = (a[0] + a[4] + a[8]) / 3;
  const double d0 = a[0] - q, d1 = a[4] - q, d2 = a[8] - q;
  const double p = std::sqrt((d0 * d0 + d1 * d1 + d2 * d2 + 2 * off) / 6);
  if (!(p > 0)) return std::fabs(q);
  // Eigenvalues q + 2p cos(theta + 2 pi k / 3), theta = acos(det((A - q I) / p) / 2) / 3.
  const double det = d0 * (d1 * d2 - a[5] * a[5]) - a[1] * (a[1] * d2 - a[5] * a[2]) + a[2] * (a[1] * a[5] - d1 * a[2]);
  const double r = std::clamp(det / (2 * p * p * p), -1.0, 1.0);
  const double theta = std::acos(r) / 3;
  const double largest = q + 2 * p * std::cos(theta);
  const double smallest = q + 2 * p * std::cos(theta + 2.0943951023931957);
  return std::max(std::fabs(largest), std::fabs(smallest));
}

}  // namespace

double max_gradient_norm(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field) {
  const Program program = point_program(surface.dims, field.gradient(), atoms);
  Evaluator gradient(program);  // keeps a reference to the program
  auto norm2 = [&](const std::vector<double>& p) {
    double sum = 0;
    for (double g : gradient(p)) sum += g * g;
    return sum;
  };
  SampleRegion region(surface);
  const double maximum = maximum_over_region(region, norm2, "the gradient of F");
  // A relative margin well above the refinement's resolution keeps M an upper bound, also after
  // rounding to float.
  return std::sqrt(maximum) * (1 + 1e-6);
}

double max_hessian_norm(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field) {
  if (!field.has_hessian()) return 0;
  std::vector<GiNaC::ex> entries;
  for (int i = 0; i < field.dims; ++i)
    for (int j = 0; j < field.dims; ++j) entries.push_back(field.hessian(i, j));
  const Program program = point_program(surface.dims, entries, atoms);
  Evaluator hessian(program);
  auto norm = [&](const std::vector<double>& p) { return symmetric_spectral_norm(hessian(p), surface.dims); };
  SampleRegion region(surface);
  return maximum_over_region(region, norm, "the Hessian of F") * (1 + 1e-6);
}

std::vector<double> min_gradient_in_bands(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field,
                                          const CellBounds& bounds, const std::vector<double>& levels) {
  std::vector<GiNaC::ex> outputs = {field.field()};
  for (int i = 0; i < surface.dims; ++i) outputs.push_back(field.gradient(i));
  const Program program = point_program(surface.dims, outputs, atoms);
  Evaluator evaluate(program);
  const int dims = surface.dims;
  SampleRegion region(surface);
  std::vector<double> lowest(levels.size(), INFINITY);
  // Best-first branch and bound over boxes (centre c, half side a, half-diagonal r): every point of a
  // box has |F| >= |F(c)| - M r and |grad F| >= |grad F(c)| - H r. Per band, the box with the lowest
  // such bound is split until that bound is within 1/8 of the least |grad F| seen at a centre in the
  // band, or an evaluation budget runs out; the lowest bound left is the answer.
  constexpr int kCoarse = 16;
  constexpr size_t kBudget = 60000;  // per band
  struct Box {
    double lower;  // lower bound of |grad F| in the box
    double half;   // the largest half side
    std::vector<double> c;
    bool operator<(const Box& o) const { return lower > o.lower; }  // a min-heap in std::priority_queue
  };
  auto probe = [&](std::vector<double> c, double half, double level, double& seen) -> std::optional<Box> {
    const double r = half * std::sqrt(static_cast<double>(dims));
    if (!region.contains(c)) return std::nullopt;  // near a mapped surface's singular set
    const auto& v = evaluate(c);
    const double f = std::fabs(v[0]);
    if (f - bounds.gradient * r > level) return std::nullopt;  // not in the band
    double g2 = 0;
    for (size_t i = 1; i < v.size(); ++i) g2 += v[i] * v[i];
    const double g = std::sqrt(g2);
    if (f <= level) seen = std::min(seen, g);
    return Box{g - bounds.hessian * r, half, std::move(c)};
  };
  for (size_t k = 0; k < levels.size(); ++k) {
    std::priority_queue<Box> queue;
    double seen = INFINITY;
    // Boxes' half sides per axis (equal for a cell), scaled alike when split.
    std::vector<double> halves0(static_cast<size_t>(dims));
    double half0 = 0;
    for (int i = 0; i < dims; ++i) {
      halves0[static_cast<size_t>(i)] = (region.hi(i) - region.lo(i)) / kCoarse / 2;
      half0 = std::max(half0, halves0[static_cast<size_t>(i)]);
    }
    const int total = dims == 3 ? kCoarse * kCoarse * kCoarse : kCoarse * kCoarse;
    for (int index = 0; index < total; ++index) {
      std::vector<double> c(static_cast<size_t>(dims));
      int rest = index;
      for (int i = 0; i < dims; ++i) {
        c[static_cast<size_t>(i)] = region.lo(i) + (2 * (rest % kCoarse) + 1) * halves0[static_cast<size_t>(i)];
        rest /= kCoarse;
      }
      if (auto b = probe(std::move(c), half0, levels[k], seen)) queue.push(std::move(*b));
    }
    size_t evaluations = static_cast<size_t>(total);
    while (!queue.empty() && queue.top().lower < seen * 7 / 8 && evaluations < kBudget) {
      Box b = queue.top();
      queue.pop();
      for (int corner = 0; corner < (1 << dims); ++corner) {
        std::vector<double> c = b.c;
        for (int i = 0; i < dims; ++i) {
          const double half = b.half * halves0[static_cast<size_t>(i)] / half0;
          c[static_cast<size_t>(i)] += ((corner >> i) & 1 ? half : -half) / 2;
        }
        if (auto child = probe(std::move(c), b.half / 2, levels[k], seen)) queue.push(std::move(*child));
        ++evaluations;
      }
    }
    lowest[k] = queue.empty() ? seen : queue.top().lower;
  }
  for (double& g : lowest) g = std::isfinite(g) ? std::max(0.0, g) : 0.0;
  return lowest;
}

std::vector<double> lipschitz_band_levels(const CellBounds& bounds, double scale) {
  std::vector<double> levels;
  for (double h : kLipschitzHalfThicknesses) levels.push_back(2 * bounds.gradient * scale * h);
  return levels;
}

std::vector<double> lipschitz_band_minima(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field,
                                          const CellBounds& bounds) {
  // The table's minima hold for the bands of its own bounds only.
  const CatalogSweeps* known = catalog_sweeps(surface);
  if (known && field.has_hessian() && bounds.gradient == known->bounds.gradient &&
      bounds.hessian == known->bounds.hessian)
    return {known->band_minima.begin(), known->band_minima.end()};
  const double scale = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
  return min_gradient_in_bands(surface, atoms, field, bounds, lipschitz_band_levels(bounds, scale));
}

CellBounds swept_cell_bounds(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field) {
  return {max_gradient_norm(surface, atoms, field), max_hessian_norm(surface, atoms, field)};
}

CellBounds cell_bounds(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field) {
  if (const CatalogSweeps* known = catalog_sweeps(surface))
    return {known->bounds.gradient, field.has_hessian() ? known->bounds.hessian : 0.0};
  return swept_cell_bounds(surface, atoms, field);
}

}  // namespace offsetgen
