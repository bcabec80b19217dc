#include "step/exact_walls.h"

#include "density/surface_constants.h"
#include "pipeline/generate.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace offsetgen::step {

LevelFunction offset_sheet(const wall::WallField& field, wall::WallField::Worker& worker, const CellFrame& frame,
                           double side, const std::array<int, 3>* block) {
  return
      [&field, &worker, frame, side, block](size_t n, const double* x, const double* y, const double* z, double* out) {
        std::vector<double> h(n);
        for (size_t i = 0; i < n; ++i) {
          Point p{x[i], y[i], z[i]};
          if (block != nullptr)
            for (size_t a = 0; a < 3; ++a) p[a] = std::clamp(p[a], 0.0, double((*block)[a]));
          p = frame.to_field(p);
          h[i] = side * 0.5 * field.thickness_at(p[0], p[1], p[2], worker);
        }
        if (!frame.distorted()) return field.offsets(n, x, y, z, h.data(), out);
        std::vector<double> fx(n), fy(n), fz(n);
        for (size_t i = 0; i < n; ++i) {
          fx[i] = x[i] * frame.field[0];
          fy[i] = y[i] * frame.field[1];
          fz[i] = z[i] * frame.field[2];
        }
        field.offsets(n, fx.data(), fy.data(), fz.data(), h.data(), out);
      };
}

bool inside_wall_at(const wall::WallField& field, wall::WallField::Worker& worker, const CellFrame& frame,
                    const Point& p) {
  return wall_at(field, worker, frame.to_field(p).data()) < 0;
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
  const CellFrame frame = cell_frame(r);
  s.graded = field.graded();
  s.thickness_in_mm = frame.distorted();
  s.thickness = field.thickness_at(0, 0, 0, worker);
  // Over the block in the field's units (a box cell's graded wall is an expression of x, y, z in mm).
  s.thickness_range =
      field.thickness_range({0, 0, 0}, frame.to_field({double(r.cells[0]), double(r.cells[1]), double(r.cells[2])}));
  s.thickness_text = s.graded ? r.wall.thickness : fmt::format("{}", s.thickness);
  try {
    // A box cell's field is the surface composed with its map: the limit is the cube cell's surface's.
    GenerationRequest cube = r.wall.generation;
    cube.map.clear();
    cube.domain.reset();
    s.thickness_limit =
        density::surface_constants(frame.distorted() ? resolve_surface(cube) : field.generation().surface)
            .thickness_limit();
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("offsetgen step needs the surface's curvature limit, from its constants: {}", e.what()));
  }
  if (frame.distorted()) {
    // Stretching by S = diag(X, Y, Z) scales a normal curvature by at most max(S) / min(S)^2.
    const double lo = std::min({frame.mm[0], frame.mm[1], frame.mm[2]});
    s.thickness_limit *= lo * lo / frame.largest_mm();
  }
  const char* unit = frame.distorted() ? "mm, bounded for the box cell" : "cell units";
  if (!(s.thickness_range[1] < s.thickness_limit))
    throw InputError(fmt::format(
        "--thickness {} is beyond the curvature limit of {}{}: t/2 must stay below the smallest radius of "
        "curvature, t < {:.6f} ({})",
        s.thickness_text, s.surface, s.graded ? fmt::format(" (it reaches {} in the block)", s.thickness_range[1]) : "",
        s.thickness_limit, unit));
}

}  // namespace offsetgen::step
