// An independent estimate of a trimmed part's volume, to catch the booleans when they go wrong without
// a trace: OpenCASCADE can return valid, closed solids that are not lattice ∩ body (a ball just inside
// one cell, touching the block's faces, came back as 167% of the ball). The skin's volume is exact
// (the body's less the core's, both B-rep volumes); the lattice inside the core is sampled: points on
// a jittered grid over the core's box, counted where the core holds them and the exact wall does.
#pragma once

#include "step/body_solid.h"
#include "support/point.h"

#include <functional>

namespace offsetgen::step {

struct SampledPart {
  double volume = 0;  // mm^3: skin (exact) + lattice ∩ core (sampled)
  double error = 0;   // mm^3: the sampling's standard error (as if independent: the grid's is smaller)
  long points = 0;
};

// `in_wall`: whether a point (mm, where the part lies) is inside the exact wall. `per_side`^3 points.
SampledPart sample_part_volume(const CadBody& body, double body_volume, double core_volume,
                               const std::function<bool(const Point&)>& in_wall, int per_side);

// Whether the part's volume is the sampled one: within 5 standard errors, and 0.2% of the body for
// the B-rep's own deviation from the exact wall.
bool part_volume_agrees(double part_volume, const SampledPart& sampled, double body_volume);

}  // namespace offsetgen::step
