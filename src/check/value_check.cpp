#include "check/value_check.h"

#include "check/domain_cube.h"
#include "offset/offset_reference.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <type_traits>
#include <utility>

namespace offsetgen::check {
namespace {

class DigitsScope {
 public:
  explicit DigitsScope(int digits) : saved_(GiNaC::Digits) { GiNaC::Digits = static_cast<long>(digits); }
  ~DigitsScope() { GiNaC::Digits = saved_; }
  DigitsScope(const DigitsScope&) = delete;
  DigitsScope& operator=(const DigitsScope&) = delete;

 private:
  long saved_;
};

double dbl(const GiNaC::numeric& n) { return n.to_double(); }

struct Accumulator {
  FunctionDeviation d;
  double sum = 0;
  Accumulator(std::string function, bool is_float, std::string measure, double tolerance) {
    d.function = std::move(function);
    d.is_float = is_float;
    d.measure = std::move(measure);
    d.tolerance = tolerance;
  }
  void add(double shift, const std::vector<double>& where) {
    if (std::isnan(shift)) shift = INFINITY;
    ++d.points;
    sum += shift;
    if (shift > d.max_shift || d.worst_point.empty()) {
      d.max_shift = std::max(d.max_shift, shift);
      d.worst_point = where;
    }
  }
  FunctionDeviation done() {
    d.mean_shift = d.points > 0 ? sum / d.points : 0;
    d.pass = d.max_shift <= d.tolerance;  // NaN and inf fail
    return d;
  }
};

}  // namespace

int default_value_points(int order) { return order <= 4 ? 200 : (order <= 6 ? 60 : 16); }

GiNaC::numeric exact(double value) {
  if (value == 0 || !std::isfinite(value)) return GiNaC::numeric(0);
  int exponent = 0;
  const double mantissa = std::frexp(value, &exponent);  // value = mantissa * 2^exponent, |mantissa| in [0.5, 1)
  const auto integer = static_cast<long>(std::ldexp(mantissa, 53));
  return GiNaC::numeric(integer) * GiNaC::numeric(2).power(exponent - 53);
}

namespace {

// One random point with everything the 40-digit model says about it.
struct Sample {
  std::vector<double> p;  // cell units, representable in float
  double h = 0, t = 0;    // h in [-h_max, h_max], t = 2|h|
  double grad_norm = 0;   // |grad F| in cell units
  double field = 0, phi = 0, shell = 0, shell_scale = 0;
  std::optional<std::vector<double>> normal;  // unit normal of phi(., h), every stride-th point
  std::optional<double> graded, graded_scale, t_of_x;
};

std::vector<Sample> reference_samples(const Reference& reference, const run::FileMetadata& meta,
                                      const std::optional<GiNaC::ex>& thickness, const ValueCheckOptions& options) {
  const Generation& g = reference.generation;
  OffsetReference hp(g.surface, *g.construction, options.digits);
  const int dims = meta.dims;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  // A mapped file: points in the cube centred in its domain, h in its sides (check/domain_cube.h).
  const DomainCube cube = domain_cube(meta);
  std::uniform_real_distribution<double> distance(-options.h_max * cube.side, options.h_max * cube.side);
  const int points = options.points > 0 ? options.points : default_value_points(meta.order);
  const int stride = std::max(1, options.normal_stride);

  std::vector<Sample> samples;
  for (int i = 0; i < points; ++i) {
    if (options.progress) options.progress(i, points);
    Sample s;
    std::vector<GiNaC::numeric> x(static_cast<size_t>(dims));
    for (int k = 0; k < dims; ++k) {
      // float and double functions see the same point: draw it representable in float
      s.p.push_back(static_cast<double>(static_cast<float>(cube.at(k, coordinate(rng)))));
      x[static_cast<size_t>(k)] = exact(s.p.back());
    }
    s.h = static_cast<double>(static_cast<float>(distance(rng)));
    s.t = 2 * std::fabs(s.h);
    const GiNaC::numeric hn = exact(s.h), tn = exact(s.t);
    {
      DigitsScope digits(options.digits);
      GiNaC::numeric sum = 0;
      for (const auto& c : hp.field_gradient(x)) sum += c * c;
      s.grad_norm = std::sqrt(dbl(sum));
    }
    s.field = dbl(hp.field(x));
    s.phi = dbl(hp.offset(x, hn));
    if (i % stride == 0) {
      // the unit normal, from the method's own reference (the projection's is n at the last foot-point
      // estimate, which equals grad phi / |grad phi| on the zero set only)
      std::vector<double> n;
      double len2 = 0;
      for (const auto& c : hp.normal(x, hn)) {
        n.push_back(dbl(c));
        len2 += n.back() * n.back();
      }
      if (len2 > 0) s.normal = n;
    }
    const GiNaC::numeric plus = hp.offset(x, tn / 2), minus = hp.offset(x, -tn / 2);
    s.shell = dbl(plus * minus);
    s.shell_scale = s.grad_norm * (std::fabs(dbl(plus)) + std::fabs(dbl(minus)));
    if (thickness) {
      GiNaC::numeric tx;
      {
        DigitsScope digits(options.digits);
        GiNaC::exmap subs;
        for (int k = 0; k < dims; ++k) subs[Symbols::get().cell(k)] = x[static_cast<size_t>(k)];
        tx = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(thickness->subs(subs)));
      }
      // The scale of the shell's rounding: phi at +-t(p)/2 (the graded walls read t where the method does).
      const GiNaC::numeric gp = hp.offset(x, tx / 2), gm = hp.offset(x, -tx / 2);
      s.graded = dbl(hp.graded(x, *thickness));
      s.graded_scale = s.grad_norm * (std::fabs(dbl(gp)) + std::fabs(dbl(gm)));
      s.t_of_x = dbl(tx);
    }
    samples.push_back(std::move(s));
  }
  return samples;
}

std::vector<double> with(std::vector<double> p, double extra) {
  p.push_back(extra);
  return p;
}

const char* const kFieldMeasure = "|dF| / |grad F|";
const char* const kOffsetMeasure = "|dphi| / |grad F|";
const char* const kShellMeasure = "|dPhi| / (|grad F| (|phi+| + |phi-|))";
const char* const kGradedMeasure = "|dPhi| / (|grad F| (|phi+| + |phi-|)), t = t(x)";
const char* const kNormalMeasure = "|dn| (unit normal, vs the method's 40-digit normal)";

// The scalar C functions of one precision (T = double or float).
template <typename T>
struct Scalar {
  T (*field)(const T*);
  T (*offset)(const T*, T);
  T (*shell)(const T*, T);
  void (*normal)(const T*, T, T*);
  T (*graded)(const T*);
};

template <typename T>
void compare_scalar(const Scalar<T>& f, const char* suffix, const std::vector<Sample>& samples, int dims, double tol,
                    double normal_tol, std::vector<FunctionDeviation>& out) {
  const bool is_float = std::is_same<T, float>::value;
  const std::string sfx = suffix;
  Accumulator field("field" + sfx, is_float, kFieldMeasure, tol), offset("offset" + sfx, is_float, kOffsetMeasure, tol),
      shell("shell" + sfx, is_float, kShellMeasure, tol), graded("graded" + sfx, is_float, kGradedMeasure, tol),
      normal("normal" + sfx, is_float, kNormalMeasure, normal_tol);
  std::vector<T> p(static_cast<size_t>(dims)), n(static_cast<size_t>(dims));
  for (const Sample& s : samples) {
    for (int k = 0; k < dims; ++k) p[static_cast<size_t>(k)] = static_cast<T>(s.p[static_cast<size_t>(k)]);
    const T h = static_cast<T>(s.h), t = static_cast<T>(s.t);
    if (f.field) field.add(std::fabs(double(f.field(p.data())) - s.field) / s.grad_norm, s.p);
    if (f.offset) offset.add(std::fabs(double(f.offset(p.data(), h)) - s.phi) / s.grad_norm, with(s.p, s.h));
    if (f.shell) shell.add(std::fabs(double(f.shell(p.data(), t)) - s.shell) / s.shell_scale, with(s.p, s.t));
    if (f.graded && s.graded)
      graded.add(std::fabs(double(f.graded(p.data())) - *s.graded) / *s.graded_scale, with(s.p, *s.t_of_x));
    if (f.normal && s.normal) {
      f.normal(p.data(), h, n.data());
      double e2 = 0;
      for (int k = 0; k < dims; ++k)
        e2 += std::pow(double(n[static_cast<size_t>(k)]) - (*s.normal)[static_cast<size_t>(k)], 2);
      normal.add(std::sqrt(e2), with(s.p, s.h));
    }
  }
  for (Accumulator* a : {&field, &offset, &shell, &graded, &normal})
    if (a->d.points > 0) out.push_back(a->done());
}

// The batch functions: one call over all points, coordinates as separate arrays.
template <typename T>
void compare_batch(run::BatchFunction<T> offset_n, run::BatchFunction<T> shell_n, const char* suffix,
                   const std::vector<Sample>& samples, int dims, double tol, std::vector<FunctionDeviation>& out) {
  const bool is_float = std::is_same<T, float>::value;
  const size_t n = samples.size();
  std::vector<std::vector<T>> coords(3, std::vector<T>(n, T(0)));
  std::vector<T> h(n), t(n), result(n);
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dims; ++k)
      coords[static_cast<size_t>(k)][i] = static_cast<T>(samples[i].p[static_cast<size_t>(k)]);
    h[i] = static_cast<T>(samples[i].h);
    t[i] = static_cast<T>(samples[i].t);
  }
  if (offset_n) {
    Accumulator a(std::string("offset") + suffix + "_n", is_float, kOffsetMeasure, tol);
    offset_n(n, coords[0].data(), coords[1].data(), coords[2].data(), h.data(), result.data());
    for (size_t i = 0; i < n; ++i)
      a.add(std::fabs(double(result[i]) - samples[i].phi) / samples[i].grad_norm, with(samples[i].p, samples[i].h));
    out.push_back(a.done());
  }
  if (shell_n) {
    Accumulator a(std::string("shell") + suffix + "_n", is_float, kShellMeasure, tol);
    shell_n(n, coords[0].data(), coords[1].data(), coords[2].data(), t.data(), result.data());
    for (size_t i = 0; i < n; ++i)
      a.add(std::fabs(double(result[i]) - samples[i].shell) / samples[i].shell_scale, with(samples[i].p, samples[i].t));
    out.push_back(a.done());
  }
}

