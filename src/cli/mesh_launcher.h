// `offsetgen mesh` runs in offsetgen-mesh, the executable beside offsetgen that links OpenVDB: linked
// into offsetgen, OpenVDB and TBB cost every run (generate, list, --version) about 75 ms of start-up.
#pragma once

namespace offsetgen {

// Replaces this process with offsetgen-mesh from this executable's directory (the build tree's or an
// installed bin/), given the same arguments. Returns only if that fails, after saying why on stderr,
// with exit status 3 (kExitInternal): the installation is incomplete, the input is not at fault.
int exec_mesh_executable(char** argv);

}  // namespace offsetgen
