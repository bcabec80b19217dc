#include "step/cell_frame.h"

#include "validate/block_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace offsetgen::step {

double CellFrame::largest_mm() const { return std::max({mm[0], mm[1], mm[2]}); }

double CellFrame::cell_volume() const {
  return distorted() ? mm[0] * mm[1] * mm[2] : std::pow(mm[0], 3);  // a cube cell's as it always was
}

Point CellFrame::to_field(const Point& p) const { return {p[0] * field[0], p[1] * field[1], p[2] * field[2]}; }

CellFrame cell_frame(const StepRequest& r) {
  CellFrame f;
  f.mm = r.cell_size;
  if (!cube_cell(r.cell_size)) f.field = r.cell_size;
  return f;
}

wall::WallRequest framed_wall(const StepRequest& r) {
  wall::WallRequest w = r.wall;
  if (cube_cell(r.cell_size)) return w;
  const Point& s = r.cell_size;
  w.generation.map = fmt::format("x/{}; y/{}; z/{}", s[0], s[1], s[2]);
  Surface::Box block;
  for (size_t a = 0; a < 3; ++a) block.hi[a] = r.cells[a] * s[a];
  w.generation.domain = block;
  return w;
}

std::string cell_size_words(const std::array<double, 3>& s) {
  return cube_cell(s) ? fmt::format("{}", s[0]) : fmt::format("{} x {} x {}", s[0], s[1], s[2]);
}

}  // namespace offsetgen::step
