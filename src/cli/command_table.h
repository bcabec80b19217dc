// The CLI as a table of commands. A command is one row: its name, and a function that adds its
// subcommand (with the option groups it shares: generation_options.h, cells_option.h, ...) to the
// app and returns what runs it once the arguments are parsed. offsetgen and the executables beside it
// (siblings.h) each parse and run their own table the same way (run_command_table).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace offsetgen {

// Runs a parsed command; argv is the whole command line (a sibling is handed it unchanged).
using CommandRun = std::function<int(char** argv)>;

struct Command {
  std::string name;
  std::function<CommandRun(CLI::App& app)> define;
};

// A row from an options struct, the function that adds its subcommand and options, and the run;
// the options live as long as the returned run.
template <class Options>
Command command_row(std::string name, void (*add)(CLI::App&, Options&),
                    std::function<int(const Options&, char** argv)> run) {
  return {std::move(name), [add, run = std::move(run)](CLI::App& app) -> CommandRun {
            auto options = std::make_shared<Options>();
            add(app, *options);
            return [options, run](char** argv) { return run(*options, argv); };
          }};
}

// offsetgen's table, in the order of its --help.
std::vector<Command> offsetgen_commands();

// Adds the table's subcommands to `app` (one is required), parses argv (--help and usage errors: exit 0
// and 2), makes Ctrl-C and SIGTERM remove unfinished files ("offsetgen <command>: ..."), and runs the
// chosen command with its errors reported (run_reporting_errors in command_line.h).
int run_command_table(CLI::App& app, const std::vector<Command>& table, int argc, char** argv);

}  // namespace offsetgen
