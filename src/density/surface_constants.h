// The constants of a periodic surface that turn wall thickness into relative density and back
// (docs/density.md): per cell of length 1, the area A of F = 0, the integral of the Gaussian
// curvature (2 pi chi by Gauss-Bonnet), the integral of the mean curvature, the volume V_0 of F < 0,
// and the largest principal curvature, which limits where the tube formula holds.
#pragma once

#include "surfaces/surface.h"

#include <array>
#include <optional>
#include <string>

namespace offsetgen::density {

struct SurfaceConstants {
  double area = 0, area_error = 0;             // A
  double gauss_integral = 0, gauss_error = 0;  // integral of K dA, measured
  int euler_characteristic = 0;                // chi = round(integral K dA / 2 pi)
  double chi_residual = 0;                     // |integral K dA / 2 pi - chi|, the self-check
  double mean_integral = 0, mean_error = 0;    // integral of H dA, H = (k1 + k2) / 2, n = grad F / |grad F|
  double volume_inside = 0, volume_error = 0;  // V_0, the volume of F < 0 per cell
  double max_curvature = 0;                    // max |k1|, |k2| over F = 0 (cell units)
  std::array<double, 3> max_curvature_point{};
  long columns = 0, points = 0, grid = 0;  // work done by the quadrature (grid: columns per face side)

  // The largest total sheet thickness the tube formula holds for (no focal point): t/2 < 1/k_max.
  double thickness_limit() const { return 2 / max_curvature; }
  // The largest |h| for the network solid phi(p, h) < 0.
  double offset_limit() const { return 1 / max_curvature; }
};

// The self-check on chi: the measured integral of K dA must lie this close to 2 pi chi.
inline constexpr double kChiTolerance = 1e-6;

// Why `surface` has no density functions (not 3D, not periodic with period 1 in every coordinate),
// or nullopt when it has them.
std::optional<std::string> density_unavailable(const Surface& surface);

// The constants of `surface`, computed once per process and surface. Throws InputError when
// density_unavailable() says why, or when the Gauss-Bonnet self-check fails (a singular surface).
const SurfaceConstants& surface_constants(const Surface& surface);

// The same, always computed afresh (tests).
SurfaceConstants compute_surface_constants(const Surface& surface);

}  // namespace offsetgen::density
