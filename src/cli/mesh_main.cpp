// offsetgen-mesh: runs `offsetgen mesh`, which offsetgen passes on unparsed (siblings.h), so that only
// meshing loads OpenVDB and TBB.
#include "cli/command_table.h"
#include "cli/mesh_command.h"
#include "cli/mesh_options.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  using namespace offsetgen;
  CLI::App app{"offsetgen-mesh: the `offsetgen mesh` command (see offsetgen mesh --help)", "offsetgen"};
  return run_command_table(app,
                           {command_row<MeshOptions>("mesh", add_mesh_command,
                                                     [](const MeshOptions& o, char**) { return run_mesh_command(o); })},
                           argc, argv);
}
