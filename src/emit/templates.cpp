#include "emit/templates.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

// Defined only in test and benchmark executables (src/dev/source_paths.cpp): the source tree.
extern "C" const char* offsetgen_source_dir() __attribute__((weak));

namespace offsetgen {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> candidate_directories() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("OFFSETGEN_TEMPLATE_DIR"); env && *env) dirs.emplace_back(env);
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    dirs.push_back(exe.parent_path().parent_path() / "share" / "offsetgen" / "templates");  // installed: bin/..
    dirs.push_back(exe.parent_path() / "share" / "offsetgen" / "templates");  // the build tree's copy
  }
  if (offsetgen_source_dir) dirs.push_back(fs::path(offsetgen_source_dir()) / "templates");
  return dirs;
}

}  // namespace

std::string template_directory() {
  for (const auto& dir : candidate_directories()) {
    std::error_code ec;
    if (fs::is_regular_file(dir / "c/c_header.h.in", ec)) return dir.string();
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

std::map<std::string, std::string> load_template_sections(const std::string& name,
                                                          const std::vector<std::string>& required) {
  std::map<std::string, std::string> sections;
  std::istringstream in(load_template(name));
  std::string line, current;
  while (std::getline(in, line)) {
    if (line.rfind("@@ ", 0) == 0) {
      current = line.substr(3);
      sections[current];
      continue;
    }
    if (current.empty()) continue;
    sections[current] += line + "\n";
  }
  for (const auto& section : required)
    if (!sections.count(section)) throw std::runtime_error("template " + name + " lacks section @@ " + section);
  return sections;
}

}  // namespace offsetgen
