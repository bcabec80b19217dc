// What `offsetgen step` is asked for, and the one place it is validated: the CLI hands its options
// over as given (docs/step.md).
#pragma once

#include "body/body_request.h"
#include "wall/wall_field.h"

#include <array>
#include <optional>
#include <string>

namespace offsetgen::step {

// How the sheets are cut into faces (docs/step.md, "How it works").
enum class Patches {
  Auto,      // symmetry patches where the surface has a layout that auto takes, else box patches
  Symmetry,  // mirror-plane patches, copied: faces that share their edges exactly
  Box,       // each sheet's pieces in a grid of boxes, fitted one by one: any periodic surface
};

// "auto", "symmetry" or "box" (--patches); InputError for any other name.
Patches patches_from_name(const std::string& name);

struct StepRequest {
  wall::WallRequest wall;
  std::array<int, 3> cells{1, 1, 1};
  // mm along x, y and z: a cube cell (all equal; the wall in cell units), or a box cell ("distorted
  // cells"; the wall in mm along the physical normal, step/cell_frame.h).
  std::array<double, 3> cell_size{10, 10, 10};
  double tolerance = 0;         // mm: the largest distance allowed from the exact walls to the faces
  std::string output;           // .step / .stp
  int max_control_points = 40;  // per patch side; beyond it the tolerance is reported as out of reach
  Patches patches = Patches::Auto;
  // --body: the lattice trimmed by a CAD body, with a skin (body_solid.h); the block then covers it.
  std::optional<body::BodyRequest> body;
};

// InputError for a request the exporter cannot take, found before any work: the wall not given as
// one of --thickness and --density, too few control points, a tolerance or cell size that is not a
// positive length, --density with a box cell, an output that is not a writable .step or .stp file.
void validate_request(const StepRequest& request);

}  // namespace offsetgen::step
