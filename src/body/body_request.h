// A body as a command asks for it (`--body part.stl --scale --skin --fillet --origin --repair`, for mesh
// and slice alike): the request, checked once; the file read, scaled and made sure closed (or repaired);
// and the checks that the body can hold a lattice.
#pragma once

#include "body/body_mesh.h"

#include <array>
#include <functional>
#include <optional>
#include <string>

namespace offsetgen::body {

struct BodyRequest {
  std::string path;                             // STL, PLY, OBJ or 3MF, in millimetres
  double scale = 1;                             // multiplies the body's coordinates
  double skin = 0;                              // mm; 0: the lattice cut flush by the body
  double fillet = 0;                            // mm: radius of the blend where walls meet the skin
  std::optional<std::array<double, 3>> origin;  // a lattice cell's corner, mm; default the body's box minimum
  bool repair = false;                          // repair an open or inconsistent body instead of refusing it
  // A box instead of a file: a mapped block (mesh's --map with --domain), as a body without a skin.
  std::optional<std::array<std::array<double, 3>, 2>> box;
};

// Throws InputError for a bad scale, skin, fillet or origin, or an output that is the body itself.
void validate_body(const BodyRequest& request, const std::string& output);

struct LoadedBody {
  BodyMesh mesh;                               // mm, after --scale; closed
  std::string repaired;                        // what --repair did; empty without it
  std::array<std::array<double, 3>, 2> box{};  // mm
  double volume = 0;                           // enclosed by the mesh, mm^3
};

using BodyWarning = std::function<void(const std::string& message)>;
// Reads the body (or makes the box), scales it and makes sure it is closed (or repairs it); warns of
// sizes that look like other units. Throws InputError for an unreadable or open body.
LoadedBody load_body(const BodyRequest& request, const BodyWarning& warn = {});
// Refuses bodies that cannot hold a lattice: smaller than a cell, or all skin.
void check_body_size(const std::array<std::array<double, 3>, 2>& box, double cell_size, double skin);
// The eight corners and twelve triangles of a box, facing out.
BodyMesh box_body(const std::array<std::array<double, 3>, 2>& box);

}  // namespace offsetgen::body
