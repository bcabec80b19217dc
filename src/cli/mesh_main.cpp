// offsetgen-mesh: runs `offsetgen mesh`. offsetgen parses the command (its --help and usage errors),
// then execs this executable with the same arguments ("offsetgen mesh ..."), so that only meshing
// loads OpenVDB and TBB (mesh_launcher.h).
#include "cli/command_line.h"
#include "cli/mesh_command.h"
#include "cli/mesh_options.h"
#include "support/interrupt_cleanup.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  using namespace offsetgen;
  CLI::App app{"offsetgen-mesh: the `offsetgen mesh` command (see offsetgen mesh --help)", "offsetgen"};
  app.require_subcommand(1);
  MeshOptions mesh;
  add_mesh_command(app, mesh);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  install_interrupt_cleanup("offsetgen mesh");  // Ctrl-C or SIGTERM removes the unfinished output
  return run_reporting_errors([&] { return run_mesh_command(mesh); });
}
