// Runs `offsetgen step` (in offsetgen-step, which links OpenCASCADE).
#pragma once

#include "cli/step_options.h"

namespace offsetgen {

int run_step_command(const StepOptions& options);

}  // namespace offsetgen
