// A mapped file (--map) takes physical x, y, z in its domain box, while check's measurements run in
// the unit cell [0, 1]^d. The view below maps them isotropically onto a cube centred in the domain,
// 4/5 of its smallest side (walls and rays stay inside, where the bounds hold): distances scale by one factor (the
// side), so relative thickness errors, the Lipschitz bands and zero-set shifts keep their meaning. For an unmapped file
// it is the identity.
#pragma once

#include "check/thickness.h"
#include "run/metadata.h"

#include <array>

namespace offsetgen::check {

struct DomainCube {
  std::array<double, 3> origin{};
  double side = 1;
  bool identity = true;
  double at(int axis, double unit) const { return identity ? unit : origin[static_cast<size_t>(axis)] + side * unit; }
};

DomainCube domain_cube(const run::FileMetadata& meta);

// The probe seen through the cube: p in [0, 1]^d is origin + side p, and a distance h is side h.
Probe in_cube(const Probe& probe, const DomainCube& cube, int dims);

}  // namespace offsetgen::check
