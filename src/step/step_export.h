// `offsetgen step`: the wall of a block of cells as a STEP solid, its deviation from the exact wall
// measured before the file is written (docs/step.md). The request (step_request.h), the route and fit
// (patch_route.h), the file (step_file.h, step_metadata.h), the measurement (measurement.h) and the
// file check (step_check.h) each have their own file; this one runs them in turn.
#pragma once

#include "step/step_request.h"
#include "step/step_summary.h"

#include <functional>
#include <string>

namespace offsetgen::step {

// Throws InputError for what the exporter does not cover or bad input (nothing is written then).
// summary.passed: every check passed and request.output was written.
StepSummary export_step(const StepRequest& request, const std::function<void(const std::string&)>& progress);

}  // namespace offsetgen::step
