// offsetgen: closed-form offset functions of implicit surfaces.
#include "cli/command_line.h"
#include "cli/density_command.h"
#include "cli/generate_command.h"
#include "cli/list_command.h"
#include "cli/slice_command.h"
#ifdef OFFSETGEN_HAVE_CHECK
#include "cli/check_command.h"
#endif
#ifdef OFFSETGEN_HAVE_MESH
#include "cli/mesh_launcher.h"
#include "cli/mesh_options.h"
#endif
#ifdef OFFSETGEN_HAVE_STEP
#include "cli/step_launcher.h"
#include "cli/step_options.h"
#endif
#include "emit/backend.h"
#include "support/interrupt_cleanup.h"
#include "surfaces/surface.h"

#include <fmt/format.h>
#include <ginac/ginac.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace offsetgen;
  std::vector<std::string> args(argv, argv + argc);

  // Targets and methods come from their registries, so the help text names every one that is built in.
  std::string targets;
  for (const Backend* b : backends()) targets += (targets.empty() ? "" : ", ") + b->title();
  const std::string about = fmt::format(
      "offsetgen: turns an implicit surface F = 0 (e.g. a TPMS such as the gyroid) into closed-form\n"
      "offset functions phi(x, h) of any order, emitted as {} (--lang).\n"
      "Offset constructions (--method):{}",
      targets, method_help_lines());
  CLI::App app{about, "offsetgen"};
  app.set_version_flag("-V,--version",
                       fmt::format("offsetgen {} (GiNaC {}.{}.{}, CLN)", OFFSETGEN_VERSION, GINACLIB_MAJOR_VERSION,
                                   GINACLIB_MINOR_VERSION, GINACLIB_MICRO_VERSION));
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 a check failed, 2 usage or input error, 3 internal error,\n"
      "4 not checked (a tool the check needs is missing), 130/143 interrupted by SIGINT/SIGTERM\n"
      "(the unfinished files removed).\n"
      "Example: offsetgen generate --surface gyroid --order 4 --lang c -o gyroid_o4.h");

  GenerateOptions generate;
  add_generate_command(app, generate);
  ListOptions list;
  add_list_command(app, list);
  DensityOptions density;
  add_density_command(app, density);
  SliceOptions slice;
  add_slice_command(app, slice);
#ifdef OFFSETGEN_HAVE_CHECK
  CheckOptions check;
  add_check_command(app, check);
#endif
#ifdef OFFSETGEN_HAVE_MESH
  // Parsed here (--help, usage errors), run by offsetgen-mesh, which parses the same arguments again.
  MeshOptions mesh;
  add_mesh_command(app, mesh);
#else
  // Named, so that asking for it gets a reason rather than "unknown subcommand".
  app.add_subcommand("mesh", "(not in this build: offsetgen was configured without OpenVDB)")
      ->allow_extras()
      ->group("");
#endif
#ifdef OFFSETGEN_HAVE_STEP
  // Parsed here, run by offsetgen-step (OpenCASCADE), which parses the same arguments again.
  StepOptions step;
  add_step_command(app, step);
#else
  app.add_subcommand("step", "(not in this build: offsetgen was configured without OpenCASCADE)")
      ->allow_extras()
      ->group("");
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  // Ctrl-C or SIGTERM removes the unfinished files and scratch directories ("offsetgen generate: ...").
  // mesh and step exec their own executables, which install the same.
  install_interrupt_cleanup(("offsetgen " + app.get_subcommands().front()->get_name()).c_str());
  const int status = run_reporting_errors([&] {
    if (app.got_subcommand("generate")) return run_generate(generate, args);
    if (app.got_subcommand("list")) return run_list(list);
    if (app.got_subcommand("density")) return run_density(density);
    if (app.got_subcommand("slice")) return run_slice_command(slice);
#ifdef OFFSETGEN_HAVE_CHECK
    if (app.got_subcommand("check") && names_a_step_file(check.file)) {
#ifdef OFFSETGEN_HAVE_STEP
      return exec_step_executable(argv);  // offsetgen-step reads the file with OpenCASCADE
#else
      throw InputError(
          "checking a STEP file needs offsetgen-step, and this offsetgen was built without it: it needs "
          "OpenCASCADE (tools/install_deps.sh --build, then reconfigure)");
#endif
    }
    if (app.got_subcommand("check")) return run_check(check);
#endif
#ifdef OFFSETGEN_HAVE_MESH
    if (app.got_subcommand("mesh")) return exec_mesh_executable(argv);
#else
    if (app.got_subcommand("mesh"))
      throw InputError(
          "this offsetgen was built without `mesh`: it needs OpenVDB (apt-get install libopenvdb-dev "
          "libboost-iostreams-dev, then reconfigure; -DOFFSETGEN_BUILD_MESH=ON insists)");
#endif
#ifdef OFFSETGEN_HAVE_STEP
    if (app.got_subcommand("step")) return exec_step_executable(argv);
#else
    if (app.got_subcommand("step")) {
      fmt::print(stderr,
                 "offsetgen: error: this offsetgen was built without `step`: it needs OpenCASCADE (apt-get install "
                 "libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev "
                 "libocct-data-exchange-dev, then reconfigure; -DOFFSETGEN_BUILD_STEP=ON insists)\n");
      return static_cast<int>(kExitInternal);
    }
#endif
    return static_cast<int>(kExitUsage);
  });
  // Every file is written and closed by now, so only the standard streams need flushing. The static
  // destructors are skipped: GiNaC's and CLN's are thousands (the exit handlers were 3% of a --version
  // run in perf record).
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(status);
}
