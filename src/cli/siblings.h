// Commands that need a large library run in an executable of their own beside offsetgen: `mesh` in
// offsetgen-mesh (OpenVDB), `step` (and `check` of a STEP file) in offsetgen-step (OpenCASCADE).
// Linked into offsetgen, such a library would cost every run (generate, list, --version) its start-up.
// offsetgen passes the command line on unparsed; the sibling parses it once, --help included.
#pragma once

#include "cli/command_table.h"

namespace offsetgen {

struct Sibling {
  const char* command;     // "mesh"
  const char* summary;     // its line in offsetgen --help
  const char* executable;  // its file name, or "" where this build has none
  const char* library;     // what it links, for messages
  const char* to_build;    // how to get a build that has it
};

const Sibling& mesh_sibling();
const Sibling& step_sibling();

// offsetgen's row for a sibling: a subcommand that takes any arguments and execs the sibling.
Command sibling_command(const Sibling& sibling);

// Replaces this process with the sibling from this executable's directory (the build tree's or an
// installed bin/), given the same arguments. Returns only if that fails, after saying why on stderr,
// with exit status 3 (kExitInternal): the installation is incomplete or was built without it, the
// input is not at fault.
int exec_sibling(const Sibling& sibling, char** argv);

}  // namespace offsetgen
