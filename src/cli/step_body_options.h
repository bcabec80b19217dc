// `offsetgen step --body part.step --skin --origin --scale`: mesh's body options (body_options.h) as
// STEP export takes them, a B-rep body instead of a mesh, no --fillet and no --repair.
#pragma once

#include "cli/body_options.h"

#include <CLI/CLI.hpp>

namespace offsetgen {

void add_step_body_options(CLI::App* cmd, BodyOptions& options);

}  // namespace offsetgen
