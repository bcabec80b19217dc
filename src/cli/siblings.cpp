#include "cli/siblings.h"

#include "cli/command_line.h"

#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace offsetgen {

// OFFSETGEN_MESH_EXECUTABLE and OFFSETGEN_STEP_EXECUTABLE: set by src/CMakeLists.txt, "" when not built.
const Sibling& mesh_sibling() {
  static const Sibling s{"mesh",
                         "Mesh a block of cells of a wall solid, or fill a part (--body) with it inside a skin, as a "
                         "closed triangle mesh (STL, PLY, 3MF)",
                         OFFSETGEN_MESH_EXECUTABLE, "OpenVDB",
                         "apt-get install libopenvdb-dev libboost-iostreams-dev, then reconfigure; "
                         "-DOFFSETGEN_BUILD_MESH=ON insists"};
  return s;
}

const Sibling& step_sibling() {
  static const Sibling s{"step", "Write a block of cells of a wall solid as a STEP file of B-spline faces, for CAD",
                         OFFSETGEN_STEP_EXECUTABLE, "OpenCASCADE",
                         "apt-get install libocct-foundation-dev libocct-modeling-data-dev "
                         "libocct-modeling-algorithms-dev libocct-data-exchange-dev, then reconfigure; "
                         "-DOFFSETGEN_BUILD_STEP=ON insists"};
  return s;
}

Command sibling_command(const Sibling& sibling) {
  return {sibling.command, [&sibling](CLI::App& app) -> CommandRun {
            CLI::App* cmd = app.add_subcommand(sibling.command, sibling.summary);
            cmd->set_help_flag();  // --help too is the sibling's
            cmd->prefix_command();
            return [&sibling](char** argv) { return exec_sibling(sibling, argv); };
          }};
}

int exec_sibling(const Sibling& sibling, char** argv) {
  namespace fs = std::filesystem;
  const std::string command = argv[1] != nullptr ? argv[1] : sibling.command;
  if (*sibling.executable == '\0') {
    fmt::print(
        stderr,
        "offsetgen: error: `offsetgen {}` needs offsetgen-{} ({}), which this offsetgen was built without ({})\n",
        command, sibling.command, sibling.library, sibling.to_build);
    return kExitInternal;
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    fmt::print(stderr, "offsetgen: error: cannot start {} for `offsetgen {}`: /proc/self/exe: {}\n", sibling.executable,
               command, ec.message());
    return kExitInternal;
  }
  const fs::path path = self.parent_path() / sibling.executable;
  ::execv(path.c_str(), argv);
  const int error = errno;
  fmt::print(stderr,
             "offsetgen: error: `offsetgen {}` runs {}, which {} ({}); it is built with {} and installed "
             "beside offsetgen: rebuild or reinstall offsetgen\n",
             command, path.string(), error == ENOENT ? "is missing" : "cannot be started", std::strerror(error),
             sibling.library);
  return kExitInternal;
}

}  // namespace offsetgen
