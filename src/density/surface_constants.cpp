#include "density/surface_constants.h"

#include "density/field_sampler.h"
#include "density/periodicity.h"
#include "density/surface_quadrature.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace offsetgen::density {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// Absolute error tolerance of A, integral(H dA) and V_0 (integral(K dA) is judged by Gauss-Bonnet).
constexpr double kTolerance = 1e-7;

// A smooth bump rho(u) = C (1 - u^2)^8 on |u| < 1 around `centre` with half width `half`, and its
// primitive from 0, on the periodic unit interval. Used to write V_0 as a surface integral.
class Bump {
 public:
  Bump(double centre, double half) : centre_(centre), half_(half) {
    for (int j = 0; j <= kPower; ++j) {
      coefficients_[static_cast<size_t>(j)] = binomial(j) * (j % 2 ? -1 : 1) / (2 * j + 1);
      full_ += 2 * coefficients_[static_cast<size_t>(j)];
    }
    below_zero_ = images_below(0);
  }
  double density(double x) const {
    const double u = (x - centre_ - std::round(x - centre_)) / half_;
    if (std::fabs(u) >= 1) return 0;
    double b = 1 - u * u, p = 1;
    for (int i = 0; i < kPower; ++i) p *= b;
    return p / (half_ * full_);
  }
  // The mass in [0, x) for x in [0, 1], counting the periodic images; 1 at x = 1.
  double mass_below(double x) const { return images_below(x) - below_zero_; }

 private:
  static constexpr int kPower = 8;
  static double binomial(int j) {
    double r = 1;
    for (int i = 1; i <= j; ++i) r = r * (kPower - j + i) / i;
    return r;
  }
  // Primitive of the normalised bump from -1 to u: (u * sum_j c_j u^2j + full / 2) / full.
  double primitive(double u) const {
    if (u <= -1) return 0;
    if (u >= 1) return 1;
    const double u2 = u * u;
    double s = 0;
    for (int j = kPower; j >= 0; --j) s = s * u2 + coefficients_[static_cast<size_t>(j)];
    return (u * s + full_ / 2) / full_;
  }
  double images_below(double x) const {
    double total = 0;
    for (int m = -2; m <= 2; ++m) total += primitive((x - centre_ - m) / half_);
    return total;
  }
  double centre_, half_, full_ = 0, below_zero_ = 0;
  std::array<double, kPower + 1> coefficients_{};
};

// A box [c - r, c + r]^3 that lies in one phase of F, proven by branch and bound with the Taylor
// bound |F(s + d)| >= |F(s)| - |grad F(s)| rho - H rho^2 / 2 (rho the sub-box's half-diagonal).
struct PhaseBox {
  std::array<double, 3> centre{};
  double half = 0;
  int sign = 1;  // of F inside
};

bool box_in_one_phase(FieldSampler& field, const std::array<double, 3>& c, double half, int sign) {
  struct Pending {
    std::array<double, 3> c;
    double half;
  };
  std::vector<Pending> stack = {{c, half}};
  const double curvature = 1.5 * field.hessian_bound();
  int budget = 6000;
  while (!stack.empty()) {
    if (--budget < 0) return false;
    const Pending b = stack.back();
    stack.pop_back();
    const FieldJet j = field.jet(b.c);
    const double f = sign * j.value;
    if (!(f > 0)) return false;
    const double g =
        std::sqrt(j.gradient[0] * j.gradient[0] + j.gradient[1] * j.gradient[1] + j.gradient[2] * j.gradient[2]);
    const double rho = b.half * std::sqrt(3.0);
    if (f - g * rho - curvature * rho * rho / 2 > 0) continue;
    if (b.half < half / 64) return false;
    for (int corner = 0; corner < 8; ++corner) {
      Pending child{b.c, b.half / 2};
      for (size_t i = 0; i < 3; ++i) child.c[i] += ((corner >> i) & 1 ? 1 : -1) * b.half / 2;
      stack.push_back(child);
    }
  }
  return true;
}

