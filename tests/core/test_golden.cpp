// The committed golden files of generated/ are exactly what generated/MANIFEST produces now: every
// regenerated file is committed with the same bytes, and every committed file is regenerated (a
// file whose manifest line is gone is stale). tools/update_golden.sh keeps both true.
// To accept an intended change: tools/update_golden.sh, review `git status generated/`, commit.
#include "test_support.h"

#include "emit/backend.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace offsetgen {
namespace {
namespace fs = std::filesystem;

const fs::path kGolden = fs::path(test_support::source_dir()) / "generated";

// Runs every line of <golden>/MANIFEST into `dir`; returns the number of lines run.
int regenerate(const fs::path& golden, const std::string& dir) {
  std::ifstream manifest(golden / "MANIFEST");
  EXPECT_TRUE(manifest) << golden / "MANIFEST"
                        << " missing";
  int commands = 0;
  for (std::string line; std::getline(manifest, line);) {
    if (line.empty() || line[0] == '#') continue;
    auto r = testing::run_offsetgen("generate " + line + " --out-dir " + dir + " --quiet");
    EXPECT_EQ(r.exit_code, 0) << line << "\n" << r.output;
    ++commands;
  }
  return commands;
}

// File names in `dir`, MANIFEST left out.
std::set<std::string> outputs_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename() != "MANIFEST") names.insert(entry.path().filename().string());
  return names;
}

TEST(GoldenFiles, RegeneratingGivesTheCommittedBytes) {
  const std::string dir = testing::scratch_dir("golden");
  const int commands = regenerate(kGolden, dir);
  EXPECT_GE(commands, 32);
  const std::set<std::string> fresh = outputs_in(dir);
  // Every line says --lang all: one file per backend (.h, .glsl, .hlsl, .wgsl).
  EXPECT_EQ(fresh.size(), offsetgen::backends().size() * static_cast<std::size_t>(commands));
  for (const std::string& name : fresh) {
    const fs::path committed = kGolden / name;
    ASSERT_TRUE(fs::exists(committed)) << committed << " is not committed; run tools/update_golden.sh";
    EXPECT_TRUE(testing::read_file((fs::path(dir) / name).string()) == testing::read_file(committed.string()))
        << committed << " differs from what the generator produces now. If the change is intended, run "
        << "tools/update_golden.sh, review `git diff generated/`, and commit.";
  }
}

TEST(GoldenFiles, EveryCommittedFileIsProducedByTheManifest) {
  const std::string dir = testing::scratch_dir("golden_stale");
  regenerate(kGolden, dir);
  const std::set<std::string> fresh = outputs_in(dir);
  for (const std::string& name : outputs_in(kGolden)) {
    EXPECT_EQ(fresh.count(name), 1u) << "generated/" << name << " is committed but generated/MANIFEST does not "
                                     << "produce it: it is stale. tools/update_golden.sh removes it.";
  }
}

// tools/update_golden.sh on a copy of generated/ with a stale file, a changed file and a missing
// one: afterwards the copy holds exactly the manifest's outputs, byte for byte.
TEST(GoldenUpdate, RemovesStaleFilesAndRestoresTheManifestOutputs) {
  const fs::path copy = testing::scratch_dir("golden_update");
  for (const auto& entry : fs::directory_iterator(kGolden)) fs::copy_file(entry.path(), copy / entry.path().filename());
  std::ofstream(copy / "stale_o9.h") << "/* a golden file whose manifest line was removed */\n";
  std::ofstream(copy / "gyroid_o1.h", std::ios::app) << "/* edited */\n";
  fs::remove(copy / "diamond_o2.glsl");

  auto r = testing::run_command({"bash", test_support::source_dir() + "/tools/update_golden.sh",
                                 test_support::offsetgen_executable(), copy.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("removed " + (copy / "stale_o9.h").string()), std::string::npos) << r.output;
  const std::string fresh = testing::scratch_dir("golden_update_fresh");
  regenerate(kGolden, fresh);
  EXPECT_EQ(outputs_in(copy), outputs_in(fresh));
  for (const std::string& name : outputs_in(fresh))
    EXPECT_TRUE(testing::read_file((copy / name).string()) == testing::read_file(fresh + "/" + name)) << name;
  EXPECT_EQ(testing::read_file((copy / "MANIFEST").string()), testing::read_file((kGolden / "MANIFEST").string()));
}

}  // namespace
}  // namespace offsetgen
