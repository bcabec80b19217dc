// Helpers every test folder shares: running programs (one runner, src/run/process.h), scratch
// directories, reading and writing files, and where the built offsetgen and the source tree are.
// Metadata of generated files: use run::parse_metadata / run::read_metadata directly.
#pragma once

#include <sys/types.h>

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

// A program started in the background, for tests that signal it while it runs. It gets a process
// group of its own, as a shell's job does, so that signal_group() reaches it and the compilers it
// starts, as Ctrl-C and Slurm's SIGTERM do; SIGINT and SIGTERM start at their default actions (a test
// run from a background job would otherwise pass SIGINT on ignored). Stdout and stderr go to `log`;
// `environment` ("NAME=value") adds to or replaces this process's. Killed and reaped, if still
// running, when this goes out of scope.
class BackgroundCommand {
 public:
  BackgroundCommand(const std::vector<std::string>& argv, const std::string& log,
                    const std::vector<std::string>& environment = {});
  ~BackgroundCommand();
  BackgroundCommand(const BackgroundCommand&) = delete;
  BackgroundCommand& operator=(const BackgroundCommand&) = delete;

  bool running();
  void signal_group(int signo);
  CommandResult wait();  // exit status or 128 + signal; output: the log

 private:
  pid_t pid_ = -1;
  int status_ = 0;
  bool reaped_ = false;
  std::string log_;
};

// The name of the first entry of `dir` that starts with `prefix`, polled for while `command` runs;
// "" when the command ends or `seconds` pass first.
std::string wait_for_entry(const std::string& dir, const std::string& prefix, BackgroundCommand& command,
                           double seconds);

// The names in `dir` that start with `prefix`.
std::vector<std::string> entries_starting_with(const std::string& dir, const std::string& prefix);

std::string offsetgen_executable();
std::string source_dir();

// A fresh empty directory <build>/tests/tmp/<name>-<pid> (ctest runs tests in parallel processes).
std::string scratch_dir(const std::string& name);

std::string read_file(const std::string& path);  // "" when it cannot be read
void write_file(const std::string& path, const std::string& text);

}  // namespace offsetgen::test_support
