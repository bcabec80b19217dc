// The exact walls as the exporter fits and measures them: each offset sheet as a level function, the
// wall's level at a point, and the wall's thickness against what the exporter covers.
#pragma once

#include "step/bspline_fit.h"
#include "step/cell_frame.h"
#include "step/level_function.h"
#include "step/step_request.h"
#include "step/step_summary.h"
#include "wall/wall_field.h"

#include <array>

namespace offsetgen::step {

// One offset sheet, phi(p, side t(p) / 2) = 0 with side +1 or -1; t uniform or graded; p in cell
// units, handed to the field in its own (frame.to_field). With `block`, a graded t is taken at the
// nearest point of the block [0, cells]: diamond's patches reach beyond it (the box cuts them
// afterwards), where the expression may not be positive or may be nothing the user asked for; inside
// the block the sheet is unchanged. The function holds field, worker and block by reference.
LevelFunction offset_sheet(const wall::WallField& field, wall::WallField::Worker& worker, const CellFrame& frame,
                           double side, const std::array<int, 3>* block = nullptr);

// The exact wall's level at one point p[0..2] (the field's units): negative inside (wall::WallField::walls).
double wall_at(const wall::WallField& field, wall::WallField::Worker& worker, const double* p);

// Whether a point (cell units) lies inside the exact wall.
bool inside_wall_at(const wall::WallField& field, wall::WallField::Worker& worker, const CellFrame& frame,
                    const Point& p);

// Records the wall's thickness in the summary (surface already set), in the field's units (cell units,
// or mm for a box cell): InputError where the exporter does not cover the wall (a --density-field
// grading, a thickness at or beyond the surface's curvature limit anywhere in the block; for a box
// cell, the cube cell's limit scaled by the bound min(X, Y, Z)^2 / max(X, Y, Z) of the stretched
// surface's smallest radius of curvature).
void record_thickness(const wall::WallField& field, wall::WallField::Worker& worker, const StepRequest& request,
                      StepSummary& summary);

}  // namespace offsetgen::step
