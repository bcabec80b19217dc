// The symmetry patch of a Schwarz P offset surface: the part in the region x >= y >= z of the octant
// [0, 1/2]^3 of the cell (cell units), a four-sided patch bounded by the mirror planes x = y (u = 0),
// x = 1/2 (u = 1), z = 0 (v = 0) and y = z (v = 1). The cubic group of the cell (48 elements, the
// mirror images and rotations) maps it onto the whole sheet in the cell.
//
// Its points come from root finding along the lines where the plane through the axis x = y = 1/2 at
// "angle" u meets the plane through the x axis at slope v = z / y:
//   p(s) = (1/2 - s (1 - u), 1/2 - s, v (1/2 - s)),  s in [0, 1/2].
// The boundary lines lie in their mirror planes exactly (x = y bitwise at u = 0, x = 1/2 at u = 1,
// z = 0 at v = 0, z = y at v = 1), so the fitted boundary curves do too.
#pragma once

#include "step/bspline_fit.h"
#include "step/level_function.h"

#include <vector>

namespace offsetgen::step {

// The m x m points of the patch at u = i/(m-1), v = j/(m-1) (points[i * m + j]). Throws InputError
// where a line does not cross the surface exactly once (the offset surface is not the Schwarz P
// sheet's graph over this patch: a thickness beyond what the patch layout holds).
std::vector<Point> schwarzp_patch_points(const LevelFunction& g, int m);

// The same for arbitrary (u, v) pairs (for measuring a fit between the samples).
std::vector<Point> schwarzp_patch_points(const LevelFunction& g, const std::vector<std::array<double, 2>>& uv);

// Snaps the boundary control points of a fitted patch onto their mirror planes exactly (x = 1/2 at
// u = 1; x = y, z = 0 and y = z already hold bitwise, this asserts them).
void snap_schwarzp_boundary(CubicPatch& patch);

// The largest angle (radians) between the patch's normals on either side of its edges: the patch's
// mirror image across each boundary plane meets it there, and their normals differ by twice the
// angle between the normal and the plane (the exact surface meets its mirror planes at a right
// angle: 0). Sampled at `samples` points per edge, derivatives by central differences.
double schwarzp_normal_jump(const CubicPatch& patch, int samples);

}  // namespace offsetgen::step
