// Relative density from exact wall thickness (docs/density.md). Per cell of length 1:
//
//   sheet (total thickness t centred on F = 0):   rho(t) = A t + (pi chi / 6) t^3
//   network (the region phi(p, h) < 0):           rho(h) = V_0 + A h + h^2 integral(H dA) + (2 pi chi / 3) h^3
//
// exact while t / 2 (|h|) stays below the smallest radius of curvature of F = 0. The inverses are
// Newton iterations from the linear term; out of range (beyond the curvature limit, or negative
// thickness or density) every function returns NaN.
#pragma once

#include "density/surface_constants.h"
#include "lowering/program.h"

#include <ginac/ginac.h>
#include <nlohmann/json_fwd.hpp>

namespace offsetgen::density {

class DensityModel {
 public:
  explicit DensityModel(const SurfaceConstants& constants);

  const SurfaceConstants& constants() const { return constants_; }
  double area() const { return constants_.area; }
  int chi() const { return constants_.euler_characteristic; }
  // The cubic coefficient of the sheet, pi chi / 6 (Gauss-Bonnet, exact in chi).
  double sheet_cubic() const;

  // Sheet: valid for t in [0, t_max], rho in [0, rho_max].
  double thickness_limit() const { return constants_.thickness_limit(); }
  double sheet_density_limit() const { return sheet_limit_; }
  double sheet_density(double t) const;
  double sheet_thickness(double rho) const;

  // Network phi(p, h) < 0: valid for |h| <= h_max, rho in [network_density_min(), network_density_max()].
  double offset_limit() const { return constants_.offset_limit(); }
  double network_density_min() const { return network_min_; }
  double network_density_max() const { return network_max_; }
  double network_density(double h) const;
  double network_offset(double rho) const;

 private:
  double sheet_cubic_raw(double t) const;
  double network_cubic_raw(double h) const;

  SurfaceConstants constants_;
  double sheet_limit_ = 0, network_min_ = 0, network_max_ = 0;
};

// The surface's constants and the model's limits as JSON, in the order `offsetgen density --json` and a
// generated file's metadata ("density") print them: area, chi, the Gauss integral, V_0, integral H dA,
// k_max, t_max, rho_max, h_max and the network's density range. `with_errors` adds each quadrature's
// error after its value (and chi's residual), as `density --json` does.
nlohmann::ordered_json constants_json(const DensityModel& model, bool with_errors);

// Newton steps the emitted inverses take; enough for double precision over the whole valid range
// (tests/density measure it on every catalog surface).
inline constexpr int kSheetNewtonSteps = 5;
inline constexpr int kNetworkNewtonSteps = 7;

// The four relations as one-input programs, NaN out of range (inputs: t, rho, h, rho).
struct DensityPrograms {
  Program density;                // rho(t), sheet
  Program thickness_for_density;  // t(rho), sheet
  Program network_density;        // rho(h), network
  Program offset_for_density;     // h(rho), network
};
DensityPrograms density_programs(const DensityModel& model);

// t(rho(x, y, z)) as an expression of the cell coordinates, for a graded wall from a density field:
// the emitted Newton iteration, without the range check (the field is checked at generation time).
GiNaC::ex thickness_for_density_expression(const DensityModel& model, const GiNaC::ex& rho);

}  // namespace offsetgen::density
