#include "check/thickness.h"

#include "numeric/root_finding.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace offsetgen::check {
namespace {

constexpr size_t kMissedListed = 8;

double length(const Point& v, int dims) {
  double s = 0;
  for (int i = 0; i < dims; ++i) s += v[static_cast<size_t>(i)] * v[static_cast<size_t>(i)];
  return std::sqrt(s);
}

Point unit_normal(const Probe& probe, const Point& p, double h) {
  Point n{};
  probe.normal(p.data(), h, n.data());
  return n;
}

// The unit normal of g at p by central differences (for walls whose normal has no closed form here).
Point numeric_normal(const std::function<double(const double*)>& g, const Point& p, int dims) {
  constexpr double step = 1e-6;
  Point n{};
  for (int i = 0; i < dims; ++i) {
    Point a = p, b = p;
    a[static_cast<size_t>(i)] += step;
    b[static_cast<size_t>(i)] -= step;
    n[static_cast<size_t>(i)] = (g(a.data()) - g(b.data())) / (2 * step);
  }
  const double len = length(n, dims);
  if (len > 0 && std::isfinite(len))
    for (auto& c : n) c /= len;
  else
    n = Point{};
  return n;
}

// |grad F| at p by central differences of the probe's field.
double gradient_length(const Probe& probe, const Point& p) {
  constexpr double step = 1e-6;
  Point g{};
  for (int i = 0; i < probe.dims; ++i) {
    Point a = p, b = p;
    a[static_cast<size_t>(i)] += step;
    b[static_cast<size_t>(i)] -= step;
    g[static_cast<size_t>(i)] = (probe.field(a.data()) - probe.field(b.data())) / (2 * step);
  }
  return length(g, probe.dims);
}

// Tells singular points: |grad F| below kSingularGradient of its median over the samples on F = 0.
// There (where branches of the zero set cross, or at a critical point on it) the offset is not
// defined to any order, and rays measure the geometry of the crossing, not the method.
class SingularTest {
 public:
  SingularTest(const Probe& probe, const std::vector<Point>& on_f) : probe_(probe) {
    std::vector<double> lengths;
    for (const auto& p : on_f) lengths.push_back(gradient_length(probe, p));
    if (!lengths.empty()) {
      std::nth_element(lengths.begin(), lengths.begin() + static_cast<long>(lengths.size() / 2), lengths.end());
      threshold_ = kSingularGradient * lengths[lengths.size() / 2];
    }
  }
  bool operator()(const Point& p) const { return !(gradient_length(probe_, p) >= threshold_); }

  // For a ray that found no crossing: the offset by h is not defined near q when the level sets of F
  // curve there on a scale below |h| (|h| ||Hess F|| >= |grad F|), as next to a crossing.
  bool beyond_reach(const Point& q, double h) const {
    constexpr double step = 1e-4;
    const int dims = probe_.dims;
    double hessian2 = 0;
    for (int i = 0; i < dims; ++i) {
      for (int j = 0; j < dims; ++j) {
        auto at = [&](double si, double sj) {
          Point r = q;
          r[static_cast<size_t>(i)] += si * step;
          r[static_cast<size_t>(j)] += sj * step;
          return probe_.field(r.data());
        };
        const double hij = (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * step * step);
        hessian2 += hij * hij;
      }
    }
    return !(std::fabs(h) * std::sqrt(hessian2) < gradient_length(probe_, q));
  }

 private:
  const Probe& probe_;
  double threshold_ = 0;
};

// The point at distance s along n from p.
Point along(const Point& p, const Point& n, double s, int dims) {
  Point q = p;
  for (int i = 0; i < dims; ++i) q[static_cast<size_t>(i)] += s * n[static_cast<size_t>(i)];
  return q;
}

void report(const ThicknessOptions& options, const std::string& what) {
  if (options.progress) options.progress(what);
}

std::vector<double> means(const std::vector<SweepRow>& rows, ErrorStats SweepRow::*member) {
  std::vector<double> out;
  for (const auto& r : rows) out.push_back((r.*member).mean);
  return out;
}

}  // namespace

