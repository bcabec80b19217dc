// Runs `offsetgen step` (in offsetgen-step, which links OpenCASCADE).
#pragma once

#include "cli/step_options.h"

#include <string>

namespace offsetgen {

int run_step_command(const StepOptions& options);

// `offsetgen check part.step`: exit 0 when the file passes, 1 when a check fails, 2 for a file that
// is not a STEP file of offsetgen step.
int run_step_check(const std::string& path);

}  // namespace offsetgen
