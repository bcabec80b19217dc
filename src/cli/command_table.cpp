#include "cli/command_table.h"

#include "cli/command_line.h"
#include "support/interrupt_cleanup.h"

#include <string>
#include <utility>

namespace offsetgen {

int run_command_table(CLI::App& app, const std::vector<Command>& table, int argc, char** argv) {
  app.require_subcommand(1);
  std::vector<std::pair<CLI::App*, CommandRun>> runs;
  for (const Command& c : table) {
    CommandRun run = c.define(app);
    runs.emplace_back(app.get_subcommand(c.name), std::move(run));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  for (auto& [subcommand, run] : runs) {
    if (!subcommand->parsed()) continue;
    install_interrupt_cleanup(("offsetgen " + subcommand->get_name()).c_str());
    return run_reporting_errors([&, &run = run] { return run(argv); });
  }
  return kExitUsage;
}

}  // namespace offsetgen
