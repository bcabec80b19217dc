#include "cli/step_launcher.h"

#include "cli/sibling_exec.h"

namespace offsetgen {

int exec_step_executable(char** argv) { return exec_sibling(OFFSETGEN_STEP_EXECUTABLE, "step", "OpenCASCADE", argv); }

}  // namespace offsetgen
