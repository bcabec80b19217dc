// `offsetgen step` runs in offsetgen-step, the executable beside offsetgen that links OpenCASCADE.
#pragma once

namespace offsetgen {

// Replaces this process with offsetgen-step, given the same arguments (sibling_exec.h). Returns only
// if that fails, with exit status 3.
int exec_step_executable(char** argv);

}  // namespace offsetgen
