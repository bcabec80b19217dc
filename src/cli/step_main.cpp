// offsetgen-step: runs `offsetgen step`. offsetgen parses the command (its --help and usage errors),
// then execs this executable with the same arguments ("offsetgen step ..."), so that only STEP export
// loads OpenCASCADE (sibling_exec.h).
#include "cli/command_line.h"
#include "cli/step_command.h"
#include "cli/step_options.h"
#include "support/interrupt_cleanup.h"
#include "surfaces/input_error.h"

#include <malloc.h>
#include <CLI/CLI.hpp>
#include <Standard_Failure.hxx>

#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
  using namespace offsetgen;
  // Root finding and OpenCASCADE allocate and free buffers of a few hundred kB by the million: above
  // glibc's default threshold each is a fresh mmap and its pages fault in again (a third of the
  // fitting's time went to the kernel). Keep them on the heap.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  CLI::App app{"offsetgen-step: the `offsetgen step` command (see offsetgen step --help)", "offsetgen"};
  app.require_subcommand(1);
  StepOptions step;
  add_step_command(app, step);
  // `offsetgen check part.step` lands here (offsetgen execs this executable with its arguments).
  std::string check_file;
  CLI::App* check =
      app.add_subcommand("check", "Check a STEP file of `offsetgen step` against the walls its header names");
  check->add_option("file", check_file, "A .step or .stp file written by `offsetgen step`")->required();
  check->allow_extras();  // offsetgen's own check options, refused below with a reason
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  // Ctrl-C or SIGTERM removes the unfinished STEP file and the scratch directories.
  install_interrupt_cleanup(app.got_subcommand("check") ? "offsetgen check" : "offsetgen step");
  return run_reporting_errors([&] {
    try {
      if (app.got_subcommand("check")) {
        if (!check->remaining().empty())
          throw InputError(
              "a STEP file is checked against its own header: `offsetgen check FILE.step` takes no options (" +
              check->remaining().front() + " given)");
        return run_step_check(check_file);
      }
      return run_step_command(step);
    } catch (const Standard_Failure& e) {
      // OpenCASCADE's exceptions are not std::exception: reported as an internal error, exit 3.
      throw std::runtime_error(std::string("OpenCASCADE: ") + e.DynamicType()->Name() + ": " + e.GetMessageString());
    }
  });
}
