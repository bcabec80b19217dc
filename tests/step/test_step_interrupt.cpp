// SIGTERM (Slurm at a job's time limit) or Ctrl-C ends `offsetgen step` leaving nothing behind: the
// STEP text is written to a scratch directory under $TMPDIR, checked, measured, and only then written
// to -o (docs/step.md); a signal in between removes the scratch directory, keeps an existing -o byte
// for byte, says so in one line and exits 143 or 130 (support/interrupt_cleanup.h).
#include "cli/command_line.h"
#include "offsetgen_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

namespace offsetgen {
namespace {
using test_support::BackgroundCommand;
using test_support::entries_starting_with;

TEST(StepInterrupt, SigtermWhileMeasuringRemovesTheScratchDirectoryKeepsTheOldFileAndExits143) {
  const std::string dir = test_support::scratch_dir("step_interrupt"), tmp = dir + "/tmp", output = dir + "/p.step";
  const std::string old = "ISO-10303-21;\nan older run's solid, kept byte for byte\nEND-ISO-10303-21;\n";
  std::filesystem::create_directory(tmp);
  test_support::write_file(output, old);
  // Seconds of fitting, then the STEP text in the scratch directory while the solid is measured.
  BackgroundCommand run({OFFSETGEN_EXE, "step", "--surface", "gyroid", "--thickness", "0.1", "--cells", "1",
                         "--cell-size", "10", "--tolerance", "0.001", "--quiet", "-o", output},
                        dir + "/log", {"TMPDIR=" + tmp});
  const std::string scratch = test_support::wait_for_entry(tmp, "offsetgen-step-", run, 120);
  ASSERT_FALSE(scratch.empty()) << "no scratch directory appeared in " << tmp << ":\n" << run.wait().output;
  // Registered a few system calls after its creation (support/interrupt_cleanup.cpp): a moment later.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  run.signal_group(SIGTERM);
  const test_support::CommandResult r = run.wait();
  EXPECT_EQ(r.exit_code, kExitTerminated) << r.output;
  EXPECT_EQ(r.output,
            "offsetgen step: interrupted (SIGTERM): removed the scratch directory " + tmp + "/" + scratch + "\n");
  EXPECT_TRUE(entries_starting_with(tmp, "offsetgen-").empty());
  EXPECT_TRUE(entries_starting_with(dir, ".p.step.tmp").empty());
  EXPECT_EQ(test_support::read_file(output), old);
}

}  // namespace
}  // namespace offsetgen
