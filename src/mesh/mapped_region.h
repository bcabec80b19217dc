// A mapped lattice (--map) in `offsetgen mesh`: where its walls are built. The map's coordinates are
// physical, so the lattice's "cell" is 1 mm and its origin the body's; the generation is bounded over
// the body's box, and a singular set of the map (the cylinder's axis) is accepted when it stays
// outside the body: sample points closer to it than half its distance from the body's surface are
// then skipped, since no wall is kept there (docs/maps.md).
#pragma once

#include "body/body_mesh.h"
#include "pipeline/generate.h"

#include <array>
#include <string>

namespace offsetgen::mesh {

// Sets request.domain to the body's box (grown by `margin` mm) and request.singular_clearance from
// the body's surface. Throws InputError naming the point when the map's singular set meets the body
// or lies inside it. Returns a line for the summary ("the map's singular set stays 4.2 from the body").
std::string bound_map_to_body(GenerationRequest& request, const body::BodyMesh& body, double margin);

}  // namespace offsetgen::mesh
