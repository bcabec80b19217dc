// Compares what a GLSL snippet computes on llvmpipe with a double-precision C++ reference.
// A check is a (snippet file, reference functions) pair, so covering every catalog surface is a
// loop over SurfaceReference values; see reference_surfaces.h for the ones that exist.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "run/glsl_executor.h"

namespace offsetgen::glsl_test {

using Vec3d = std::array<double, 3>;  // 2D surfaces use x[0], x[1] and ignore x[2]

struct SurfaceReference {
  std::string name;                                        // for messages, e.g. "gyroid order 1 (fixture)"
  std::string snippet_path;                                // the .glsl file
  std::string prefix;                                      // its function prefix, e.g. "gyroid_o4"
  int dim = 3;                                             // 3: functions take vec3 p; 2: vec2 p
  std::function<double(const Vec3d& x)> field;             // F(x)
  std::function<double(const Vec3d& x, double h)> offset;  // phi(x, h), what <prefix>_offset returns
  // grad_x phi(x, h), unnormalised; empty when the reference has none (normal check skipped).
  std::function<Vec3d(const Vec3d& x, double h)> offset_gradient;
};

// Uniform points: x in [0,1]^dim (other coordinates 0), w = h uniform in [-h_max, h_max].
std::vector<glsl::Sample> random_points(std::size_t n, int dim, double h_max, std::uint32_t seed);

// Which snippet function a check exercises.
enum class Quantity { Field, Offset, Shell, Normal };
const char* quantity_name(Quantity q);

// GLSL call expression for `q` on input `p`, e.g. "gyroid_o4_offset(p.xyz, p.w)"; the shell is
// called with thickness t = p.w.
std::string call_expression(const SurfaceReference& ref, Quantity q);

struct ErrorReport {
  std::string what;            // "<surface> <quantity> on <path>"
  double max_abs_error = 0.0;  // max over points (and components) of |glsl - reference|
  std::size_t worst = 0;       // index of the worst point
  glsl::Sample worst_input{};
  double reference = 0.0;  // at the worst point (worst component)
  double got = 0.0;
  std::size_t compared = 0;  // points compared (the normal skips near-zero gradients)
  glsl::RunStats stats;
  [[nodiscard]] double points_per_second() const;
  [[nodiscard]] std::string describe() const;
};

// Runs `q` of `ref`'s snippet on `path` over `points` and compares it with the reference evaluated
// in double at the same (float-rounded) inputs. For Normal, points where |grad phi| < min_gradient
// are skipped: the direction is ill-conditioned there.
ErrorReport check(const SurfaceReference& ref, Quantity q, glsl::Path path, const std::vector<glsl::Sample>& points,
                  double min_gradient = 0.5);

}  // namespace offsetgen::glsl_test