Probe make_probe(const run::LoadedFunctions& f) {
  Probe probe;
  probe.dims = f.dims;
  const int dims = f.dims;
  if (f.field && f.offset && f.shell && f.normal) {
    probe.field = f.field;
    probe.offset = f.offset;
    probe.shell = f.shell;
    probe.normal = f.normal;
    if (f.graded) probe.graded = f.graded;
    return probe;
  }
  probe.float_only = true;
  auto to_float = [dims](const double* p) {
    std::array<float, 3> q{};
    for (int i = 0; i < dims; ++i) q[static_cast<size_t>(i)] = static_cast<float>(p[i]);
    return q;
  };
  auto fieldf = f.fieldf;
  auto offsetf = f.offsetf;
  auto shellf = f.shellf;
  auto normalf = f.normalf;
  auto gradedf = f.gradedf;
  probe.field = [=](const double* p) { return double(fieldf(to_float(p).data())); };
  probe.offset = [=](const double* p, double h) { return double(offsetf(to_float(p).data(), static_cast<float>(h))); };
  probe.shell = [=](const double* p, double t) { return double(shellf(to_float(p).data(), static_cast<float>(t))); };
  probe.normal = [=](const double* p, double h, double* n) {
    std::array<float, 3> m{};
    normalf(to_float(p).data(), static_cast<float>(h), m.data());
    for (int i = 0; i < dims; ++i) n[i] = m[static_cast<size_t>(i)];
  };
  if (gradedf) probe.graded = [=](const double* p) { return double(gradedf(to_float(p).data())); };
  return probe;
}

void ErrorStats::add(double relative_error, const Point& where) {
  ++rays;
  ++crossed;
  sum += relative_error;
  if (!(relative_error <= max)) {  // also replaces the initial NaN
    max = relative_error;
    worst = where;
  }
}

void ErrorStats::miss(const Point& where) {
  ++rays;
  ++missed;
  if (missed_at.size() < kMissedListed) missed_at.push_back(where);
}

void ErrorStats::finish() { mean = crossed > 0 ? sum / crossed : NAN; }

std::vector<Point> sample_zero_set(const std::function<double(const double*)>& g, int dims, int grid, int scan) {
  std::vector<Point> points;
  const int free_axes = dims - 1;
  const int solved = dims - 1;
  const int columns = free_axes == 2 ? grid * grid : grid;
  for (int c = 0; c < columns; ++c) {
    Point p{};
    p[0] = grid > 1 ? static_cast<double>(c % grid) / (grid - 1) : 0.0;
    if (free_axes == 2) p[1] = grid > 1 ? static_cast<double>(c / grid) / (grid - 1) : 0.0;
    auto along = [&](double v) {
      Point q = p;
      q[static_cast<size_t>(solved)] = v;
      return g(q.data());
    };
    for (double root : numeric::roots_in_interval(along, 0.0, 1.0, scan)) {
      Point q = p;
      q[static_cast<size_t>(solved)] = root;
      points.push_back(q);
    }
  }
  return points;
}

std::optional<double> ray_crossing(const std::function<double(const double*)>& g, const Point& p, const Point& n,
                                   int dims, double expected, double reach) {
  auto along = [&](double s) {
    Point q = p;
    for (int i = 0; i < dims; ++i) q[static_cast<size_t>(i)] += s * n[static_cast<size_t>(i)];
    return g(q.data());
  };
  return numeric::root_near(along, expected, reach);
}

