#include "lowering/sample_region.h"

#include "field/atom_table.h"
#include "lowering/point_program.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace offsetgen {

SampleRegion::SampleRegion(const Surface& surface) : dims_(surface.dims), mapped_(surface.mapped()) {
  const double k = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
  for (int i = 0; i < dims_; ++i) {
    lo_.push_back(surface.domain ? surface.domain->lo[static_cast<size_t>(i)] : 0.0);
    hi_.push_back(surface.domain ? surface.domain->hi[static_cast<size_t>(i)] : k);
  }
  clearance_ = surface.singular_clearance;
  if (surface.singular_measures.empty()) return;
  measures_ = std::make_unique<Program>(point_program(dims_, surface.singular_measures, AtomTable()));
  evaluate_ = std::make_unique<Evaluator>(*measures_);
}

SampleRegion::SampleRegion(const SampleRegion& other)
    : dims_(other.dims_), mapped_(other.mapped_), clearance_(other.clearance_), lo_(other.lo_), hi_(other.hi_) {
  if (other.measures_) {
    measures_ = std::make_unique<Program>(*other.measures_);
    evaluate_ = std::make_unique<Evaluator>(*measures_);
  }
}

SampleRegion::~SampleRegion() = default;

std::vector<double> SampleRegion::at(const std::vector<double>& t) const {
  std::vector<double> p(t.size());
  for (size_t i = 0; i < t.size(); ++i) p[i] = lo_[i] + (hi_[i] - lo_[i]) * t[i];
  return p;
}

double SampleRegion::singular_measure(const std::vector<double>& p) {
  if (!evaluate_) return std::numeric_limits<double>::infinity();
  double lowest = std::numeric_limits<double>::infinity();
  for (double m : (*evaluate_)(p)) lowest = std::fmin(lowest, m);
  return lowest;
}

bool SampleRegion::contains(const std::vector<double>& p) {
  for (size_t i = 0; i < p.size(); ++i)
    if (!(p[i] >= lo_[i] && p[i] <= hi_[i])) return false;
  return !evaluate_ || singular_measure(p) >= clearance_;
}

std::string SampleRegion::describe() const {
  if (!mapped_) return fmt::format("the cell [0, 1]^{}", dims_);
  std::string box;
  for (int i = 0; i < dims_; ++i)
    box += fmt::format("{}[{:g}, {:g}]", i ? " x " : "", lo_[static_cast<size_t>(i)], hi_[static_cast<size_t>(i)]);
  return "the domain " + box;
}

namespace {
// Per start of the compass search; a smooth maximum needs a few hundred.
constexpr int kMaxSearchEvaluations = 20000;
}  // namespace

// The maximum of f over the sample region (one cell, or a mapped surface's domain): a grid, then
// compass refinement from the 8 best samples. Non-finite values (poles of log, 1/x, ...) and points
// outside the region are skipped and the refinement is capped, so a pole cannot stall it.
double maximum_over_region(SampleRegion& region, const std::function<double(const std::vector<double>&)>& f,
                           const std::string& what, std::vector<double>* argmax) {
  const int dims = region.dims();
  // One cell: 24 samples per axis and 8 compass starts find its maximum. A mapped domain holds many
  // cells, each with its own local maxima: twice the samples and 16 times the starts (a missed
  // maximum would leave the safeguard's M too small, and walls off by a fraction of h).
  const int n = (dims == 3 ? 24 : 96) * (region.mapped() ? 2 : 1);
  const size_t max_starts = region.mapped() ? 128 : 8;
  double extent = 0;  // the longest side sets the compass steps
  for (int i = 0; i < dims; ++i) extent = std::max(extent, region.hi(i) - region.lo(i));
  auto value_at = [&](const std::vector<double>& p) { return region.contains(p) ? f(p) : NAN; };
  std::vector<std::pair<double, std::vector<double>>> best;
  std::vector<double> p(static_cast<size_t>(dims));
  const int total = dims == 3 ? n * n * n : n * n;
  for (int index = 0; index < total; ++index) {
    int rest = index;
    for (int i = 0; i < dims; ++i) {
      p[static_cast<size_t>(i)] = region.lo(i) + (region.hi(i) - region.lo(i)) * (rest % n + 0.5) / n;
      rest /= n;
    }
    const double value = value_at(p);
    if (std::isfinite(value)) best.push_back({value, p});
  }
  if (best.empty())
    throw std::runtime_error(what + " is not finite anywhere on " + region.describe() +
                             ", so the safeguard has no bound");
  const size_t starts = std::min<size_t>(max_starts, best.size());
  std::partial_sort(best.begin(), best.begin() + static_cast<long>(starts), best.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });

  double maximum = best.front().first;
  if (argmax) *argmax = best.front().second;
  for (size_t s = 0; s < starts; ++s) {
    auto [value, point] = best[s];
    int evaluations = 0;
    for (double step = extent / n; step > extent * 1e-13 && evaluations < kMaxSearchEvaluations;) {
      bool improved = false;
      for (int i = 0; i < dims && !improved; ++i) {
        for (double direction : {1.0, -1.0}) {
          auto trial = point;
          trial[static_cast<size_t>(i)] =
              std::clamp(trial[static_cast<size_t>(i)] + direction * step, region.lo(i), region.hi(i));
          const double v = value_at(trial);
          ++evaluations;
          if (std::isfinite(v) && v > value) {
            value = v;
            point = trial;
            improved = true;
            break;
          }
        }
      }
      if (!improved) step *= 0.5;
    }
    if (value > maximum) {
      maximum = value;
      if (argmax) *argmax = point;
    }
  }
  return maximum;
}

std::string point_text(const std::vector<double>& p) {
  std::string names = p.size() == 3 ? "x, y, z" : "x, y";
  std::string values;
  double size = 0;
  for (double c : p) size = std::fmax(size, std::fabs(c));
  // Rounding residue of a search that converged to 0 prints as 0.
  for (double c : p)
    values += fmt::format("{}{:.4g}", values.empty() ? "" : ", ", std::fabs(c) < 1e-12 * size ? 0.0 : c + 0.0);
  return fmt::format("({}) = ({})", names, values);
}

}  // namespace offsetgen
