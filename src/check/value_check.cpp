#include "check/value_check.h"

#include "offset/offset_reference.h"

#include <algorithm>
#include <cmath>
#include <random>

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

ValueReport check_values(const LoadedFunctions& f, const Reference& reference, const FileMetadata& meta,
                         const std::optional<GiNaC::ex>& thickness, const ValueCheckOptions& options) {
  const Generation& g = reference.generation;
  OffsetReference hp(g.surface, *g.construction, options.digits);
  const int dims = meta.dims;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  std::uniform_real_distribution<double> distance(-options.h_max, options.h_max);

  Accumulator field{{"field", false, 0, 0, 0, {}, "|dF| / |grad F|"}};
  Accumulator offset{{"offset", false, 0, 0, 0, {}, "|dphi| / |grad F|"}};
  Accumulator shell{{"shell", false, 0, 0, 0, {}, "|dPhi| / (|grad F| (|phi+| + |phi-|))"}};
  Accumulator graded{{"graded", false, 0, 0, 0, {}, "|dPhi| / (|grad F| (|phi+| + |phi-|)), t = t(x)"}};
  Accumulator normal{{"normal", false, 0, 0, 0, {}, "|dn| (unit normal, vs 40-digit central differences)"}};
  Accumulator fieldf{{"fieldf", true, 0, 0, 0, {}, "|dF| / |grad F|"}};
  Accumulator offsetf{{"offsetf", true, 0, 0, 0, {}, "|dphi| / |grad F|"}};
  Accumulator shellf{{"shellf", true, 0, 0, 0, {}, "|dPhi| / (|grad F| (|phi+| + |phi-|))"}};
  Accumulator gradedf{{"gradedf", true, 0, 0, 0, {}, "|dPhi| / (|grad F| (|phi+| + |phi-|)), t = t(x)"}};
  Accumulator normalf{{"normalf", true, 0, 0, 0, {}, "|dn|"}};

  std::vector<double> p(static_cast<size_t>(dims));
  std::vector<float> pf(static_cast<size_t>(dims));
  std::vector<GiNaC::numeric> x(static_cast<size_t>(dims));

  const int points = options.points > 0 ? options.points : default_value_points(meta.order);
  const int stride = std::max(1, options.normal_stride);
  for (int i = 0; i < points; ++i) {
    if (options.progress) options.progress(i, points);
    for (int k = 0; k < dims; ++k) {
      // float and double functions see the same point: draw it representable in float
      p[static_cast<size_t>(k)] = static_cast<double>(static_cast<float>(coordinate(rng)));
      pf[static_cast<size_t>(k)] = static_cast<float>(p[static_cast<size_t>(k)]);
      x[static_cast<size_t>(k)] = exact(p[static_cast<size_t>(k)]);
    }
    const double h = static_cast<double>(static_cast<float>(distance(rng)));
    const double t = 2 * std::fabs(h);
    const GiNaC::numeric hn = exact(h), tn = exact(t);

    double grad_norm = 0;
    {
      DigitsScope digits(options.digits);
      GiNaC::numeric sum = 0;
      for (const auto& c : hp.field_gradient(x)) sum += c * c;
      grad_norm = std::sqrt(dbl(sum));
    }
    std::vector<double> where = p;
    const double F = dbl(hp.field(x));
    if (f.field) field.add(std::fabs(f.field(p.data()) - F) / grad_norm, where);
    if (f.fieldf) fieldf.add(std::fabs(double(f.fieldf(pf.data())) - F) / grad_norm, where);

    where.push_back(h);
    const GiNaC::numeric phi_n = hp.offset(x, hn);
    const double phi = dbl(phi_n);
    if (f.offset) offset.add(std::fabs(f.offset(p.data(), h) - phi) / grad_norm, where);
    if (f.offsetf) offsetf.add(std::fabs(double(f.offsetf(pf.data(), static_cast<float>(h))) - phi) / grad_norm, where);

    // the unit normal, from the method's own reference
    if ((f.normal || f.normalf) && i % stride == 0) {
      std::vector<double> n_ref;
      double len2 = 0;
      for (const auto& c : hp.normal(x, hn)) {
        n_ref.push_back(dbl(c));
        len2 += n_ref.back() * n_ref.back();
      }
      if (len2 > 0) {
        if (f.normal) {
          std::vector<double> n(static_cast<size_t>(dims));
          f.normal(p.data(), h, n.data());
          double e2 = 0;
          for (int k = 0; k < dims; ++k) e2 += std::pow(n[static_cast<size_t>(k)] - n_ref[static_cast<size_t>(k)], 2);
          normal.add(std::sqrt(e2), where);
        }
        if (f.normalf) {
          std::vector<float> n(static_cast<size_t>(dims));
          f.normalf(pf.data(), static_cast<float>(h), n.data());
          double e2 = 0;
          for (int k = 0; k < dims; ++k)
            e2 += std::pow(double(n[static_cast<size_t>(k)]) - n_ref[static_cast<size_t>(k)], 2);
          normalf.add(std::sqrt(e2), where);
        }
      }
    }

    where.back() = t;
    const GiNaC::numeric plus = hp.offset(x, tn / 2), minus = hp.offset(x, -tn / 2);
    const double Phi = dbl(plus * minus);
    const double scale = grad_norm * (std::fabs(dbl(plus)) + std::fabs(dbl(minus)));
    if (f.shell) shell.add(std::fabs(f.shell(p.data(), t) - Phi) / scale, where);
    if (f.shellf) shellf.add(std::fabs(double(f.shellf(pf.data(), static_cast<float>(t))) - Phi) / scale, where);

    if (thickness && (f.graded || f.gradedf)) {
      GiNaC::numeric tx;
      {
        DigitsScope digits(options.digits);
        GiNaC::exmap subs;
        for (int k = 0; k < dims; ++k) subs[Symbols::get().cell(k)] = x[static_cast<size_t>(k)];
        tx = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(thickness->subs(subs)));
      }
      // The scale of the shell's rounding: phi at +-t(p)/2 (the graded walls read t where the method does).
      const GiNaC::numeric gp = hp.offset(x, tx / 2), gm = hp.offset(x, -tx / 2);
      const double G = dbl(hp.graded(x, *thickness));
      const double gscale = grad_norm * (std::fabs(dbl(gp)) + std::fabs(dbl(gm)));
      where.back() = dbl(tx);
      if (f.graded) graded.add(std::fabs(f.graded(p.data()) - G) / gscale, where);
      if (f.gradedf) gradedf.add(std::fabs(double(f.gradedf(pf.data())) - G) / gscale, where);
    }
  }

  ValueReport report;
  report.tolerance = options.tolerance;
  report.digits = options.digits;
  for (Accumulator* a : {&field, &offset, &shell, &graded, &normal, &fieldf, &offsetf, &shellf, &gradedf, &normalf}) {
    if (a->d.points == 0) continue;
    FunctionDeviation d = a->done();
    if (d.function == "normal") {
      report.max_normal_double = d.max_shift;
    } else if (d.is_float) {
      if (d.function != "normalf") report.max_shift_float = std::max(report.max_shift_float, d.max_shift);
    } else {
      report.max_shift_double = std::max(report.max_shift_double, d.max_shift);
    }
    report.functions.push_back(d);
  }
  report.has_double = f.offset != nullptr;
  report.pass = report.max_shift_double <= options.tolerance;
  return report;
}

}  // namespace offsetgen::check