ThicknessReport measure_constant(const Probe& probe, const ThicknessOptions& options) {
  ThicknessReport out;
  out.grid = options.grid;
  out.scan = options.scan;
  const int dims = probe.dims;
  report(options, "sampling F = 0");
  const std::vector<Point> on_f = sample_zero_set(probe.field, dims, options.grid, options.scan);
  out.samples_on_f = static_cast<int>(on_f.size());
  std::vector<Point> normals;
  for (const auto& p : on_f) normals.push_back(unit_normal(probe, p, 0.0));
  const SingularTest singular(probe, on_f);
  std::vector<char> singular_on_f;
  for (const auto& p : on_f) singular_on_f.push_back(singular(p) ? 1 : 0);
  out.singular_on_f = static_cast<int>(std::count(singular_on_f.begin(), singular_on_f.end(), 1));

  int index = 0;
  for (double h : options.h) {
    ++index;
    report(options, fmt::format("h = {:g} ({}/{})", h, index, options.h.size()));
    SweepRow row;
    row.h = h;
    const double ah = std::fabs(h);
    auto offset_at_h = [&](const double* q) { return probe.offset(q, h); };
    auto shell_at_t = [&](const double* q) { return probe.shell(q, 2 * ah); };
    for (size_t i = 0; i < on_f.size(); ++i) {
      const Point& p = on_f[i];
      const Point& n = normals[i];
      if (singular_on_f[i]) {
        ++row.f_to_phi.singular;
        if (options.shell) ++row.shell.singular;
        continue;
      }
      if (length(n, dims) == 0) {
        row.f_to_phi.miss(p);
        if (options.shell) row.shell.miss(p);
        continue;
      }
      // F -> phi: distance along +n to phi(., h) = 0, expected h
      if (auto s = ray_crossing(offset_at_h, p, n, dims, h, ah)) {
        row.f_to_phi.add(std::fabs(*s - h) / ah, p);
      } else if (singular.beyond_reach(p, h)) {
        ++row.f_to_phi.singular;
      } else {
        row.f_to_phi.miss(p);
      }
      // the shell: both walls of Phi(., t) with t = 2|h|, total thickness against t
      if (options.shell) {
        auto plus = ray_crossing(shell_at_t, p, n, dims, ah, ah);
        auto minus = ray_crossing(shell_at_t, p, n, dims, -ah, ah);
        if (plus && minus) {
          row.shell.add(std::fabs((*plus - *minus) - 2 * ah) / (2 * ah), p);
        } else if (singular.beyond_reach(p, h)) {
          ++row.shell.singular;
        } else {
          row.shell.miss(p);
        }
      }
    }
    // phi -> F: points on phi(., h) = 0, rays along the offset surface's own normal back to F = 0
    for (const Point& q : sample_zero_set(offset_at_h, dims, options.grid, options.scan)) {
      const Point n = unit_normal(probe, q, h);
      // Singular when F's gradient vanishes at the expected foot point q - h n, or where the ray lands.
      if (length(n, dims) > 0 && singular(along(q, n, -h, dims))) {
        ++row.phi_to_f.singular;
        continue;
      }
      if (length(n, dims) == 0) {
        row.phi_to_f.miss(q);
        continue;
      }
      const auto s = ray_crossing(probe.field, q, n, dims, -h, ah);
      if (s && singular(along(q, n, *s, dims))) {
        ++row.phi_to_f.singular;
        continue;
      }
      if (s) {
        row.phi_to_f.add(std::fabs(-*s - h) / ah, q);
      } else if (singular.beyond_reach(q, h)) {
        ++row.phi_to_f.singular;
      } else {
        row.phi_to_f.miss(q);
      }
    }
    row.f_to_phi.finish();
    row.phi_to_f.finish();
    row.shell.finish();
    out.rows.push_back(row);
  }
  std::vector<double> hs;
  for (const auto& r : out.rows) hs.push_back(std::fabs(r.h));
  out.fit_f_to_phi = fit_order(hs, means(out.rows, &SweepRow::f_to_phi));
  out.fit_phi_to_f = fit_order(hs, means(out.rows, &SweepRow::phi_to_f));
  if (options.shell) out.fit_shell = fit_order(hs, means(out.rows, &SweepRow::shell));
  return out;
}

namespace {

GradedRow measure_graded_row(const Probe& probe, ThicknessFunction& thickness, const std::vector<Point>& on_f,
                             const std::vector<Point>& normals, const SingularTest& singular,
                             const std::vector<char>& singular_on_f, double lambda, bool compiled,
                             const ThicknessOptions& options) {
  const int dims = probe.dims;
  GradedRow row;
  row.lambda = lambda;
  row.compiled_graded = compiled;
  auto h_at = [&](const double* q) { return 0.5 * lambda * thickness(q); };
  auto wall = [&](double sign) -> std::function<double(const double*)> {
    if (probe.graded_wall) return [&, sign](const double* q) { return probe.graded_wall(q, sign * lambda); };
    return [&, sign](const double* q) { return probe.offset(q, sign * h_at(q)); };
  };
  const auto w_plus = wall(+1), w_minus = wall(-1);
  const std::string skip_reason = "target thickness <= 0 at the point (relative error undefined)";

  for (size_t i = 0; i < on_f.size(); ++i) {
    const Point& p = on_f[i];
    const double h0 = h_at(p.data());
    if (!(h0 > 0)) {
      ++row.total.skipped;
      ++row.one_sided.skipped;
      row.total.skipped_reason = row.one_sided.skipped_reason = skip_reason;
      continue;
    }
    if (singular_on_f[i]) {
      ++row.total.singular;
      ++row.one_sided.singular;
      continue;
    }
    const Point& n = normals[i];
    if (length(n, dims) == 0) {
      row.total.miss(p);
      row.one_sided.miss(p);
      row.one_sided.miss(p);
      continue;
    }
    std::optional<double> plus, minus;
    if (compiled) {
      plus = ray_crossing(probe.graded, p, n, dims, h0, h0);
      minus = ray_crossing(probe.graded, p, n, dims, -h0, h0);
    } else {
      plus = ray_crossing(w_plus, p, n, dims, h0, h0);
      minus = ray_crossing(w_minus, p, n, dims, -h0, h0);
    }
    if (plus && minus) {
      row.total.add(std::fabs((*plus - *minus) - 2 * h0) / (2 * h0), p);
    } else {
      row.total.miss(p);
    }
    if (plus) {
      row.one_sided.add(std::fabs(*plus - h0) / h0, p);
    } else {
      row.one_sided.miss(p);
    }
    if (minus) {
      row.one_sided.add(std::fabs(-*minus - h0) / h0, p);
    } else {
      row.one_sided.miss(p);
    }
  }

  // The paper's measure: from the walls back to F, along each wall's own normal.
  for (double sign : {+1.0, -1.0}) {
    const auto& w = sign > 0 ? w_plus : w_minus;
    for (const Point& q : sample_zero_set(w, dims, options.grid, options.scan)) {
      const double hq = h_at(q.data());
      if (!(hq > 0)) {
        ++row.paper.skipped;
        row.paper.skipped_reason = skip_reason;
        continue;
      }
      const Point n = numeric_normal(w, q, dims);
      if (length(n, dims) == 0) {
        row.paper.miss(q);
        continue;
      }
      const auto s = ray_crossing(probe.field, q, n, dims, -sign * hq, hq);
      if (singular(along(q, n, s ? *s : -sign * hq, dims))) {
        ++row.paper.singular;
      } else if (s) {
        row.paper.add(std::fabs(-sign * *s - hq) / hq, q);
      } else {
        row.paper.miss(q);
      }
    }
  }
  row.total.finish();
  row.one_sided.finish();
  row.paper.finish();
  return row;
}

}  // namespace

