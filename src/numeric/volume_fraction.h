// The volume fraction of a region {g < 0} in a box, measured by column integration: the volume is
// the integral over the box's base of the length of {g < 0} along each column, and each length is
// exact up to root finding (every sign change along the column, refined by Brent's method).
//
// Columns grazing a thin wall see a long segment (t / |n_z|): the column length is spiky, and a
// grid of columns along one axis converges slowly. So the volume is split over the three axes by a
// smooth partition of unity, w_i = n_i^2 with n = grad F / |grad F| on the surface, blended to 1/3
// away from it (any partition keeps the sum exact): columns along axis i integrate w_i over their
// segments of {g < 0} (composite Gauss-Legendre), and w_i vanishes where such a column grazes.
// Squares, not higher powers: where the normal turns fast (Neovius' sheets pass 0.04 cell from
// saddles of F) n_i^8 weights vary so sharply that the columns' grid converges slowly; measured in
// docs/density.md.
//
// The base integrals are a randomly shifted lattice rule: R independent random shifts of an n x n
// grid of columns per axis, each an unbiased estimate; their mean is the result and their standard
// error (standard deviation / sqrt(R)) the stated error, so the quadrature error is measured, not
// assumed.
//
// Cost control: outside the band |F| <= band around the surface, g has a known sign (a documented
// property of the emitted functions: |phi(p, h) - F(p)| <= M |h| in natural units), so only columns
// segments that may reach the band are scanned finely.
#pragma once

#include <array>
#include <functional>

namespace offsetgen::numeric {

struct VolumeFractionSetup {
  std::function<double(const double*)> g;      // the region is g < 0
  std::function<double(const double*)> field;  // F
  double field_slope_bound = 0;                // >= |dF/dz| (cell units): k M
  double band = 0;                             // |F| > band: g has the sign `outside` says
  bool outside_follows_field = false;          // outside the band: sign(g) = sign(F) (network); else g > 0 (sheet)
  double scan_step = 0;                        // fine scan inside the band; must be below the thinnest feature along z
  // Measure only along z, the plain column length (no partition): for comparison and tests.
  bool single_axis = false;
  // Whether the region repeats with the box's size (a whole periodic cell of a periodic solid). A
  // shifted grid of columns converges fast on periodic integrands; on others (one cell of a graded
  // block) its error is O(1/n) per shift, so the columns are placed through the baker's (tent)
  // transform u -> 1 - |2u - 1|, which keeps each shift unbiased and cancels that first-order term.
  bool periodic = true;
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 3> size{1, 1, 1};
};

struct VolumeFractionOptions {
  int grid = 40;   // columns per side of the base, per shift
  int shifts = 6;  // independent random shifts
  unsigned seed = 20240613;
};

struct VolumeFraction {
  double value = 0;           // mean over the shifts
  double standard_error = 0;  // of the mean
  long columns = 0;
  long evaluations = 0;    // of g
  long weight_points = 0;  // Gauss points of the partition weights
};

VolumeFraction measure_volume_fraction(const VolumeFractionSetup& setup, const VolumeFractionOptions& options);

}  // namespace offsetgen::numeric
