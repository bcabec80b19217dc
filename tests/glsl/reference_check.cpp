#include "reference_check.h"

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "run/glsl_source.h"

namespace offsetgen::glsl_test {
namespace {

Vec3d position(const glsl::Sample& p, int dim) { return {p[0], p[1], dim == 3 ? static_cast<double>(p[2]) : 0.0}; }

// Reference value(s) of `q` at one input: 1 value, or 3 for the normal (empty when skipped).
std::vector<double> reference_values(const SurfaceReference& ref, Quantity q, const glsl::Sample& p,
                                     double min_gradient) {
  const Vec3d x = position(p, ref.dim);
  const double w = p[3];
  switch (q) {
    case Quantity::Field:
      return {ref.field(x)};
    case Quantity::Offset:
      return {ref.offset(x, w)};
    case Quantity::Shell:
      return {ref.offset(x, 0.5 * w) * ref.offset(x, -0.5 * w)};
    case Quantity::Normal: {
      const Vec3d g = ref.offset_gradient(x, w);
      const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      if (len < min_gradient) return {};
      return {g[0] / len, g[1] / len, g[2] / len};
    }
  }
  return {};
}

}  // namespace

std::vector<glsl::Sample> random_points(std::size_t n, int dim, double h_max, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_real_distribution<float> offset(static_cast<float>(-h_max), static_cast<float>(h_max));
  std::vector<glsl::Sample> pts(n);
  for (auto& p : pts) {
    p[0] = unit(rng);
    p[1] = unit(rng);
    p[2] = dim == 3 ? unit(rng) : 0.0f;
    p[3] = offset(rng);
  }
  return pts;
}

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::Field:
      return "field";
    case Quantity::Offset:
      return "offset";
    case Quantity::Shell:
      return "shell";
    case Quantity::Normal:
      return "normal";
  }
  return "?";
}

std::string call_expression(const SurfaceReference& ref, Quantity q) {
  const std::string p = ref.dim == 3 ? "p.xyz" : "p.xy";
  const std::string fn = ref.prefix + "_" + quantity_name(q);
  return q == Quantity::Field ? fn + "(" + p + ")" : fn + "(" + p + ", p.w)";
}

double ErrorReport::points_per_second() const {
  return stats.run_s > 0.0 ? static_cast<double>(stats.points) / stats.run_s : 0.0;
}

std::string ErrorReport::describe() const {
  std::ostringstream os;
  os.precision(3);
  os << what << ": max |error| " << std::scientific << max_abs_error << " over " << compared << " points (worst at x=("
     << worst_input[0] << ", " << worst_input[1] << ", " << worst_input[2] << "), w=" << worst_input[3] << ": got "
     << got << ", want " << reference << "); " << std::defaultfloat << points_per_second() / 1e6
     << " Mpoints/s, compile " << stats.compile_s << " s";
  return os.str();
}

ErrorReport check(const SurfaceReference& ref, Quantity q, glsl::Path path, const std::vector<glsl::Sample>& points,
                  double min_gradient) {
  if (q == Quantity::Normal && !ref.offset_gradient) {
    throw std::invalid_argument(ref.name + " has no reference gradient");
  }
  const int components = q == Quantity::Normal ? 3 : 1;
  ErrorReport r;
  r.what = ref.name + " " + quantity_name(q) + " on " + glsl::path_name(path);
  const std::string snippet = glsl::read_text_file(ref.snippet_path);
  const auto got = glsl::run(path, snippet, call_expression(ref, q), points, components, &r.stats);
  r.max_abs_error = -1.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto want = reference_values(ref, q, points[i], min_gradient);
    if (want.empty()) continue;
    ++r.compared;
    for (std::size_t c = 0; c < want.size(); ++c) {
      const double g = got[i * static_cast<std::size_t>(components) + c];
      const double e = std::isfinite(g) ? std::abs(g - want[c]) : HUGE_VAL;
      if (e > r.max_abs_error) {
        r.max_abs_error = e;
        r.worst = i;
        r.worst_input = points[i];
        r.reference = want[c];
        r.got = g;
      }
    }
  }
  if (r.compared == 0) r.max_abs_error = 0.0;
  return r;
}

}  // namespace offsetgen::glsl_test
