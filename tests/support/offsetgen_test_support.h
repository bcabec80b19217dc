// Helpers every test folder shares: running programs (one runner, src/run/process.h), scratch
// directories, reading and writing files, and where the built offsetgen and the source tree are.
// Metadata of generated files: use run::parse_metadata / run::read_metadata directly.
#pragma once

#include <string>
#include <vector>

namespace offsetgen::test_support {

struct CommandResult {
  int exit_code = -1;  // exit status, 128 + signal, or -1 when the program could not be started
  std::string output;  // stdout and stderr together
};

// Runs argv[0] (looked up on PATH) with the arguments, without a shell.
CommandResult run_command(const std::vector<std::string>& argv);

// Runs `command_line` with /bin/sh -c: for command lines written with shell quoting.
CommandResult run_shell(const std::string& command_line);

// The built offsetgen with `args`: as an argument vector, or as one shell-quoted string.
CommandResult run_offsetgen(const std::vector<std::string>& args);
CommandResult run_offsetgen(const std::string& args);

std::string offsetgen_executable();
std::string source_dir();

// A fresh empty directory <build>/tests/tmp/<name>-<pid> (ctest runs tests in parallel processes).
std::string scratch_dir(const std::string& name);

std::string read_file(const std::string& path);  // "" when it cannot be read
void write_file(const std::string& path, const std::string& text);

}  // namespace offsetgen::test_support
