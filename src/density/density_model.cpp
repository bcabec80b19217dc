#include "density/density_model.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace offsetgen::density {
namespace {

constexpr double kPi = 3.141592653589793;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The root of an increasing f in [lo, hi] with f(lo) <= 0 <= f(hi): Newton, falling back to
// bisection, to the last representable width.
double increasing_root(const std::function<double(double)>& f, const std::function<double(double)>& slope, double lo,
                       double hi, double guess) {
  double x = std::clamp(guess, lo, hi);
  for (int it = 0; it < 200; ++it) {
    const double v = f(x);
    if (v == 0) return x;
    (v < 0 ? lo : hi) = x;
    double next = x - v / slope(x);
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (next == x || hi - lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(x))) return next;
    x = next;
  }
  return x;
}

}  // namespace

DensityModel::DensityModel(const SurfaceConstants& constants) : constants_(constants) {
  sheet_limit_ = std::min(1.0, sheet_cubic_raw(thickness_limit()));
  network_min_ = std::max(0.0, network_cubic_raw(-offset_limit()));
  network_max_ = std::min(1.0, network_cubic_raw(offset_limit()));
}

double DensityModel::sheet_cubic() const { return kPi * chi() / 6; }

double DensityModel::sheet_cubic_raw(double t) const { return t * (area() + sheet_cubic() * t * t); }

double DensityModel::network_cubic_raw(double h) const {
  const double a = constants_.volume_inside, b = area(), c = constants_.mean_integral, d = 2 * kPi * chi() / 3;
  return a + h * (b + h * (c + h * d));
}

double DensityModel::sheet_density(double t) const {
  if (!(t >= 0 && t <= thickness_limit())) return kNaN;
  return sheet_cubic_raw(t);
}

double DensityModel::sheet_thickness(double rho) const {
  if (!(rho >= 0 && rho <= sheet_limit_)) return kNaN;
  const double c = sheet_cubic();
  return increasing_root([&](double t) { return sheet_cubic_raw(t) - rho; },
                         [&](double t) { return area() + 3 * c * t * t; }, 0, thickness_limit(), rho / area());
}

double DensityModel::network_density(double h) const {
  if (!(std::fabs(h) <= offset_limit())) return kNaN;
  return network_cubic_raw(h);
}

double DensityModel::network_offset(double rho) const {
  if (!(rho >= network_min_ && rho <= network_max_)) return kNaN;
  const double b = area(), c = constants_.mean_integral, d = 2 * kPi * chi() / 3;
  return increasing_root([&](double h) { return network_cubic_raw(h) - rho; },
                         [&](double h) { return b + h * (2 * c + 3 * d * h); }, -offset_limit(), offset_limit(),
                         (rho - constants_.volume_inside) / b);
}

namespace {

// value if lo <= x <= hi, else NaN (also for a NaN x: comparisons with NaN are false).
NodeId in_range(Program& p, NodeId x, double lo, double hi, NodeId value) {
  const NodeId nan = p.constant(kNaN);
  return p.select(p.less_eq(p.constant(lo), x), p.select(p.less_eq(x, p.constant(hi)), value, nan), nan);
}

// c0 + x (c1 + x (c2 + x c3))
NodeId cubic(Program& p, NodeId x, double c0, double c1, double c2, double c3) {
  NodeId acc = p.constant(c3);
  for (double c : {c2, c1, c0}) acc = p.add(p.constant(c), p.mul(x, acc));
  return acc;
}

}  // namespace

DensityPrograms density_programs(const DensityModel& m) {
  const double a = m.area(), c = m.sheet_cubic();
  const double v0 = m.constants().volume_inside, ih = m.constants().mean_integral, ik3 = 2 * kPi * m.chi() / 3;
  DensityPrograms out;
  {
    Program& p = out.density = Program({"t"});
    const NodeId t = p.input(0);
    p.add_output("rho", in_range(p, t, 0, m.thickness_limit(), cubic(p, t, 0, a, 0, c)));
  }
  {
    Program& p = out.thickness_for_density = Program({"rho"});
    const NodeId rho = p.input(0);
    NodeId t = p.mul(rho, p.constant(1 / a));
    for (int i = 0; i < kSheetNewtonSteps; ++i) {
      const NodeId t2 = p.mul(t, t);
      const NodeId residual = p.sub(p.mul(t, p.add(p.constant(a), p.mul(p.constant(c), t2))), rho);
      t = p.sub(t, p.div(residual, p.add(p.constant(a), p.mul(p.constant(3 * c), t2))));
    }
    p.add_output("t", in_range(p, rho, 0, m.sheet_density_limit(), t));
  }
  {
    Program& p = out.network_density = Program({"h"});
    const NodeId h = p.input(0);
    p.add_output("rho", in_range(p, h, -m.offset_limit(), m.offset_limit(), cubic(p, h, v0, a, ih, ik3)));
  }
  {
    Program& p = out.offset_for_density = Program({"rho"});
    const NodeId rho = p.input(0);
    NodeId h = p.mul(p.sub(rho, p.constant(v0)), p.constant(1 / a));
    for (int i = 0; i < kNetworkNewtonSteps; ++i) {
      const NodeId residual = p.sub(cubic(p, h, v0, a, ih, ik3), rho);
      h = p.sub(h, p.div(residual, cubic(p, h, a, 2 * ih, 3 * ik3, 0)));
    }
    p.add_output("h", in_range(p, rho, m.network_density_min(), m.network_density_max(), h));
  }
  return out;
}

GiNaC::ex thickness_for_density_expression(const DensityModel& m, const GiNaC::ex& rho) {
  const GiNaC::ex a = GiNaC::numeric(m.area()), c = GiNaC::numeric(m.sheet_cubic());
  GiNaC::ex t = rho / a;
  for (int i = 0; i < kSheetNewtonSteps; ++i)
    t = t - (a * t + c * GiNaC::pow(t, 3) - rho) / (a + 3 * c * GiNaC::pow(t, 2));
  return t;
}

nlohmann::ordered_json constants_json(const DensityModel& model, bool with_errors) {
  const SurfaceConstants& k = model.constants();
  nlohmann::ordered_json j;
  j["area"] = k.area;
  if (with_errors) j["area_error"] = k.area_error;
  j["chi"] = k.euler_characteristic;
  j["gauss_integral"] = k.gauss_integral;
  if (with_errors) j["chi_residual"] = k.chi_residual;
  j["volume_inside"] = k.volume_inside;
  if (with_errors) j["volume_error"] = k.volume_error;
  j["mean_integral"] = k.mean_integral;
  if (with_errors) j["mean_error"] = k.mean_error;
  j["max_curvature"] = k.max_curvature;
  j["thickness_limit"] = model.thickness_limit();
  j["density_limit"] = model.sheet_density_limit();
  j["offset_limit"] = model.offset_limit();
  j["network_density_range"] = {model.network_density_min(), model.network_density_max()};
  return j;
}

}  // namespace offsetgen::density
