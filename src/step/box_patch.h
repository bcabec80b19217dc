// Box patches: the route for a surface without mirror planes (the gyroid). The block is cut into cubes
// (boxes) of 1/k cell; where one offset sheet crosses a face of a box, the crossing is one curve,
// traced on the face and shared by the two boxes on either side of it. In each box, the curves of one
// sheet close into loops, and each loop bounds one piece of the sheet: a graph over the plane across
// the piece's mean normal, fitted as a bicubic patch and trimmed by the loop. On the block's faces,
// the parts of the boxes' faces inside the wall become planar caps, bounded by the same curves and by
// straight segments on the boxes' edges. Every edge of the solid is one of those curves or segments,
// used by exactly two faces, so the shell is closed by construction: no sewing, no booleans.
//
// Plain C++ (no OpenCASCADE): the B-rep is assembled in box_brep.cpp.
#pragma once

#include "step/bspline_fit.h"
#include "step/level_function.h"

#include <array>
#include <functional>
#include <vector>

namespace offsetgen::step {

// Where one sheet crosses one face of a box: its points lie on the sheet and in the face's plane,
// from vertex `from` to vertex `to` (both where the sheet crosses the box's edges), evenly spaced.
struct BoxCurve {
  int sheet = 0;
  int from = -1, to = -1;
  std::vector<Point> points;
};

// One edge of a face's boundary loop: a curve (traversed from its `from` to its `to` when forward), or
// with curve < 0 the straight segment from vertex `from` to vertex `to` along a box's edge (caps only).
struct LoopEdge {
  int curve = -1;
  bool forward = true;
  int from = -1, to = -1;  // in the loop's direction
};

// One piece of one sheet in one box: p(a, b) = origin + (u0 + a (u1 - u0)) e1 + (v0 + b (v1 - v0)) e2
// + height(a, b) normal, for (a, b) in [0, 1]^2, with `normal` (e1 x e2) pointing out of the wall.
// The patch's control points have exactly that affine (u, v), so a point's parameters are its plane
// coordinates, scaled. Its loop runs counterclockwise seen from outside the wall.
struct BoxPatch {
  int sheet = 0;
  std::vector<LoopEdge> loop;
  CubicPatch patch;
  Point origin{}, e1{}, e2{}, normal{};
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  double error = 0;  // cell units: the largest height difference between the exact sheet and the patch inside the loop
  std::array<double, 2> parameters(const Point& p) const;
};

// A planar piece of the block's face inside the wall, on the plane x[axis] = offset (cell units), its
// loop counterclockwise seen along `outward` (+1 or -1 along the axis).
struct BoxCap {
  int axis = 0;
  double offset = 0;
  int outward = 1;
  std::vector<LoopEdge> loop;
};

struct BoxPartition {
  int boxes_per_cell = 0;
  std::vector<Point> vertices;  // cell units
  std::vector<BoxCurve> curves;
  std::vector<BoxPatch> patches;
  std::vector<BoxCap> caps;
  int largest_side = 0;  // control points per side of the largest patch
  double fit_error = 0;  // cell units, over all patches
};

// The wall between the sheets g[0] = 0 (the offset at +t/2) and g[1] = 0 (at -t/2) in the block
// [0, cells], cut into boxes of 1/boxes_per_cell cell. Each patch gets the fewest control points per
// side (4, 5, 6, ..., at most max_side) that fit it within `target` (cell units). Throws InputError
// where a sheet is not what the boxes need (it touches a box's face, or a piece is not a graph).
// `more`: the same two sheets once more for each further thread the patches are fitted on (a
// LevelFunction is used by one thread at a time); the result does not depend on how many.
BoxPartition partition_wall(const std::array<LevelFunction, 2>& g, const std::function<bool(const Point&)>& inside_wall,
                            const std::array<int, 3>& cells, int boxes_per_cell, double target, int max_side,
                            const std::vector<std::array<LevelFunction, 2>>& more = {});

}  // namespace offsetgen::step
