// `offsetgen mesh`: the run, in offsetgen-mesh (the executable that links OpenVDB).
#pragma once

#include "cli/cells_option.h"
#include "cli/mesh_options.h"

#include <array>
#include <string>

namespace offsetgen {

int run_mesh_command(const MeshOptions& options);

}  // namespace offsetgen
