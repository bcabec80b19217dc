// The measurement of a solid, by export (the solid it writes, as it is in memory) and by check (the
// file read back) alike: valid closed solids, as many as the wall has pieces in the block; the exact
// walls' deviation from its faces; its volume against the exact wall volume.
#pragma once

#include "step/step_request.h"
#include "step/step_summary.h"
#include "wall/wall_field.h"

#include <TopoDS_Shape.hxx>

#include <future>

namespace offsetgen::step {

// The exact wall volume, mm^3, by column quadrature (numeric/volume_fraction.h), and its standard error.
struct ExactVolume {
  double volume = 0, error = 0, seconds = 0;
};
// It needs only the wall's functions, with a Worker of its own, so it runs on a thread of its own
// while OpenCASCADE writes and checks the solid (or, in check, reads it) on one core. `field` and
// `request` must outlive the future; the summary gives the thickness (record_thickness).
std::future<ExactVolume> start_exact_wall_volume(const wall::WallField& field, const StepRequest& request,
                                                 const StepSummary& summary);

// The volume of a solid that passes: within 0.1% of the exact wall volume (issue 28), beyond three
// standard errors of the quadrature.
constexpr double kVolumeTolerance = 1e-3;
bool volume_agrees(const StepSummary& summary);

// Fills the summary's counts, deviation and volumes, and, where a check fails, its failure (the first
// that fails). Waits for `exact_volume`.
void measure_solid(const TopoDS_Shape& shape, const StepRequest& request, wall::WallField& field,
                   wall::WallField::Worker& worker, std::future<ExactVolume>& exact_volume, StepSummary& summary);

}  // namespace offsetgen::step
