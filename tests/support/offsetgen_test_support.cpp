#include "offsetgen_test_support.h"

#include "run/process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace offsetgen::test_support {

CommandResult run_command(const std::vector<std::string>& argv) {
  const run::ProcessResult r = run::run_process(argv);
  return {r.started ? r.exit_code : -1, r.output};
}

CommandResult run_shell(const std::string& command_line) { return run_command({"/bin/sh", "-c", command_line}); }

CommandResult run_offsetgen(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {OFFSETGEN_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_command(argv);
}

CommandResult run_offsetgen(const std::string& args) { return run_shell("'" + offsetgen_executable() + "' " + args); }

BackgroundCommand::BackgroundCommand(const std::vector<std::string>& argv, const std::string& log,
                                     const std::vector<std::string>& environment)
    : log_(log) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const auto& add : environment) {
      const std::string name = add.substr(0, add.find('=') + 1);  // "TMPDIR="
      replaced = replaced || (!name.empty() && entry.rfind(name, 0) == 0);
    }
    if (!replaced) env.push_back(entry);
  }
  env.insert(env.end(), environment.begin(), environment.end());
  std::vector<char*> args, envp;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  for (const auto& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  args.push_back(nullptr);
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults, empty;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigemptyset(&empty);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &empty);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  const int rc = ::posix_spawn(&pid_, args[0], &actions, &attr, args.data(), envp.data());
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error(argv[0] + ": " + std::strerror(rc));
}

BackgroundCommand::~BackgroundCommand() {
  if (running()) {
    ::kill(-pid_, SIGKILL);
    wait();
  }
}

bool BackgroundCommand::running() {
  if (reaped_) return false;
  reaped_ = ::waitpid(pid_, &status_, WNOHANG) == pid_;
  return !reaped_;
}

void BackgroundCommand::signal_group(int signo) { ::kill(-pid_, signo); }

CommandResult BackgroundCommand::wait() {
  while (!reaped_) reaped_ = ::waitpid(pid_, &status_, 0) == pid_ || errno != EINTR;
  const int code = WIFEXITED(status_) ? WEXITSTATUS(status_) : WIFSIGNALED(status_) ? 128 + WTERMSIG(status_) : -1;
  return {code, read_file(log_)};
}

std::vector<std::string> entries_starting_with(const std::string& dir, const std::string& prefix) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) names.push_back(name);
  }
  return names;
}

std::string wait_for_entry(const std::string& dir, const std::string& prefix, BackgroundCommand& command,
                           double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (command.running() && std::chrono::steady_clock::now() < end) {
    const std::vector<std::string> names = entries_starting_with(dir, prefix);
    if (!names.empty()) return names.front();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return "";
}

std::string offsetgen_executable() { return OFFSETGEN_EXE; }

std::string source_dir() { return OFFSETGEN_SOURCE_DIR; }

std::string scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(OFFSETGEN_TEST_TMP) / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace offsetgen::test_support
