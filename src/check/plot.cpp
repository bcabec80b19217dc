#include "check/plot.h"

#include "emit/file_writer.h"
#include "run/process.h"
#include "surfaces/surface.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

// Defined only in test and benchmark executables (src/dev/source_paths.cpp): the source tree.
extern "C" const char* offsetgen_source_dir() __attribute__((weak));

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
  for (const fs::path& share :
       {executable_dir() / ".." / "share", executable_dir() / "share"}) {  // installed, build tree
    const fs::path script = share / "offsetgen" / "tools" / "plot_convergence.py";
    if (is_file(script)) return fs::weakly_canonical(script).string();
  }
  if (offsetgen_source_dir) {
    const fs::path source = fs::path(offsetgen_source_dir()) / "tools" / "plot_convergence.py";
    if (is_file(source)) return source.string();
  }
  return "";
}

void render_plot(const nlohmann::json& spec, const std::string& png, const std::string& script) {
  if (script.empty())
    throw InputError(
        "--plot: tools/plot_convergence.py not found (looked at --plot-script, $OFFSETGEN_PLOT_SCRIPT, "
        "<prefix>/share/offsetgen/tools and the source tree); pass its path with --plot-script");
  const std::string python = run::find_python();
  if (python.empty()) throw InputError("--plot: no python3 found (Debian: apt-get install python3-matplotlib)");
  std::string pattern = (fs::temp_directory_path() / "offsetgen-plot-XXXXXX.json").string();
  int fd = ::mkstemps(pattern.data(), 5);
  if (fd < 0) throw std::runtime_error("cannot create a scratch file for the plot");
  ::close(fd);
  {
    std::ofstream out(pattern);
    out << spec.dump(1);
  }
  // The script draws into a scratch file; the PNG is then written by offsetgen's own rules (normal
  // mode, symlinks written through, no device or FIFO clobbered).
  const std::string scratch_png = pattern.substr(0, pattern.size() - 5) + ".png";
  run::ProcessResult r = run::run_process({python, script, pattern, scratch_png});
  std::error_code ec;
  fs::remove(pattern, ec);
  std::string bytes;
  {
    std::ifstream in(scratch_png, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  fs::remove(scratch_png, ec);
  if (!r.started || r.exit_code != 0)
    throw InputError(fmt::format("--plot: {} {} failed (exit {}):\n{}", python, script, r.exit_code, r.output));
  try {
    write_file_if_changed(png, bytes);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("--plot: {}", e.what()));
  }
}

}  // namespace offsetgen::check