GradedReport measure_graded(const Probe& probe, ThicknessFunction& thickness, const std::string& expression,
                            bool use_compiled_graded, const ThicknessOptions& options) {
  GradedReport out;
  out.expression = expression;
  const int dims = probe.dims;
  // the peak of t over the cell, on a fine grid
  constexpr int kPeakGrid = 41;
  double peak = 0;
  const int cells = dims == 3 ? kPeakGrid * kPeakGrid * kPeakGrid : kPeakGrid * kPeakGrid;
  for (int c = 0; c < cells; ++c) {
    Point p{};
    int rest = c;
    for (int i = 0; i < dims; ++i) {
      p[static_cast<size_t>(i)] = static_cast<double>(rest % kPeakGrid) / (kPeakGrid - 1);
      rest /= kPeakGrid;
    }
    const double t = thickness(p.data());
    if (std::isfinite(t)) peak = std::max(peak, t);
  }
  out.t_peak = peak;
  if (!(peak > 0)) return out;  // nothing to measure; the caller reports it

  report(options, "graded: sampling F = 0");
  const std::vector<Point> on_f = sample_zero_set(probe.field, dims, options.grid, options.scan);
  std::vector<Point> normals;
  for (const auto& p : on_f) normals.push_back(unit_normal(probe, p, 0.0));
  const SingularTest singular(probe, on_f);
  std::vector<char> singular_on_f;
  for (const auto& p : on_f) singular_on_f.push_back(singular(p) ? 1 : 0);

  int index = 0;
  for (double h_max : options.h) {
    ++index;
    if (!(h_max > 0)) continue;
    report(options, fmt::format("graded h_max = {:g} ({}/{})", h_max, index, options.h.size() + 1));
    const double lambda = 2 * h_max / peak;
    GradedRow row =
        measure_graded_row(probe, thickness, on_f, normals, singular, singular_on_f, lambda, false, options);
    row.h_max = h_max;
    out.rows.push_back(row);
  }
  report(options, "graded: as given");
  GradedRow given = measure_graded_row(probe, thickness, on_f, normals, singular, singular_on_f, 1.0,
                                       use_compiled_graded && probe.graded != nullptr, options);
  given.as_given = true;
  given.h_max = peak / 2;
  out.rows.push_back(given);

  std::vector<double> hs, total, one_sided, paper;
  for (const auto& r : out.rows) {
    if (r.as_given) continue;
    hs.push_back(r.h_max);
    total.push_back(r.total.mean);
    one_sided.push_back(r.one_sided.mean);
    paper.push_back(r.paper.mean);
  }
  out.fit_total = fit_order(hs, total);
  out.fit_one_sided = fit_order(hs, one_sided);
  out.fit_paper = fit_order(hs, paper);
  return out;
}

}  // namespace offsetgen::check
