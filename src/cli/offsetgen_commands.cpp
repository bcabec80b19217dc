// offsetgen's command table: one row per command, in the order of its --help. A new command is a
// row here (docs/architecture.md, "To add a command").
#include "cli/check_command.h"
#include "cli/command_table.h"
#include "cli/density_command.h"
#include "cli/generate_command.h"
#include "cli/list_command.h"
#include "cli/siblings.h"
#include "cli/slice_command.h"

#include <string>
#include <vector>

namespace offsetgen {

std::vector<Command> offsetgen_commands() {
  return {
      command_row<GenerateOptions>("generate", add_generate_command,
                                   [](const GenerateOptions& o, char** argv) {
                                     std::vector<std::string> args;
                                     for (char** a = argv; *a != nullptr; ++a) args.emplace_back(*a);
                                     return run_generate(o, args);
                                   }),
      command_row<ListOptions>("list", add_list_command, [](const ListOptions& o, char**) { return run_list(o); }),
      command_row<DensityOptions>("density", add_density_command,
                                  [](const DensityOptions& o, char**) { return run_density(o); }),
      command_row<SliceOptions>("slice", add_slice_command,
                                [](const SliceOptions& o, char**) { return run_slice_command(o); }),
      // A STEP file is read with OpenCASCADE, by offsetgen-step.
      command_row<CheckOptions>("check", add_check_command,
                                [](const CheckOptions& o, char** argv) {
                                  return names_a_step_file(o.file) ? exec_sibling(step_sibling(), argv) : run_check(o);
                                }),
      sibling_command(mesh_sibling()),
      sibling_command(step_sibling()),
  };
}

}  // namespace offsetgen