PhaseBox find_phase_box(FieldSampler& field) {
  // Candidates: grid points far from the surface by the gradient bound, best first.
  constexpr int n = 16;
  std::vector<std::pair<double, std::array<double, 3>>> candidates;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const std::array<double, 3> p = {(i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n};
        candidates.push_back({std::fabs(field.value(p)), p});
      }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  PhaseBox best;
  for (size_t c = 0; c < std::min<size_t>(4, candidates.size()); ++c) {
    const auto& p = candidates[c].second;
    const int sign = field.value(p) < 0 ? -1 : 1;
    for (double half = 0.3; half > std::max(best.half, 0.004); half *= 0.85) {
      if (box_in_one_phase(field, p, half, sign)) {
        best = {p, half, sign};
        break;
      }
    }
  }
  if (best.half == 0)
    throw InputError(
        "cannot compute V_0: no box of the cell provably lies in one phase of F (both phases are thinner "
        "than 0.008 cell everywhere)");
  return best;
}

struct Curvatures {
  double mean = 0;      // H = (k1 + k2) / 2
  double gaussian = 0;  // K = k1 k2
  double largest = 0;   // max |k1|, |k2|
};

// Curvatures of the level set through a point, from the jet (Goldman 2005).
Curvatures curvatures(const FieldJet& j) {
  const auto& g = j.gradient;
  const auto& h = j.hessian;
  const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const double gn = std::sqrt(g2);
  double ghg = 0;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = 0; b < 3; ++b) ghg += g[a] * h[a][b] * g[b];
  const double trace = h[0][0] + h[1][1] + h[2][2];
  const double adj[3][3] = {{h[1][1] * h[2][2] - h[1][2] * h[2][1], h[0][2] * h[2][1] - h[0][1] * h[2][2],
                             h[0][1] * h[1][2] - h[0][2] * h[1][1]},
                            {h[1][2] * h[2][0] - h[1][0] * h[2][2], h[0][0] * h[2][2] - h[0][2] * h[2][0],
                             h[0][2] * h[1][0] - h[0][0] * h[1][2]},
                            {h[1][0] * h[2][1] - h[1][1] * h[2][0], h[0][1] * h[2][0] - h[0][0] * h[2][1],
                             h[0][0] * h[1][1] - h[0][1] * h[1][0]}};
  double gag = 0;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = 0; b < 3; ++b) gag += g[a] * adj[a][b] * g[b];
  Curvatures c;
  c.mean = (g2 * trace - ghg) / (2 * g2 * gn);
  c.gaussian = gag / (g2 * g2);
  c.largest = std::fabs(c.mean) + std::sqrt(std::max(0.0, c.mean * c.mean - c.gaussian));
  return c;
}

// p moved onto F = 0 along the gradient (Newton), or nullopt when it does not converge.
std::optional<std::array<double, 3>> onto_surface(FieldSampler& field, std::array<double, 3> p) {
  for (int it = 0; it < 20; ++it) {
    const FieldJet j = field.jet(p);
    const double g2 = j.gradient[0] * j.gradient[0] + j.gradient[1] * j.gradient[1] + j.gradient[2] * j.gradient[2];
    if (!(g2 > 0)) return std::nullopt;
    const double step = j.value / g2;
    for (size_t i = 0; i < 3; ++i) p[i] -= step * j.gradient[i];
    if (std::fabs(step) * std::sqrt(g2) < 1e-12) return p;  // |F| near rounding: p is on the surface
  }
  return std::nullopt;
}

