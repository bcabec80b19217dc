// Where the drain holes go (issue 43, --drain D): every enclosed void region of 1 mm^3 or more gets
// two, one at its lowest voxel along --up (to drain) and one at its highest (to let air in), or, where
// those lie within two diameters of each other, at the voxel of its extremes furthest from the lowest.
// Each hole runs from that voxel straight to the nearest point of the body's surface and on past it,
// so it crosses the skin where the skin is thinnest. --drain-at places holes by hand instead.
#pragma once

#include "body/body_mesh.h"
#include "mesh/body_domain.h"
#include "mesh/void_regions.h"
#include "wall/drain_holes.h"

#include <array>
#include <string>
#include <vector>

namespace offsetgen::mesh {

struct DrainRequest {
  double diameter = 0;                    // --drain D, mm; 0: no holes
  std::vector<std::array<double, 3>> at;  // --drain-at X,Y,Z ...: holes by hand (mm), instead of placed
  int up = 2;                             // --up X|Y|Z: the axis the build goes up along
  double fill_below = 0;                  // --fill-pockets V: enclosed regions under V mm^3 made solid
  bool any() const { return diameter > 0 || fill_below > 0; }
};

struct PlannedHole {
  std::array<double, 3> at{};         // mm: where it starts, inside the void
  std::array<double, 3> direction{};  // unit: out through the skin
  double length = 0;                  // mm: from `at` to past the body's surface
  double diameter = 0;                // mm
  std::string role;                   // "drain", "air" or "by hand"
};

// The holes for the regions of `voids` of kDrainRegionMm3 or more and not filled (under
// request.fill_below), or at request.at; positions in mm through `frame`.
std::vector<PlannedHole> plan_drain_holes(const VoidReport& voids, const body::BodyMesh& body, const VoxelFrame& frame,
                                          const DrainRequest& request);
// The holes as the sampler cuts them: voxel index coordinates of `frame`.
std::vector<wall::DrainHole> holes_in_voxels(const std::vector<PlannedHole>& holes, const VoxelFrame& frame);

// Throws InputError for a diameter under two voxels or of half the body's smallest extent or more.
void check_drain_diameter(const DrainRequest& request, double voxel, const std::array<std::array<double, 3>, 2>& box);
// Parses "X", "Y" or "Z" (--up).
int parse_up_axis(const std::string& text);

}  // namespace offsetgen::mesh
