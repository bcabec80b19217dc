// offsetgen: closed-form offset functions of implicit surfaces. Its commands are the rows of
// offsetgen_commands() (command_table.cpp); mesh and step run in executables beside it (siblings.h).
#include "cli/command_line.h"
#include "cli/command_table.h"
#include "emit/backend.h"

#include <fmt/format.h>
#include <ginac/ginac.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  using namespace offsetgen;
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
  app.footer(
      "Exit status: 0 success, 1 a check failed, 2 usage or input error, 3 internal error,\n"
      "4 not checked (a tool the check needs is missing), 130/143 interrupted by SIGINT/SIGTERM\n"
      "(the unfinished files removed).\n"
      "Example: offsetgen generate --surface gyroid --order 4 --lang c -o gyroid_o4.h");
  const int status = run_command_table(app, offsetgen_commands(), argc, argv);
  // Every file is written and closed by now, so only the standard streams need flushing. The static
  // destructors are skipped: GiNaC's and CLN's are thousands (the exit handlers were 3% of a --version
  // run in perf record).
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(status);
}
