// Double-precision references for the GLSL snippets the tests run. Today only the hand-written
// first-order gyroid fixture; real generated snippets get one entry each (snippet + reference).
#pragma once

#include <string>
#include <vector>

#include "reference_check.h"

namespace offsetgen::glsl_test {

// Directory of tests/glsl/fixtures (set by CMake).
std::string fixture_dir();

// Gyroid, cell length 1: F = sin(kx)cos(ky) + sin(ky)cos(kz) + sin(kz)cos(kx), k = 2 pi.
double gyroid_field(const Vec3d& x);
Vec3d gyroid_gradient(const Vec3d& x);
// First order (paper eq. 3): phi_1 = F - h |grad F|, and its exact gradient
// grad F - h H grad F / |grad F|.
double gyroid_offset_o1(const Vec3d& x, double h);
Vec3d gyroid_offset_o1_gradient(const Vec3d& x, double h);

// tests/glsl/fixtures/gyroid_o1.glsl, prefix gyroid_o1.
SurfaceReference gyroid_o1_fixture();

// Every snippet the executor tests cover.
std::vector<SurfaceReference> all_references();

}  // namespace offsetgen::glsl_test