// The largest principal curvature: the quadrature's best samples, refined by a compass search on
// the surface.
std::pair<double, std::array<double, 3>> refine_largest_curvature(
    FieldSampler& field, const std::vector<std::pair<double, std::array<double, 3>>>& samples) {
  double best = 0;
  std::array<double, 3> best_point{};
  for (const auto& [value, start] : samples) {
    double k = value;
    std::array<double, 3> p = start;
    int budget = 2000;  // projections per start; a smooth maximum needs a few hundred
    for (double step = 1.0 / 256; step > 1e-6 && budget > 0;) {
      // Four directions in the tangent plane at p, both ways.
      const FieldJet j = field.jet(p);
      const auto& g = j.gradient;
      const size_t least = std::fabs(g[0]) <= std::fabs(g[1]) && std::fabs(g[0]) <= std::fabs(g[2])
                               ? 0
                               : (std::fabs(g[1]) <= std::fabs(g[2]) ? 1 : 2);
      std::array<double, 3> e{};
      e[least] = 1;
      std::array<double, 3> t1 = {g[1] * e[2] - g[2] * e[1], g[2] * e[0] - g[0] * e[2], g[0] * e[1] - g[1] * e[0]};
      std::array<double, 3> t2 = {g[1] * t1[2] - g[2] * t1[1], g[2] * t1[0] - g[0] * t1[2],
                                  g[0] * t1[1] - g[1] * t1[0]};
      const double n1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
      const double n2 = std::sqrt(t2[0] * t2[0] + t2[1] * t2[1] + t2[2] * t2[2]);
      if (!(n1 > 0) || !(n2 > 0)) break;
      bool improved = false;
      for (int d = 0; d < 8 && !improved; ++d) {
        const double angle = d * M_PI / 4;
        std::array<double, 3> trial = p;
        for (size_t i = 0; i < 3; ++i) trial[i] += step * (std::cos(angle) * t1[i] / n1 + std::sin(angle) * t2[i] / n2);
        --budget;
        const auto on = onto_surface(field, trial);
        if (!on) continue;
        const double kt = curvatures(field.jet(*on)).largest;
        if (kt > k * (1 + 1e-13)) {  // above rounding noise
          k = kt;
          p = *on;
          improved = true;
        }
      }
      if (!improved) step /= 2;
    }
    if (k > best) {
      best = k;
      best_point = p;
    }
  }
  for (double& c : best_point) c -= std::floor(c);
  return {best, best_point};
}

std::string surface_key(const Surface& s) {
  std::ostringstream key;
  key << s.field << " | " << s.scale;
  return key.str();
}

}  // namespace

std::optional<std::string> density_unavailable(const Surface& surface) {
  if (surface.mapped())
    return std::string(
        "a mapped lattice (--map) is not periodic: its cells are stretched differently from place to "
        "place, so no closed-form density relation holds; give the wall with --thickness");
  if (surface.dims != 3) return "density functions need a 3D surface (a volume fraction of the cell); this one is 2D";
  const Symbols& sym = Symbols::get();
  const GiNaC::ex cell = surface.field.subs(
      GiNaC::lst{sym.X == surface.scale * sym.x, sym.Y == surface.scale * sym.y, sym.Z == surface.scale * sym.z});
  for (int i = 0; i < 3; ++i) {
    if (auto problem = periodicity_problem(cell, sym.cell(i)))
      return fmt::format(
          "density functions need a surface periodic with period 1 (one cell) in x, y and z, and F is not "
          "provably periodic in {}: {}",
          sym.cell(i).get_name(), *problem);
  }
  return std::nullopt;
}

