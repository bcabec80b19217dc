// Helpers shared by the subcommands: exit codes, the banner's command text and help text.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace offsetgen {

// 130 and 143 (128 + SIGINT, 128 + SIGTERM, the shell's convention) are the exits of a run ended by
// Ctrl-C or a scheduler's SIGTERM, after its unfinished files are removed (support/interrupt_cleanup.h).
enum ExitCode {
  kExitOk = 0,
  kExitCheckFailed = 1,
  kExitUsage = 2,
  kExitInternal = 3,
  kExitNotChecked = 4,  // check: a tool it needs is missing (ToolMissing); the file was not judged
  kExitInterrupted = 130,
  kExitTerminated = 143
};

// "offsetgen generate --surface gyroid ..." with shell quoting where needed. Output locations
// (-o, --out-dir) are reduced to file names so the same inputs give the same bytes in any directory.
std::string banner_command(const std::vector<std::string>& args);

// Runs a parsed command: bad input says "offsetgen: error: ..." and exits 2, anything else that throws
// says "offsetgen: internal error: ..." and exits 3. Shared by offsetgen and offsetgen-mesh, so a user
// sees the same either way.
int run_reporting_errors(const std::function<int()>& command);

// One "\n  name: description" line per registered offset method, for --help texts.
std::string method_help_lines();

}  // namespace offsetgen
