#include "emit/templates.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#ifndef OFFSETGEN_SOURCE_TEMPLATE_DIR
#define OFFSETGEN_SOURCE_TEMPLATE_DIR ""
#endif

namespace offsetgen {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> candidate_directories() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("OFFSETGEN_TEMPLATE_DIR"); env && *env) dirs.emplace_back(env);
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share" / "offsetgen" / "templates");
  if (*OFFSETGEN_SOURCE_TEMPLATE_DIR) dirs.emplace_back(OFFSETGEN_SOURCE_TEMPLATE_DIR);
  return dirs;
}

}  // namespace

std::string template_directory() {
  for (const auto& dir : candidate_directories()) {
    std::error_code ec;
    if (fs::is_regular_file(dir / "c_header.h.in", ec)) return dir.string();
  }
  std::string tried;
  for (const auto& dir : candidate_directories()) tried += "\n  " + dir.string();
  throw std::runtime_error("cannot find offsetgen's templates; looked in:" + tried +
                           "\nset OFFSETGEN_TEMPLATE_DIR to the templates/ folder");
}

std::string load_template(const std::string& name) {
  fs::path path = fs::path(template_directory()) / name;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read template " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace offsetgen
