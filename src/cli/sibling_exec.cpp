#include "cli/sibling_exec.h"

#include "cli/command_line.h"

#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace offsetgen {

int exec_sibling(const char* executable, const char* command, const char* library, char** argv) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    fmt::print(stderr, "offsetgen: error: cannot start {} for `{}`: /proc/self/exe: {}\n", executable, command,
               ec.message());
    return kExitInternal;
  }
  const fs::path path = self.parent_path() / executable;
  ::execv(path.c_str(), argv);
  const int error = errno;
  fmt::print(stderr,
             "offsetgen: error: `offsetgen {}` runs {}, which {} ({}); it is built with {} and installed "
             "beside offsetgen: rebuild or reinstall offsetgen\n",
             command, path.string(), error == ENOENT ? "is missing" : "cannot be started", std::strerror(error),
             library);
  return kExitInternal;
}

}  // namespace offsetgen
