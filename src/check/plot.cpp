#include "check/plot.h"

#include "check/process.h"
#include "surfaces/surface.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#ifndef OFFSETGEN_SOURCE_DIR
#define OFFSETGEN_SOURCE_DIR ""
#endif

namespace offsetgen::check {
namespace {

namespace fs = std::filesystem;

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

fs::path executable_dir() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

}  // namespace

std::string find_plot_script(const std::string& explicit_path) {
  if (!explicit_path.empty()) return is_file(explicit_path) ? explicit_path : "";
  if (const char* env = std::getenv("OFFSETGEN_PLOT_SCRIPT"); env != nullptr && *env != '\0')
    return is_file(env) ? std::string(env) : "";
  const fs::path installed = executable_dir() / ".." / "share" / "offsetgen" / "tools" / "plot_convergence.py";
  if (is_file(installed)) return fs::weakly_canonical(installed).string();
  const fs::path source = fs::path(OFFSETGEN_SOURCE_DIR) / "tools" / "plot_convergence.py";
  if (!std::string(OFFSETGEN_SOURCE_DIR).empty() && is_file(source)) return source.string();
  return "";
}

std::string find_python() {
  if (const char* env = std::getenv("OFFSETGEN_PYTHON"); env != nullptr && *env != '\0') return env;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return find_on_path("python3");
}

void render_plot(const nlohmann::json& spec, const std::string& png, const std::string& script) {
  if (script.empty())
    throw InputError(
        "--plot: tools/plot_convergence.py not found (looked at --plot-script, $OFFSETGEN_PLOT_SCRIPT, "
        "<prefix>/share/offsetgen/tools and the source tree); pass its path with --plot-script");
  const std::string python = find_python();
  if (python.empty()) throw InputError("--plot: no python3 found (Debian: apt-get install python3-matplotlib)");
  std::string pattern = (fs::temp_directory_path() / "offsetgen-plot-XXXXXX.json").string();
  int fd = ::mkstemps(pattern.data(), 5);
  if (fd < 0) throw std::runtime_error("cannot create a scratch file for the plot");
  ::close(fd);
  {
    std::ofstream out(pattern);
    out << spec.dump(1);
  }
  ProcessResult r = run_process({python, script, pattern, png});
  std::error_code ec;
  fs::remove(pattern, ec);
  if (!r.started || r.exit_code != 0)
    throw InputError(fmt::format("--plot: {} {} failed (exit {}):\n{}", python, script, r.exit_code, r.output));
}

}  // namespace offsetgen::check
