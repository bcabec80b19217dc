// `offsetgen mesh`: the run, in offsetgen-mesh (the executable that links OpenVDB).
#pragma once

#include "cli/cells_option.h"
#include "cli/mesh_options.h"

#include <array>
#include <string>

namespace offsetgen {

int run_mesh_command(const MeshOptions& options);

// "1,2.5,-3" -> {1, 2.5, -3} (--origin). Throws InputError naming `option`.
std::array<double, 3> parse_point(const std::string& text, const std::string& option);

}  // namespace offsetgen
