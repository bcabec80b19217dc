// Commands that need a large library run in an executable of their own beside offsetgen: `mesh` in
// offsetgen-mesh (OpenVDB), `step` in offsetgen-step (OpenCASCADE). Linked into offsetgen, such a
// library would cost every run (generate, list, --version) its start-up.
#pragma once

namespace offsetgen {

// Replaces this process with `executable` from this executable's directory (the build tree's or an
// installed bin/), given the same arguments. Returns only if that fails, after saying why on stderr
// (naming `command` and the `library` it is built with), with exit status 3 (kExitInternal): the
// installation is incomplete, the input is not at fault.
int exec_sibling(const char* executable, const char* command, const char* library, char** argv);

}  // namespace offsetgen
