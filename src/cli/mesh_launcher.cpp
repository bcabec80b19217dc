#include "cli/mesh_launcher.h"

#include "cli/sibling_exec.h"

namespace offsetgen {

int exec_mesh_executable(char** argv) { return exec_sibling(OFFSETGEN_MESH_EXECUTABLE, "mesh", "OpenVDB", argv); }

}  // namespace offsetgen
