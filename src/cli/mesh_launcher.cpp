#include "cli/mesh_launcher.h"

#include "cli/command_line.h"

#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace offsetgen {

int exec_mesh_executable(char** argv) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    fmt::print(stderr, "offsetgen: error: cannot start {} for `mesh`: /proc/self/exe: {}\n", OFFSETGEN_MESH_EXECUTABLE,
               ec.message());
    return kExitInternal;
  }
  const fs::path mesh = self.parent_path() / OFFSETGEN_MESH_EXECUTABLE;
  ::execv(mesh.c_str(), argv);
  const int error = errno;
  fmt::print(stderr,
             "offsetgen: error: `offsetgen mesh` runs {}, which {} ({}); it is built with OpenVDB and installed "
             "beside offsetgen: rebuild or reinstall offsetgen\n",
             mesh.string(), error == ENOENT ? "is missing" : "cannot be started", std::strerror(error));
  return kExitInternal;
}

}  // namespace offsetgen
