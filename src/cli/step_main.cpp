// offsetgen-step: runs `offsetgen step`. offsetgen parses the command (its --help and usage errors),
// then execs this executable with the same arguments ("offsetgen step ..."), so that only STEP export
// loads OpenCASCADE (sibling_exec.h).
#include "cli/command_line.h"
#include "cli/step_command.h"
#include "cli/step_options.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  using namespace offsetgen;
  CLI::App app{"offsetgen-step: the `offsetgen step` command (see offsetgen step --help)", "offsetgen"};
  app.require_subcommand(1);
  StepOptions step;
  add_step_command(app, step);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  return run_reporting_errors([&] { return run_step_command(step); });
}