SurfaceConstants compute_surface_constants(const Surface& surface) {
  if (auto why = density_unavailable(surface)) throw InputError(*why);
  FieldSampler field(surface);
  const PhaseBox box = find_phase_box(field);
  const std::array<Bump, 3> bumps = {Bump(box.centre[0], box.half), Bump(box.centre[1], box.half),
                                     Bump(box.centre[2], box.half)};

  // The samples with the largest curvature, for the refinement.
  std::vector<std::pair<double, std::array<double, 3>>> sharpest;
  auto keep_sharpest = [&sharpest](double k, const std::array<double, 3>& p) {
    constexpr size_t kKeep = 8;
    if (sharpest.size() == kKeep && k <= sharpest.back().first) return;
    for (const auto& s : sharpest) {
      double d2 = 0;
      for (size_t i = 0; i < 3; ++i) {
        const double d = s.second[i] - p[i] - std::round(s.second[i] - p[i]);
        d2 += d * d;
      }
      if (d2 < 1e-4) return;  // one start per neighbourhood
    }
    sharpest.push_back({k, p});
    std::sort(sharpest.begin(), sharpest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    if (sharpest.size() > kKeep) sharpest.pop_back();
  };

  // V_0 = integral over F < 0 of div v + integral over F < 0 of the bump, with the periodic field
  // v = (x - R1(x), r1(x) (y - R2(y)), r1(x) r2(y) (z - R3(z))), div v = 1 - r1 r2 r3 (r_i the bumps,
  // R_i their primitives). The bump's box lies in one phase, so its integral is 0 or 1, and the
  // first term is the flux of v through F = 0: a smooth surface integral like the others.
  SurfaceIntegrand integrand = [&](const SurfacePoint& s, std::vector<double>& out) {
    const Curvatures c = curvatures(s.jet);
    keep_sharpest(c.largest, s.p);
    const double x = s.p[0], y = s.p[1], z = s.p[2];
    const double v[3] = {x - bumps[0].mass_below(x), bumps[0].density(x) * (y - bumps[1].mass_below(y)),
                         bumps[0].density(x) * bumps[1].density(y) * (z - bumps[2].mass_below(z))};
    out[0] = 1;
    out[1] = c.gaussian;
    out[2] = c.mean;
    out[3] = v[0] * s.normal[0] + v[1] * s.normal[1] + v[2] * s.normal[2];
  };
  QuadratureOptions options;
  // integral(K dA) is judged by Gauss-Bonnet itself: the grid is fine enough when it lies within a
  // tenth of the self-check's tolerance of 2 pi times an integer.
  options.tolerance = {kTolerance, INFINITY, kTolerance, kTolerance};
  options.accept = [](const std::vector<double>& value) {
    const double chi = value[1] / kTwoPi;
    return std::fabs(chi - std::round(chi)) <= kChiTolerance / 10;
  };
  const QuadratureResult q = integrate_over_surface(field, integrand, options);

  SurfaceConstants k;
  k.area = q.value[0];
  k.area_error = q.error[0];
  k.gauss_integral = q.value[1];
  k.gauss_error = q.error[1];
  const double chi = q.value[1] / kTwoPi;
  k.euler_characteristic = static_cast<int>(std::lround(chi));
  k.chi_residual = std::fabs(chi - k.euler_characteristic);
  k.mean_integral = q.value[2];
  k.mean_error = q.error[2];
  k.volume_inside = q.value[3] + (box.sign < 0 ? 1 : 0);
  k.volume_error = q.error[3];
  k.columns = q.columns;
  k.grid = q.grid;
  k.points = q.points;
  const auto [largest, where] = refine_largest_curvature(field, sharpest);
  k.max_curvature = largest;
  k.max_curvature_point = where;
  if (!(k.area > 0)) throw InputError("the surface F = 0 does not meet the cell: there is no wall to give a density");
  if (!(k.chi_residual <= kChiTolerance))
    throw InputError(fmt::format(
        "the Gauss-Bonnet self-check failed: integral(K dA) / 2 pi = {:.9f} is not within {:g} of an integer "
        "(quadrature error estimate {:.1e}). Is F = 0 singular somewhere (grad F = 0 on the surface)?",
        chi, kChiTolerance, q.error[1] / kTwoPi));
  return k;
}

const SurfaceConstants& surface_constants(const Surface& surface) {
  static std::mutex mutex;
  static std::map<std::string, SurfaceConstants> cache;
  const std::string key = surface_key(surface);
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, compute_surface_constants(surface)).first;
  return it->second;
}

}  // namespace offsetgen::density