// A runner's lane (GLSL in float32, NumPy in float64, ...): one run per function over all points,
// whose coordinates are rounded to the lane's precision T.
template <typename T>
void compare_lane(const run::Lane& lane, const std::vector<Sample>& samples, int dims, double tol, double normal_tol,
                  std::vector<FunctionDeviation>& out) {
  const bool is_float = std::is_same<T, float>::value;
  const std::string label = lane.label + " ";
  const std::string& suffix = lane.suffix;
  const bool has_graded = lane.graded;
  auto inputs = [&](bool with_t) {
    std::vector<run::Sample> in;
    for (const Sample& s : samples) {
      run::Sample q{};
      for (int k = 0; k < dims; ++k)
        q[static_cast<size_t>(k)] = static_cast<double>(static_cast<T>(s.p[static_cast<size_t>(k)]));
      q[static_cast<size_t>(dims)] = static_cast<double>(static_cast<T>(with_t ? s.t : s.h));
      in.push_back(q);
    }
    return in;
  };
  const auto at_h = inputs(false), at_t = inputs(true);
  {
    Accumulator a(label + "field" + suffix, is_float, kFieldMeasure, tol);
    const auto v = lane.evaluate("field", at_h, 1);
    for (size_t i = 0; i < samples.size(); ++i)
      a.add(std::fabs(double(v[i]) - samples[i].field) / samples[i].grad_norm, samples[i].p);
    out.push_back(a.done());
  }
  {
    Accumulator a(label + "offset" + suffix, is_float, kOffsetMeasure, tol);
    const auto v = lane.evaluate("offset", at_h, 1);
    for (size_t i = 0; i < samples.size(); ++i)
      a.add(std::fabs(double(v[i]) - samples[i].phi) / samples[i].grad_norm, with(samples[i].p, samples[i].h));
    out.push_back(a.done());
  }
  {
    Accumulator a(label + "shell" + suffix, is_float, kShellMeasure, tol);
    const auto v = lane.evaluate("shell", at_t, 1);
    for (size_t i = 0; i < samples.size(); ++i)
      a.add(std::fabs(double(v[i]) - samples[i].shell) / samples[i].shell_scale, with(samples[i].p, samples[i].t));
    out.push_back(a.done());
  }
  {
    Accumulator a(label + "normal" + suffix, is_float, kNormalMeasure, normal_tol);
    const auto v = lane.evaluate("normal", at_h, dims);
    for (size_t i = 0; i < samples.size(); ++i) {
      if (!samples[i].normal) continue;
      double e2 = 0;
      for (int k = 0; k < dims; ++k)
        e2 += std::pow(double(v[i * static_cast<size_t>(dims) + static_cast<size_t>(k)]) -
                           (*samples[i].normal)[static_cast<size_t>(k)],
                       2);
      a.add(std::sqrt(e2), with(samples[i].p, samples[i].h));
    }
    out.push_back(a.done());
  }
  if (has_graded) {
    Accumulator a(label + "graded" + suffix, is_float, kGradedMeasure, tol);
    const auto v = lane.evaluate("graded", at_h, 1);
    for (size_t i = 0; i < samples.size(); ++i)
      if (samples[i].graded)
        a.add(std::fabs(double(v[i]) - *samples[i].graded) / *samples[i].graded_scale,
              with(samples[i].p, *samples[i].t_of_x));
    if (a.d.points > 0) out.push_back(a.done());
  }
}

}  // namespace

