#include "run/process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace offsetgen::run {

namespace {

bool is_executable(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::string find_python() {
  if (const char* env = std::getenv("OFFSETGEN_PYTHON"); env != nullptr && *env != '\0') return env;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return find_on_path("python3");
}

std::string find_on_path(const std::string& name) {
  if (name.empty()) return "";
  if (name.find('/') != std::string::npos) return is_executable(name) ? name : "";
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    std::string candidate = dir + "/" + name;
    if (is_executable(candidate)) return candidate;
  }
  return "";
}

ScratchDir::ScratchDir(const std::string& stem) {
  namespace fs = std::filesystem;
  std::string pattern = (fs::temp_directory_path() / (stem + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a scratch directory in " + fs::temp_directory_path().string());
  path_ = pattern;
  if (std::getenv("OFFSETGEN_CHECK_KEEP") == nullptr) tracked_ = RemovedOnInterrupt::directory(path_.string());
}

ScratchDir::~ScratchDir() {
  if (std::getenv("OFFSETGEN_CHECK_KEEP") != nullptr) return;
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::vector<double> run_on_points(std::vector<std::string> command, const std::filesystem::path& dir,
                                  const std::vector<std::array<double, 4>>& inputs, size_t count) {
  const std::filesystem::path source = dir / "in.f64", target = dir / "out.f64";
  {
    std::ofstream out(source, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(inputs.data()),
              static_cast<std::streamsize>(inputs.size() * sizeof(inputs[0])));
    if (!out) throw std::runtime_error("cannot write " + source.string());
  }
  std::filesystem::remove(target);
  command.insert(command.end(), {source.string(), target.string()});
  const ProcessResult r = run_process(command);
  if (!r.started || r.exit_code != 0)
    throw std::runtime_error(command.front() + " failed (exit " + std::to_string(r.exit_code) + "):\n" + r.output);
  std::vector<double> values(count);
  std::ifstream in(target, std::ios::binary);
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(count * sizeof(double)));
  if (in.gcount() != static_cast<std::streamsize>(count * sizeof(double)) || in.peek() != EOF)
    throw std::runtime_error(command.front() + " wrote " + std::to_string(in.gcount()) + " bytes, expected " +
                             std::to_string(count) + " float64 values");
  return values;
}

std::vector<std::string> split_words(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  std::string word;
  while (in >> word) words.push_back(word);
  return words;
}

ProcessResult run_process(const std::vector<std::string>& argv) {
  ProcessResult result;
  if (argv.empty()) return result;
  std::string program = find_on_path(argv[0]);
  if (program.empty()) {
    result.output = argv[0] + ": not found";
    return result;
  }
  int fds[2];
  if (::pipe(fds) != 0) {
    result.output = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);

  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  int rc = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (rc != 0) {
    ::close(fds[0]);
    result.output = program + ": " + std::strerror(rc);
    return result;
  }
  result.started = true;
  std::array<char, 4096> buffer{};
  for (;;) {
    ssize_t n = ::read(fds[0], buffer.data(), buffer.size());
    if (n > 0) {
      result.output.append(buffer.data(), static_cast<size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;
    }
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.exit_code = 128 + WTERMSIG(status);
  }
  return result;
}

}  // namespace offsetgen::run
