#include "step/exact_walls.h"

#include "density/surface_constants.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace offsetgen::step {

LevelFunction offset_sheet(const wall::WallField& field, wall::WallField::Worker& worker, double side,
                           const std::array<int, 3>* block) {
  return [&field, &worker, side, block](size_t n, const double* x, const double* y, const double* z, double* out) {
    std::vector<double> h(n);
    for (size_t i = 0; i < n; ++i) {
      Point p{x[i], y[i], z[i]};
      if (block != nullptr)
        for (size_t a = 0; a < 3; ++a) p[a] = std::clamp(p[a], 0.0, double((*block)[a]));
      h[i] = side * 0.5 * field.thickness_at(p[0], p[1], p[2], worker);
    }
    field.offsets(n, x, y, z, h.data(), out);
  };
}

double wall_at(const wall::WallField& field, wall::WallField::Worker& worker, const double* p) {
  double w = 0;
  field.walls(1, p, p + 1, p + 2, &w, worker);
  return w;
}

void record_thickness(const wall::WallField& field, wall::WallField::Worker& worker, const StepRequest& r,
                      StepSummary& s) {
  if (field.graded() && r.wall.thickness.empty())
    throw InputError(
        "STEP export takes a graded wall as --thickness EXPR (an expression of x, y, z); --density-field is refused");
  s.graded = field.graded();
  s.thickness = field.thickness_at(0, 0, 0, worker);
  s.thickness_range = field.thickness_range(r.cells);
  s.thickness_text = s.graded ? r.wall.thickness : fmt::format("{}", s.thickness);
  try {
    s.thickness_limit = density::surface_constants(field.generation().surface).thickness_limit();
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("offsetgen step needs the surface's curvature limit, from its constants: {}", e.what()));
  }
  if (!(s.thickness_range[1] < s.thickness_limit))
    throw InputError(fmt::format(
        "--thickness {} is beyond the curvature limit of {}{}: t/2 must stay below the smallest radius of "
        "curvature, t < {:.6f} (cell units)",
        s.thickness_text, s.surface, s.graded ? fmt::format(" (it reaches {} in the block)", s.thickness_range[1]) : "",
        s.thickness_limit));
}

}  // namespace offsetgen::step
