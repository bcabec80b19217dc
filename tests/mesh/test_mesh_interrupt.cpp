// Ctrl-C (SIGINT) or a scheduler's SIGTERM (Slurm at a job's time limit) ends `offsetgen mesh` leaving
// nothing behind: the unfinished temporary beside the output is removed, an existing output keeps its
// bytes, one line on stderr says so, and the exit status is 130 or 143 (support/interrupt_cleanup.h).
// The signal goes to the run's process group, as a terminal's Ctrl-C and Slurm's SIGTERM do.
#include "cli/command_line.h"
#include "mesh_test_support.h"
#include "offsetgen_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace offsetgen::mesh::testing {
namespace {
using test_support::BackgroundCommand;
using test_support::entries_starting_with;
using test_support::wait_for_entry;

// 800 MB of STL written tile by tile: the temporary lives for seconds.
const std::vector<std::string> kLargePart = {"--surface", "gyroid",    "--cells", "6",      "--cell-size",
                                             "8",         "--density", "0.2",     "--quiet"};

// The registry learns of a temporary a few system calls after it is created: a signal sent at once on
// seeing it could land in between (support/interrupt_cleanup.cpp). A moment later it is registered.
void settle() { std::this_thread::sleep_for(std::chrono::milliseconds(50)); }

// Removes a test's directory however the test ends: a run not stopped in time writes 800 MB there.
struct RemovedAtEnd {
  std::string dir;
  ~RemovedAtEnd() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

std::string old_output() {
  std::string bytes = "solid an older run's part, kept byte for byte\n";
  for (int i = 0; i < 256; ++i) bytes += char(i);
  return bytes;
}

// Starts `offsetgen mesh ARGS -o DIR/NAME` over an older DIR/NAME, sends `signo` once the temporary
// appears beside it, and checks what is left.
void interrupt_while_writing(const std::string& test, std::vector<std::string> args, const std::string& name, int signo,
                             int expected_exit, const std::string& signal_name) {
  const std::string dir = scratch_dir(test), output = dir + "/" + name, old = old_output();
  const RemovedAtEnd cleanup{dir};
  test_support::write_file(output, old);
  args.insert(args.begin(), {OFFSETGEN_EXE, "mesh"});
  args.insert(args.end(), {"-o", output});
  BackgroundCommand run(args, dir + "/log");
  const std::string temporary = wait_for_entry(dir, "." + name + ".tmp", run, 60);
  ASSERT_FALSE(temporary.empty()) << "no temporary appeared beside " << output << ":\n" << run.wait().output;
  settle();
  run.signal_group(signo);
  const test_support::CommandResult r = run.wait();
  EXPECT_EQ(r.exit_code, expected_exit) << r.output;
  EXPECT_EQ(r.output, "offsetgen mesh: interrupted (" + signal_name + "): removed the unfinished " + temporary + "; " +
                          output + " is unchanged\n");
  EXPECT_TRUE(entries_starting_with(dir, "." + name + ".tmp").empty());
  EXPECT_EQ(test_support::read_file(output), old);
}

TEST(MeshInterrupt, SigintRemovesTheTemporaryKeepsTheOldFileAndExits130) {
  interrupt_while_writing("interrupt_sigint", kLargePart, "keep.stl", SIGINT, kExitInterrupted, "SIGINT");
}

TEST(MeshInterrupt, SigtermRemovesTheTemporaryKeepsTheOldFileAndExits143) {
  interrupt_while_writing("interrupt_sigterm", kLargePart, "keep.stl", SIGTERM, kExitTerminated, "SIGTERM");
}

TEST(MeshInterrupt, SigtermToATileRangeShareRemovesItsTemporaryAndKeepsTheOldPart) {
  std::vector<std::string> args = kLargePart;
  args.insert(args.end(), {"--tile-range", "1/2"});
  interrupt_while_writing("interrupt_share", args, "part1.stl", SIGTERM, kExitTerminated, "SIGTERM");
}

// The wall's functions are compiled in a scratch directory under $TMPDIR for a second or more.
TEST(MeshInterrupt, SigintDuringTheCompileRemovesTheScratchDirectoryAndWritesNothing) {
  const std::string dir = scratch_dir("interrupt_compile"), tmp = dir + "/tmp", output = dir + "/new.stl";
  const RemovedAtEnd cleanup{dir};
  std::vector<std::string> args = {OFFSETGEN_EXE, "mesh"};
  args.insert(args.end(), kLargePart.begin(), kLargePart.end());
  args.insert(args.end(), {"-o", output});
  std::filesystem::create_directory(tmp);
  BackgroundCommand run(args, dir + "/log", {"TMPDIR=" + tmp});
  const std::string scratch = wait_for_entry(tmp, "offsetgen-mesh-", run, 60);
  ASSERT_FALSE(scratch.empty()) << "no scratch directory appeared in " << tmp << ":\n" << run.wait().output;
  settle();
  run.signal_group(SIGINT);
  const test_support::CommandResult r = run.wait();
  EXPECT_EQ(r.exit_code, kExitInterrupted) << r.output;
  EXPECT_EQ(r.output,
            "offsetgen mesh: interrupted (SIGINT): removed the scratch directory " + tmp + "/" + scratch + "\n");
  EXPECT_TRUE(entries_starting_with(tmp, "offsetgen-").empty());
  EXPECT_TRUE(entries_starting_with(dir, ".new.stl").empty());
  EXPECT_TRUE(entries_starting_with(dir, "new.stl").empty());
}

}  // namespace
}  // namespace offsetgen::mesh::testing
