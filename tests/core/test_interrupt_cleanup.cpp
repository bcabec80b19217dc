// The SIGINT/SIGTERM handler (support/interrupt_cleanup.h), in a forked child that raises the signal at
// a chosen point: an open StreamedFile's temporary and a scratch directory are removed, an existing
// target keeps its bytes, one line says what was removed, the exit is 128 + the signal; a committed
// file is not touched, and a signal the parent ignored stays ignored.
#include "emit/file_writer.h"
#include "run/process.h"
#include "support/interrupt_cleanup.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>

namespace offsetgen {
namespace {
namespace fs = std::filesystem;
using test_support::entries_starting_with;

std::string scratch() {
  return testing::scratch_dir(std::string("interrupt_") +
                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

struct Child {
  int exit_code = -1;  // exit status, or 128 + the signal that killed it
  std::string stderr_text;
};

// Runs `body` in a child with its stderr in `dir`/stderr and SIGINT, SIGTERM at their defaults; the
// child exits 0 when `body` returns.
Child in_child(const std::string& dir, const std::function<void()>& body) {
  const std::string log = dir + "/stderr";
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    try {
      body();
    } catch (...) {
      ::_exit(99);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), testing::read_file(log)};
}

TEST(InterruptCleanup, SigtermWhileAStreamedFileIsOpenRemovesItsTemporaryKeepsTheOldFileAndExits143) {
  const std::string dir = scratch(), target = dir + "/part.stl";
  test_support::write_file(target, "old bytes");
  const Child c = in_child(dir, [&] {
    install_interrupt_cleanup("offsetgen test");
    StreamedFile file(target);
    file.append("half of the new bytes");
    std::raise(SIGTERM);
  });
  EXPECT_EQ(c.exit_code, 143) << c.stderr_text;
  EXPECT_TRUE(
      std::regex_match(c.stderr_text, std::regex("offsetgen test: interrupted \\(SIGTERM\\): removed the unfinished "
                                                 "\\.part\\.stl\\.tmp[A-Za-z0-9]{6}; " +
                                                 target + " is unchanged\n")))
      << c.stderr_text;
  EXPECT_TRUE(entries_starting_with(dir, ".part.stl.tmp").empty());
  EXPECT_EQ(testing::read_file(target), "old bytes");
}

TEST(InterruptCleanup, SigintBeforeANewFileIsCommittedSaysItWasNotWrittenAndExits130) {
  const std::string dir = scratch(), target = dir + "/new.ply";
  const Child c = in_child(dir, [&] {
    install_interrupt_cleanup("offsetgen test");
    StreamedFile file(target);
    file.append("ply");
    std::raise(SIGINT);
  });
  EXPECT_EQ(c.exit_code, 130) << c.stderr_text;
  EXPECT_TRUE(std::regex_match(c.stderr_text, std::regex("offsetgen test: interrupted \\(SIGINT\\): removed the "
                                                         "unfinished \\.new\\.ply\\.tmp\\w{6}; " +
                                                         target + " was not written\n")))
      << c.stderr_text;
  EXPECT_TRUE(entries_starting_with(dir, ".new.ply").empty());
  EXPECT_FALSE(fs::exists(target));
}

TEST(InterruptCleanup, ACommittedFileIsLeftAloneAndTheLineNamesNothingRemoved) {
  const std::string dir = scratch(), target = dir + "/done.stl";
  const Child c = in_child(dir, [&] {
    install_interrupt_cleanup("offsetgen test");
    StreamedFile file(target);
    file.append("all the new bytes");
    file.commit();
    std::raise(SIGTERM);
  });
  EXPECT_EQ(c.exit_code, 143) << c.stderr_text;
  EXPECT_EQ(c.stderr_text, "offsetgen test: interrupted (SIGTERM)\n");
  EXPECT_EQ(testing::read_file(target), "all the new bytes");
}

// What it holds goes too: files, a subdirectory, a symlink (the link, not what it points at).
TEST(InterruptCleanup, SigintRemovesAScratchDirectoryWithWhatItHoldsButNotWhatALinkPointsAt) {
  const std::string dir = scratch(), outside = dir + "/outside.txt";
  test_support::write_file(outside, "not ours to remove");
  fs::create_directory(dir + "/tmp");
  const Child c = in_child(dir, [&] {
    ::setenv("TMPDIR", (dir + "/tmp").c_str(), 1);
    install_interrupt_cleanup("offsetgen test");
    const run::ScratchDir scratch_dir("offsetgen-test");
    std::ofstream(scratch_dir.path() / "wrapper.c") << "int x;\n";
    fs::create_directories(scratch_dir.path() / "sub" / "deeper");
    std::ofstream(scratch_dir.path() / "sub" / "deeper" / "a.o") << "object";
    fs::create_symlink(outside, scratch_dir.path() / "link");
    fs::create_directory_symlink(dir, scratch_dir.path() / "dirlink");
    std::raise(SIGINT);
  });
  EXPECT_EQ(c.exit_code, 130) << c.stderr_text;
  EXPECT_TRUE(std::regex_match(c.stderr_text, std::regex("offsetgen test: interrupted \\(SIGINT\\): removed the "
                                                         "scratch directory " +
                                                         dir + "/tmp/offsetgen-test-\\w{6}\n")))
      << c.stderr_text;
  EXPECT_TRUE(fs::is_empty(dir + "/tmp"));
  EXPECT_EQ(testing::read_file(outside), "not ours to remove");
}

TEST(InterruptCleanup, ASigintTheParentIgnoredStaysIgnored) {
  const std::string dir = scratch(), target = dir + "/kept.stl";
  const Child c = in_child(dir, [&] {
    std::signal(SIGINT, SIG_IGN);  // as nohup or a script's background job leaves it
    install_interrupt_cleanup("offsetgen test");
    StreamedFile file(target);
    file.append("finished anyway");
    std::raise(SIGINT);
    file.commit();
  });
  EXPECT_EQ(c.exit_code, 0) << c.stderr_text;
  EXPECT_EQ(c.stderr_text, "");
  EXPECT_EQ(testing::read_file(target), "finished anyway");
}

}  // namespace
}  // namespace offsetgen
