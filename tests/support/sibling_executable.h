// What a command that runs in an executable beside offsetgen (mesh: offsetgen-mesh, step:
// offsetgen-step) owes its users, checked the same way for each: only the sibling loads the heavy
// libraries, and offsetgen alone says which sibling is missing. For gtest tests.
#pragma once

#include "offsetgen_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace offsetgen::test_support {

// ldd's list of what `executable` loads.
inline std::string shared_libraries(const std::string& executable) {
  const CommandResult r = run_command({"ldd", executable});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r.output;
}

// offsetgen copied alone into a scratch directory: `offsetgen COMMAND ARGS -o OUTPUT` exits 3 naming the
// sibling it looked for and writes nothing; --help and an unknown option exit 3 too (the options are
// parsed once, by the sibling).
inline void expect_a_missing_sibling_exits_3(const std::string& command, const std::string& sibling,
                                             const std::vector<std::string>& args, const std::string& output) {
  namespace fs = std::filesystem;
  const std::string dir = scratch_dir("lone-offsetgen");
  const std::string lone = dir + "/offsetgen";
  fs::copy_file(offsetgen_executable(), lone);
  std::vector<std::string> argv = {lone, command};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"-o", dir + "/" + output});
  const CommandResult r = run_command(argv);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find(dir + "/" + fs::path(sibling).filename().string() + ", which is missing"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir + "/" + output));
  const CommandResult help = run_command({lone, command, "--help"});
  EXPECT_EQ(help.exit_code, 3) << help.output;
  EXPECT_NE(help.output.find("which is missing"), std::string::npos) << help.output;
  EXPECT_EQ(run_command({lone, command, "--bogus"}).exit_code, 3);
}

}  // namespace offsetgen::test_support
