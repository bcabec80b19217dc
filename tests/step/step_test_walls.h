// The walls the STEP tests fit and measure: a catalog surface's generated functions, compiled in this
// process, and one offset sheet of them as a LevelFunction.
#pragma once

#include "step/level_function.h"
#include "wall/wall_field.h"

#include <memory>
#include <string>
#include <vector>

namespace offsetgen::step {

inline std::unique_ptr<wall::WallField> compiled_walls(const std::string& surface, const std::string& thickness) {
  wall::WallRequest request;
  request.generation.surface = surface;
  request.thickness = thickness;
  auto field = std::make_unique<wall::WallField>(request);
  field->compile();
  return field;
}

// The offset sheet phi(p, h) = 0 at a fixed h (cell units).
inline LevelFunction uniform_sheet(const wall::WallField& field, double h) {
  return [&field, h](size_t n, const double* x, const double* y, const double* z, double* out) {
    const std::vector<double> hs(n, h);
    field.offsets(n, x, y, z, hs.data(), out);
  };
}

}  // namespace offsetgen::step
