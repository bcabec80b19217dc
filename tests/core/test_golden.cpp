// Regenerates every file of generated/ (from generated/MANIFEST) and diffs it byte for byte.
// To accept an intended change: tools/update_golden.sh, review `git diff generated/`, commit.
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace offsetgen {
namespace {
namespace fs = std::filesystem;

TEST(GoldenFiles, RegeneratingGivesTheCommittedBytes) {
  const fs::path golden = fs::path(OFFSETGEN_SOURCE_DIR) / "generated";
  std::ifstream manifest(golden / "MANIFEST");
  ASSERT_TRUE(manifest) << "generated/MANIFEST missing";
  std::string dir = testing::fresh_directory("golden");
  std::string line;
  int commands = 0;
  while (std::getline(manifest, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto r = testing::run_offsetgen("generate " + line + " --out-dir " + dir + " --quiet");
    ASSERT_EQ(r.exit_code, 0) << line << "\n" << r.output;
    ++commands;
  }
  EXPECT_GE(commands, 32);
  size_t compared = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const fs::path committed = golden / entry.path().filename();
    ASSERT_TRUE(fs::exists(committed)) << committed << " is not committed; run tools/update_golden.sh";
    EXPECT_TRUE(testing::read_file(entry.path().string()) == testing::read_file(committed.string()))
        << committed << " differs from what the generator produces now. If the change is intended, run "
        << "tools/update_golden.sh, review `git diff generated/`, and commit.";
    ++compared;
  }
  EXPECT_EQ(compared, 2u * static_cast<size_t>(commands));  // a .h and a .glsl per line
}

}  // namespace
}  // namespace offsetgen
