// The route: which patches cut the wall's two sheets into faces (a surface's symmetry patches, or box
// patches), their fit within the tolerance, and the B-rep built from them.
#pragma once

#include "step/bspline_fit.h"
#include "step/step_request.h"
#include "step/step_summary.h"
#include "step/symmetry_patch.h"
#include "step/wall_brep.h"
#include "wall/wall_field.h"

#include <functional>

namespace offsetgen::step {

// The symmetry layout the request's patches take, or nullptr for box patches: a surface with mirror
// planes gets its symmetry patches (diamond only when asked for them), the others (the gyroid) box
// patches. InputError for --patches symmetry on a surface without a layout.
const PatchLayout* choose_layout(const StepRequest& request);

// Whether a point (cell units) lies inside the exact wall.
using InsideWall = std::function<bool(const Point&)>;

// The wall fitted by `layout`'s symmetry patches (or box patches where it is nullptr) within half the
// request's tolerance, and built into a solid cut to the block; records the route, the patches' size,
// the fit's error and the stages' seconds in the summary (its thickness recorded already).
WallBrep fit_and_build_wall(const PatchLayout* layout, const wall::WallField& field, wall::WallField::Worker& worker,
                            const StepRequest& request, const InsideWall& inside_wall, StepSummary& summary);

}  // namespace offsetgen::step