ValueReport check_values(const Implementations& impl, const Reference& reference, const run::FileMetadata& meta,
                         const std::optional<GiNaC::ex>& thickness, const ValueCheckOptions& options) {
  const int dims = meta.dims;
  const std::vector<Sample> samples = reference_samples(reference, meta, thickness, options);
  ValueReport report;
  report.tolerance = options.tolerance;
  report.digits = options.digits;
  if (impl.c) {
    const run::LoadedFunctions& f = *impl.c;
    compare_scalar<double>({f.field, f.offset, f.shell, f.normal, thickness ? f.graded : nullptr}, "", samples, dims,
                           options.tolerance, options.normal_tolerance, report.functions);
    compare_batch<double>(f.offset_n, f.shell_n, "", samples, dims, options.tolerance, report.functions);
    compare_scalar<float>({f.fieldf, f.offsetf, f.shellf, f.normalf, thickness ? f.gradedf : nullptr}, "f", samples,
                          dims, options.float_tolerance, options.float_normal_tolerance, report.functions);
    compare_batch<float>(f.offsetf_n, f.shellf_n, "f", samples, dims, options.float_tolerance, report.functions);
  }
  for (const run::Lane& lane : impl.lanes) {
    if (lane.is_float)
      compare_lane<float>(lane, samples, dims, options.float_tolerance, options.float_normal_tolerance,
                          report.functions);
    else
      compare_lane<double>(lane, samples, dims, options.tolerance, options.normal_tolerance, report.functions);
  }
  report.has_double = (impl.c && impl.c->offset != nullptr) ||
                      std::any_of(impl.lanes.begin(), impl.lanes.end(), [](const run::Lane& l) { return !l.is_float; });
  report.pass = !report.functions.empty();
  for (const auto& d : report.functions) {
    report.pass = report.pass && d.pass;
    const bool is_normal = d.function.find("normal") != std::string::npos;
    if (d.is_float) {
      if (!is_normal) report.max_shift_float = std::max(report.max_shift_float, d.max_shift);
    } else if (is_normal) {
      report.max_normal_double = std::max(report.max_normal_double, d.max_shift);
    } else {
      report.max_shift_double = std::max(report.max_shift_double, d.max_shift);
    }
  }
  return report;
}

ValueReport check_values(const run::LoadedFunctions& functions, const Reference& reference,
                         const run::FileMetadata& meta, const std::optional<GiNaC::ex>& thickness,
                         const ValueCheckOptions& options) {
  Implementations impl;
  impl.c = &functions;
  return check_values(impl, reference, meta, thickness, options);
}

}  // namespace offsetgen::check
