// Hand-derived double-precision references for GLSL snippets: the first-order gyroid, written out
// from the paper's formula independently of the generator, to check the generated gyroid_o1
// snippet against (test_generated_execute.cpp), and the fixture snippet's directory.
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

// The reference for a snippet whose functions are prefixed gyroid_o1 (order 1: phi = F - h |grad F|;
// the safeguard's M clamp never binds at order 1, so the generated offset is exactly this).
SurfaceReference gyroid_o1_reference(const std::string& snippet_path);

}  // namespace offsetgen::glsl_test
