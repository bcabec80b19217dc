// offsetgen-step: runs `offsetgen step` and `offsetgen check FILE.step`, which offsetgen passes on
// (siblings.h), so that only STEP export loads OpenCASCADE.
#include "cli/command_table.h"
#include "cli/step_command.h"
#include "cli/step_options.h"
#include "surfaces/input_error.h"

#include <malloc.h>
#include <CLI/CLI.hpp>
#include <Standard_Failure.hxx>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// OpenCASCADE's exceptions are not std::exception: reported as an internal error, exit 3.
int with_occt_errors(const std::function<int()>& run) {
  try {
    return run();
  } catch (const Standard_Failure& e) {
    throw std::runtime_error(std::string("OpenCASCADE: ") + e.DynamicType()->Name() + ": " + e.GetMessageString());
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace offsetgen;
  // Root finding and OpenCASCADE allocate and free buffers of a few hundred kB by the million: above
  // glibc's default threshold each is a fresh mmap and its pages fault in again (a third of the
  // fitting's time went to the kernel). Keep them on the heap.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  CLI::App app{"offsetgen-step: the `offsetgen step` command (see offsetgen step --help)", "offsetgen"};
  const std::vector<Command> table{
      command_row<StepOptions>(
          "step", add_step_command,
          [](const StepOptions& o, char**) { return with_occt_errors([&] { return run_step_command(o); }); }),
      // `offsetgen check part.step` lands here (offsetgen execs this executable with its arguments).
      {"check", [](CLI::App& a) -> CommandRun {
         auto file = std::make_shared<std::string>();
         CLI::App* check =
             a.add_subcommand("check", "Check a STEP file of `offsetgen step` against the walls its header names");
         check->add_option("file", *file, "A .step or .stp file written by `offsetgen step`")->required();
         check->allow_extras();  // offsetgen's own check options, refused below with a reason
         return [file, check](char**) {
           if (!check->remaining().empty())
             throw InputError(
                 "a STEP file is checked against its own header: `offsetgen check FILE.step` takes no options (" +
                 check->remaining().front() + " given)");
           return with_occt_errors([&] { return run_step_check(*file); });
         };
       }}};
  return run_command_table(app, table, argc, argv);
}
