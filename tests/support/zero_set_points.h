// Points near the zero set of a generated surface, for comparing a target (CUDA, OpenCL, ...) with
// the C header: Newton steps along grad F take random points of the unit cell onto F = 0 (C header's
// double _field), then each moves by a random h in [-0.1, 0.1] along the unit normal, so it lies near
// the zero set of _offset(., h). Header-only, plain C++ (nvcc compiles it as host code too).
#pragma once

#include <cmath>
#include <random>
#include <vector>

namespace offsetgen::test {

struct ZeroSetPoint {
  double p[3];  // the moved point
  double h;     // the offset that moves the zero set onto it (about)
};

using Field3 = double (*)(double, double, double);

// grad F by central differences (step 1e-6: about 1e-10 relative, plenty for a scale).
inline void field_gradient(Field3 field, const double p[3], double g[3]) {
  const double step = 1e-6;
  for (int k = 0; k < 3; ++k) {
    double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
    a[k] += step;
    b[k] -= step;
    g[k] = (field(a[0], a[1], a[2]) - field(b[0], b[1], b[2])) / (2 * step);
  }
}

inline double length(const double g[3]) { return std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]); }

// `count` points, the same for the same field and seed. A finite `fixed_h` moves every point by that h.
inline std::vector<ZeroSetPoint> near_zero_set_points(Field3 field, int count, double fixed_h = NAN,
                                                      unsigned seed = 20261123u) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), distance(-0.1, 0.1);
  std::vector<ZeroSetPoint> points;
  while (static_cast<int>(points.size()) < count) {
    double p[3] = {unit(rng), unit(rng), unit(rng)}, g[3];
    for (int step = 0; step < 12; ++step) {
      field_gradient(field, p, g);
      const double f = field(p[0], p[1], p[2]), g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
      if (g2 < 1e-6) break;
      for (int k = 0; k < 3; ++k) p[k] -= f * g[k] / g2;
    }
    field_gradient(field, p, g);
    if (!(std::fabs(field(p[0], p[1], p[2])) < 1e-9) || length(g) < 1e-3) continue;  // a critical point
    ZeroSetPoint z;
    z.h = distance(rng);
    if (std::isfinite(fixed_h)) z.h = fixed_h;
    for (int k = 0; k < 3; ++k) z.p[k] = p[k] + z.h * g[k] / length(g);
    points.push_back(z);
  }
  return points;
}

// The float limit of the zero-set shift for the GPU targets (issue 15), for every case. Neovius at
// Richardson order 4 meets it only because CUDA and OpenCL C take the trig of 2 pi x in half-turns
// (sinpi(2 x)): the C header's float twins, which round 2 pi x, reach 5.2e-5 on the same points
// (docs/neovius_o4_float.md).
inline constexpr double kFloatShiftLimit = 2e-5;

// The C header's double functions of one prefix: the reference.
struct CFunctions {
  double (*field)(double, double, double);
  double (*offset)(double, double, double, double);
  double (*shell)(double, double, double, double);
  void (*normal)(double, double, double, double, double*);
};

// How far a target's values move the zero set from the C header's, the measure of offsetgen check:
// the value difference over |grad F| for _field and _offset(p, h), over |grad F| (|phi(p, t/2)| +
// |phi(p, -t/2)|) for _shell(p, t), and the largest component difference of the unit normals.
struct ZeroSetShifts {
  double field = 0, offset = 0, shell = 0, normal = 0;

  // The largest zero-set shift (the normal is a direction: it has its own limit).
  double largest_shift() const { return std::fmax(field, std::fmax(offset, shell)); }

  // A target's values at q (its arguments, as the target saw them) with h, t = 2|h|; NaN counts as inf.
  void add(const CFunctions& ref, const double q[3], double h, double f, double phi, double shell_value,
           const double n[3]) {
    const double x = q[0], y = q[1], z = q[2], t = 2 * std::fabs(h);
    double g[3];
    field_gradient(ref.field, q, g);
    const double scale = length(g);
    worst(field, (f - ref.field(x, y, z)) / scale);
    worst(offset, (phi - ref.offset(x, y, z, h)) / scale);
    const double shell_scale = scale * (std::fabs(ref.offset(x, y, z, t / 2)) + std::fabs(ref.offset(x, y, z, -t / 2)));
    if (shell_scale > 0) worst(shell, (shell_value - ref.shell(x, y, z, t)) / shell_scale);
    double n_ref[3];
    ref.normal(x, y, z, h, n_ref);
    for (int k = 0; k < 3; ++k) worst(normal, n[k] - n_ref[k]);
  }

 private:
  static void worst(double& so_far, double difference) {
    so_far = std::isnan(difference) ? INFINITY : std::fmax(so_far, std::fabs(difference));
  }
};

}  // namespace offsetgen::test
