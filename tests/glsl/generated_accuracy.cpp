#include "generated_accuracy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reference_check.h"

namespace offsetgen::glsl_test {
namespace {

constexpr double kBand = 0.05;  // "near the zero set": estimated distance <= 0.05 cell lengths

double err(double got, double want) { return std::isfinite(got) ? std::abs(got - want) : HUGE_VAL; }

}  // namespace

bool near_zero_set(const DoubleReference& ref, std::size_t i) {
  const double g = ref.field_grad[i];
  return g >= ref.gradient_floor && std::abs(ref.offset[i]) <= kBand * g;
}

DoubleReference make_reference(const GeneratedCase& c, std::size_t n, std::uint32_t seed) {
  DoubleReference r;
  r.points = random_points(n, 3, 0.05, seed);
  r.field.resize(n);
  r.offset.resize(n);
  r.shell.resize(n);
  r.phi_plus.resize(n);
  r.phi_minus.resize(n);
  r.normal.resize(3 * n);
  r.grad_len.resize(n);
  r.field_grad.resize(n);
  constexpr double e = 1e-6;
  double max_grad = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = r.points[i][0], y = r.points[i][1], z = r.points[i][2], h = r.points[i][3];
    const double t = 2.0 * std::abs(h);
    r.field[i] = c.field(x, y, z);
    r.offset[i] = c.offset(x, y, z, h);
    r.shell[i] = c.shell(x, y, z, t);
    r.phi_plus[i] = c.offset(x, y, z, 0.5 * t);
    r.phi_minus[i] = c.offset(x, y, z, -0.5 * t);
    c.normal(x, y, z, h, &r.normal[3 * i]);
    const double gx = (c.offset(x + e, y, z, h) - c.offset(x - e, y, z, h)) / (2 * e);
    const double gy = (c.offset(x, y + e, z, h) - c.offset(x, y - e, z, h)) / (2 * e);
    const double gz = (c.offset(x, y, z + e, h) - c.offset(x, y, z - e, h)) / (2 * e);
    r.grad_len[i] = std::sqrt(gx * gx + gy * gy + gz * gz);
    const double fx = (c.field(x + e, y, z) - c.field(x - e, y, z)) / (2 * e);
    const double fy = (c.field(x, y + e, z) - c.field(x, y - e, z)) / (2 * e);
    const double fz = (c.field(x, y, z + e) - c.field(x, y, z - e)) / (2 * e);
    r.field_grad[i] = std::sqrt(fx * fx + fy * fy + fz * fz);
    max_grad = std::max(max_grad, r.field_grad[i]);
  }
  r.gradient_floor = 0.1 * max_grad;
  return r;
}

Accuracy measure(const DoubleReference& ref, const FloatResults& got) {
  Accuracy a;
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    a.field = std::max(a.field, err(got.field[i], ref.field[i]));
    const double eo = err(got.offset[i], ref.offset[i]);
    a.offset_all = std::max(a.offset_all, eo);
    if (near_zero_set(ref, i)) {
      ++a.near_points;
      if (eo > a.offset) {
        a.offset = eo;
        a.worst_offset = i;
      }
      if (ref.grad_len[i] > 0.0) a.zero_set = std::max(a.zero_set, eo / ref.grad_len[i]);
      double d2 = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        const double d = err(got.normal[3 * i + k], ref.normal[3 * i + k]);
        d2 += d * d;
      }
      a.normal = std::max(a.normal, std::sqrt(d2));
    }
    const double g = ref.field_grad[i];
    const double face = std::min(std::abs(ref.phi_plus[i]), std::abs(ref.phi_minus[i]));
    if (g >= ref.gradient_floor && face <= kBand * g) {
      ++a.shell_points;
      const double scale = std::abs(ref.phi_plus[i]) + std::abs(ref.phi_minus[i]) + 1e-3;
      a.shell = std::max(a.shell, err(got.shell[i], ref.shell[i]) / scale);
    }
  }
  return a;
}

std::string describe(const Accuracy& a) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "field %.2e  offset %.2e (all %.2e)  zero set %.2e  shell %.2e  normal %.2e"
                "  [%zu/%zu pts near]",
                a.field, a.offset, a.offset_all, a.zero_set, a.shell, a.normal, a.near_points, a.shell_points);
  return buf;
}

}  // namespace offsetgen::glsl_test
