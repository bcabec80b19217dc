// An interrupted `offsetgen slice` (Ctrl-C, a scheduler's SIGTERM) removes its unfinished archive,
// leaves an older file of the same name byte for byte as it was, and exits 128 + the signal.
#include "offsetgen_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

namespace offsetgen::slice {
namespace {

void interrupt_while_writing(const std::string& test, int signo, int expected_exit, const std::string& signal_name) {
  const std::string dir = test_support::scratch_dir(test), output = dir + "/keep.sl1";
  const std::string old = "an older run's archive, kept byte for byte\n";
  test_support::write_file(output, old);
  // 960 layers: still writing when the signal comes.
  test_support::BackgroundCommand run(
      {test_support::offsetgen_executable(), "slice", "--surface", "gyroid", "--density", "0.2", "--cells", "6",
       "--cell-size", "8", "--layer-height", "0.05", "-o", output},
      dir + "/log");
  const std::string temporary = test_support::wait_for_entry(dir, ".keep.sl1.tmp", run, 60);
  ASSERT_FALSE(temporary.empty()) << "no temporary appeared beside " << output << ":\n" << run.wait().output;
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  run.signal_group(signo);
  const test_support::CommandResult r = run.wait();
  EXPECT_EQ(r.exit_code, expected_exit) << r.output;
  EXPECT_EQ(r.output, "offsetgen slice: interrupted (" + signal_name + "): removed the unfinished " + temporary + "; " +
                          output + " is unchanged\n");
  EXPECT_TRUE(test_support::entries_starting_with(dir, ".keep.sl1.tmp").empty());
  EXPECT_EQ(test_support::read_file(output), old);
}

TEST(SliceInterrupt, SigintRemovesTheTemporaryKeepsTheOldFileAndExits130) {
  interrupt_while_writing("slice-interrupt-int", SIGINT, 130, "SIGINT");
}

TEST(SliceInterrupt, SigtermRemovesTheTemporaryKeepsTheOldFileAndExits143) {
  interrupt_while_writing("slice-interrupt-term", SIGTERM, 143, "SIGTERM");
}

}  // namespace
}  // namespace offsetgen::slice
