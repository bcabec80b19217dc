#include "offsetgen_test_support.h"

#include "run/process.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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
