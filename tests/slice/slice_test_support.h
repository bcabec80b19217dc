// What the slice tests share: a gyroid block's wall, compiled once per process, and its level
// G = max(w, box) with a distance estimate |G| / |grad G| (mm) at points of the part.
#pragma once

#include "wall/wall_field.h"

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace offsetgen::slice::test {

inline wall::WallRequest gyroid_request(const std::string& density = "0.2") {
  wall::WallRequest r;
  r.generation.surface = "gyroid";
  r.generation.density = std::stod(density);
  return r;
}

inline const wall::WallField& gyroid_field() {
  static std::unique_ptr<wall::WallField> field = [] {
    auto f = std::make_unique<wall::WallField>(gyroid_request());
    f->compile();
    return f;
  }();
  return *field;
}

// The distance estimate |w| / |grad w| (in the layer) from points (mm) to the wall's zero set, in mm.
inline std::vector<double> wall_distances(const wall::WallField& field, const std::vector<std::array<double, 2>>& mm,
                                          double z_mm, double cell) {
  const double h = 1e-6;  // cell units
  std::vector<double> x, y, z;
  for (const auto& p : mm) {
    const double px = p[0] / cell, py = p[1] / cell, pz = z_mm / cell;
    const double offsets[5][2] = {{0, 0}, {h, 0}, {-h, 0}, {0, h}, {0, -h}};
    for (const auto& o : offsets) {
      x.push_back(px + o[0]);
      y.push_back(py + o[1]);
      z.push_back(pz);
    }
  }
  std::vector<double> w(x.size());
  wall::WallField::Worker worker(field);
  if (!x.empty()) field.walls(x.size(), x.data(), y.data(), z.data(), w.data(), worker);
  std::vector<double> d(mm.size());
  for (size_t k = 0; k < mm.size(); ++k) {
    const double* v = &w[5 * k];
    // The distance to the zero set within the layer: |w| over the in-layer gradient.
    const double gx = (v[1] - v[2]) / (2 * h), gy = (v[3] - v[4]) / (2 * h);
    d[k] = std::abs(v[0]) / std::hypot(gx, gy) * cell;
  }
  return d;
}

// G = max(w, box) at points (mm) of a layer of a block of `cells` x `cells` cells.
inline std::vector<double> level(const wall::WallField& field, const std::vector<std::array<double, 2>>& mm,
                                 double z_mm, double cell, const std::array<int, 2>& cells) {
  std::vector<double> x, y, z, w(mm.size());
  for (const auto& p : mm) {
    x.push_back(p[0] / cell);
    y.push_back(p[1] / cell);
    z.push_back(z_mm / cell);
  }
  wall::WallField::Worker worker(field);
  if (!x.empty()) field.walls(x.size(), x.data(), y.data(), z.data(), w.data(), worker);
  for (size_t k = 0; k < mm.size(); ++k) {
    const double box = std::max(std::max(-x[k], x[k] - cells[0]), std::max(-y[k], y[k] - cells[1]));
    w[k] = std::max(w[k], box);
  }
  return w;
}

}  // namespace offsetgen::slice::test
