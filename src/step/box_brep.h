// The wall of a box partition (box_patch.h) as an OpenCASCADE solid: every curve and segment becomes
// one edge, shared by the two faces it bounds; every patch a bicubic B-spline face trimmed by its loop
// (its edges' parameter curves are their control points' plane coordinates: exact, as the patch's
// parameters are affine in them); every cap a planar face, merged with its neighbours on the same
// block face. The faces are split into closed shells, each one solid.
#pragma once

#include "step/box_patch.h"
#include "step/wall_brep.h"

namespace offsetgen::step {

// In mm: the partition (cell units) scaled along each axis by `mm`, the cell's sides. Throws
// std::runtime_error if a face cannot be built or no closed shell comes out.
WallBrep build_box_wall(const BoxPartition& partition, const Point& mm);

}  // namespace offsetgen::step
