#include "numeric/volume_fraction.h"

#include "numeric/root_finding.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace offsetgen::numeric {
namespace {

// The partition weights: w_i = g_i^2 / |g|^2 (n_i^2 on the surface), blended to 1/3 farther than
// about kUniformBeyond (in units of F) from it.
constexpr double kUniformBeyond = 0.2;
// Coarse steps per unit length along a column for the band search.
constexpr int kCoarsePerUnit = 128;
// Composite Gauss-Legendre on the segments: pieces of at most this length, 8 points each.
constexpr double kPiece = 1.0 / 16;
constexpr std::array<double, 8> kNodes = {0.019855071751231856, 0.10166676129318664, 0.2372337950418355,
                                          0.40828267875217511,  0.59171732124782489, 0.7627662049581645,
                                          0.89833323870681336,  0.98014492824876814};
constexpr std::array<double, 8> kWeights = {0.050614268145188129, 0.11119051722668724, 0.15685332293894364,
                                            0.18134189168918099,  0.18134189168918099, 0.15685332293894364,
                                            0.11119051722668724,  0.050614268145188129};

struct Segment {
  double a, b;
};

class Column {
 public:
  // The column through `point` along `axis` (point[axis] is ignored), within the box.
  Column(const VolumeFractionSetup& setup, int axis, const std::array<double, 3>& point)
      : s_(setup), axis_(axis), p_(point) {}

  // The segments of {g < 0} on the column within the box, in order.
  std::vector<Segment> negative_segments() {
    const size_t ax = static_cast<size_t>(axis_);
    const double z0 = s_.origin[ax], length = s_.size[ax];
    const int coarse = std::max(1, static_cast<int>(std::ceil(length * kCoarsePerUnit)));
    const double w = length / coarse;
    double fa = field(z0);
    for (int i = 0; i < coarse; ++i) {
      const double a = z0 + i * w, b = i + 1 == coarse ? z0 + length : a + w;
      const double fb = field(b);
      // |F| >= (|F(a)| + |F(b)| - L w) / 2 on [a, b] (Lipschitz): is the band out of reach?
      if ((std::fabs(fa) + std::fabs(fb) - s_.field_slope_bound * w) / 2 > s_.band) {
        if (s_.outside_follows_field && fa < 0) add(a, b);
      } else {
        fine(a, b);
      }
      fa = fb;
    }
    return segments_;
  }

  // The integral of the axis's partition weight over the segments.
  double weighted_length(const std::vector<Segment>& segments) {
    double total = 0;
    for (const Segment& seg : segments) {
      const int pieces = std::max(1, static_cast<int>(std::ceil((seg.b - seg.a) / kPiece)));
      const double h = (seg.b - seg.a) / pieces;
      for (int k = 0; k < pieces; ++k)
        for (size_t q = 0; q < kNodes.size(); ++q) total += kWeights[q] * h * weight(seg.a + (k + kNodes[q]) * h);
    }
    return total;
  }

  long evaluations = 0, weight_points = 0;

 private:
  std::array<double, 3> at(double z) const {
    std::array<double, 3> p = p_;
    p[static_cast<size_t>(axis_)] = z;
    return p;
  }
  double field(double z) { return s_.field(at(z).data()); }
  double g(double z) {
    ++evaluations;
    return s_.g(at(z).data());
  }

  // w_axis at a point of the column: (g_axis^2 + e) / (|g|^2 + 3 e), g = grad F by central
  // differences, e = (F / kUniformBeyond)^2. On F = 0 that is n_axis^2; farther than about
  // kUniformBeyond from the surface, and around the critical points of F, it goes smoothly to 1/3.
  double weight(double z) {
    ++weight_points;
    const std::array<double, 3> p = at(z);
    constexpr double d = 1e-6;
    std::array<double, 3> power{};
    double sum = 0;
    for (size_t i = 0; i < 3; ++i) {
      std::array<double, 3> plus = p, minus = p;
      plus[i] += d;
      minus[i] -= d;
      const double g = (s_.field(plus.data()) - s_.field(minus.data())) / (2 * d);
      power[i] = g * g;
      sum += power[i];
    }
    const double f = s_.field(p.data()) / kUniformBeyond, e = f * f;
    return sum + 3 * e > 0 ? (power[static_cast<size_t>(axis_)] + e) / (sum + 3 * e) : 1.0 / 3;
  }

  void add(double a, double b) {
    if (!segments_.empty() && segments_.back().b == a) {
      segments_.back().b = b;
    } else {
      segments_.push_back({a, b});
    }
  }

  // The segments of {g < 0} in [a, b]: a scan at the fine step, Brent in every sign change.
  void fine(double a, double b) {
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / s_.scan_step)));
    const double step = (b - a) / n;
    double za = a, ga = g(a);
    for (int i = 1; i <= n; ++i) {
      const double zb = i == n ? b : a + i * step;
      const double gb = g(zb);
      if ((ga < 0) == (gb < 0)) {
        if (ga < 0) add(za, zb);
      } else {
        const double r = brent_root([this](double z) { return g(z); }, za, zb, ga, gb);
        if (ga < 0) {
          add(za, r);
        } else {
          add(r, zb);
        }
      }
      za = zb;
      ga = gb;
    }
  }

  const VolumeFractionSetup& s_;
  int axis_;
  std::array<double, 3> p_;
  std::vector<Segment> segments_;
};

}  // namespace

VolumeFraction measure_volume_fraction(const VolumeFractionSetup& setup, const VolumeFractionOptions& options) {
  std::mt19937_64 random(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  VolumeFraction out;
  std::vector<double> estimates;
  const int n = options.grid;
  const double volume = setup.size[0] * setup.size[1] * setup.size[2];
  auto place = [&setup](double u) { return setup.periodic ? u : 1 - std::fabs(2 * u - 1); };
  for (int r = 0; r < options.shifts; ++r) {
    double total = 0;
    for (int axis = setup.single_axis ? 2 : 0; axis < 3; ++axis) {
      const size_t a1 = static_cast<size_t>((axis + 1) % 3), a2 = static_cast<size_t>((axis + 2) % 3);
      const double su = unit(random), sv = unit(random);
      double sum = 0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<double, 3> p{};
          p[a1] = setup.origin[a1] + setup.size[a1] * place((i + su) / n);
          p[a2] = setup.origin[a2] + setup.size[a2] * place((j + sv) / n);
          Column column(setup, axis, p);
          const std::vector<Segment> segments = column.negative_segments();
          if (setup.single_axis) {
            for (const Segment& seg : segments) sum += seg.b - seg.a;
          } else {
            sum += column.weighted_length(segments);
          }
          out.evaluations += column.evaluations;
          out.weight_points += column.weight_points;
          ++out.columns;
        }
      total += sum * setup.size[a1] * setup.size[a2] / (double(n) * n);
    }
    estimates.push_back(total / volume);
  }
  double mean = 0;
  for (double e : estimates) mean += e;
  mean /= double(estimates.size());
  double variance = 0;
  for (double e : estimates) variance += (e - mean) * (e - mean);
  variance /= std::max<double>(1, double(estimates.size()) - 1);
  out.value = mean;
  out.standard_error = std::sqrt(variance / double(estimates.size()));
  return out;
}

}  // namespace offsetgen::numeric
