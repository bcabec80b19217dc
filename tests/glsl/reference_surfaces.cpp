#include "reference_surfaces.h"

#include <cmath>

namespace offsetgen::glsl_test {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

struct Trig {
  double sx, sy, sz, cx, cy, cz;
};

Trig trig(const Vec3d& x) {
  return {std::sin(kTwoPi * x[0]), std::sin(kTwoPi * x[1]), std::sin(kTwoPi * x[2]),
          std::cos(kTwoPi * x[0]), std::cos(kTwoPi * x[1]), std::cos(kTwoPi * x[2])};
}

}  // namespace

std::string fixture_dir() { return OFFSETGEN_GLSL_FIXTURE_DIR; }

double gyroid_field(const Vec3d& x) {
  const Trig t = trig(x);
  return t.sx * t.cy + t.sy * t.cz + t.sz * t.cx;
}

Vec3d gyroid_gradient(const Vec3d& x) {
  const Trig t = trig(x);
  return {kTwoPi * (t.cx * t.cy - t.sz * t.sx), kTwoPi * (t.cy * t.cz - t.sx * t.sy),
          kTwoPi * (t.cz * t.cx - t.sy * t.sz)};
}

double gyroid_offset_o1(const Vec3d& x, double h) {
  const Vec3d g = gyroid_gradient(x);
  return gyroid_field(x) - h * std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

Vec3d gyroid_offset_o1_gradient(const Vec3d& x, double h) {
  const Trig t = trig(x);
  const double k2 = kTwoPi * kTwoPi;
  const Vec3d g = gyroid_gradient(x);
  const double hxx = -k2 * (t.sx * t.cy + t.sz * t.cx);
  const double hyy = -k2 * (t.sy * t.cz + t.sx * t.cy);
  const double hzz = -k2 * (t.sz * t.cx + t.sy * t.cz);
  const double hxy = -k2 * t.cx * t.sy;
  const double hyz = -k2 * t.cy * t.sz;
  const double hxz = -k2 * t.sx * t.cz;
  const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  const double s = len > 0.0 ? h / len : 0.0;
  return {g[0] - s * (hxx * g[0] + hxy * g[1] + hxz * g[2]), g[1] - s * (hxy * g[0] + hyy * g[1] + hyz * g[2]),
          g[2] - s * (hxz * g[0] + hyz * g[1] + hzz * g[2])};
}

SurfaceReference gyroid_o1_reference(const std::string& snippet_path) {
  SurfaceReference r;
  r.name = "gyroid o1 (hand-derived reference)";
  r.snippet_path = snippet_path;
  r.prefix = "gyroid_o1";
  r.dim = 3;
  r.field = gyroid_field;
  r.offset = gyroid_offset_o1;
  r.offset_gradient = gyroid_offset_o1_gradient;
  return r;
}

}  // namespace offsetgen::glsl_test
