// Writing outputs loses nothing: two outputs never share a file; devices, FIFOs and directories are
// refused by name; symlinks are written through; mode, owner and hard links survive; stdout is `-o -`
// only (the rules of emit/file_writer.h); a missing --out-dir is created, a file in its place refused.
#include "emit/file_writer.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace offsetgen {
namespace {
namespace fs = std::filesystem;
using testing::run_offsetgen;

std::string scratch() {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return testing::scratch_dir("file_writing_" + name);
}

void write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

struct stat stat_of(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return st;
}

size_t entries(const std::string& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(FileWriting, LangAllWithAGlslNameIsRefusedInsteadOfWritingBothToOneFile) {
  const std::string dir = scratch();
  const auto r = run_offsetgen("generate --surface gyroid --order 1 --lang all -o " + dir + "/foo.glsl");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("both to"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("-o " + dir + "/foo.h"), std::string::npos) << r.output;
  EXPECT_EQ(entries(dir), 0u);
}

TEST(FileWriting, TwoOutputsThatAreOneFileThroughASymlinkAreRefused) {
  const std::string dir = scratch();
  write(dir + "/a.h", "precious");
  fs::create_symlink("a.h", dir + "/a.glsl");
  const auto r = run_offsetgen("generate --surface gyroid --order 1 --lang all -o " + dir + "/a.h");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("same file"), std::string::npos) << r.output;
  EXPECT_EQ(testing::read_file(dir + "/a.h"), "precious");
}

TEST(FileWriting, DeviceNodesAreRefusedAndLeftAlone) {
  const struct stat before = stat_of("/dev/null");
  const auto r = run_offsetgen("generate --surface gyroid --order 1 -o /dev/null");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("character device"), std::string::npos) << r.output;
  const struct stat after = stat_of("/dev/null");
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(before.st_ino, after.st_ino);
}

TEST(FileWriting, DescriptorPathsPointToDashO) {
  for (const char* path : {"/dev/stdout", "/dev/stderr", "/proc/self/fd/1"}) {
    const auto r = run_offsetgen(std::string("generate --surface gyroid --order 1 -o ") + path);
    EXPECT_EQ(r.exit_code, 2) << path << ": " << r.output;
    EXPECT_NE(r.output.find("-o -"), std::string::npos) << r.output;
  }
  const auto out = run_offsetgen("generate --surface gyroid --order 1 -o -");
  EXPECT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("static inline double gyroid_o1_offset"), std::string::npos);
}

TEST(FileWriting, AFifoIsRefusedAtOnceInsteadOfBlocking) {
  const std::string dir = scratch();
  ASSERT_EQ(::mkfifo((dir + "/pipe.h").c_str(), 0644), 0);
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_offsetgen("generate --surface gyroid --order 1 -o " + dir + "/pipe.h");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("FIFO"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_fifo(dir + "/pipe.h"));
}

TEST(FileWriting, ADirectoryIsRefusedByName) {
  const std::string dir = scratch();
  fs::create_directory(dir + "/sub.h");
  const auto r = run_offsetgen("generate --surface gyroid --order 1 -o " + dir + "/sub.h");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is a directory"), std::string::npos) << r.output;
}

// As code generators do: a missing --out-dir is made, parents included.
TEST(FileWriting, OutDirThatDoesNotExistIsCreatedWithItsParents) {
  const std::string dir = scratch();
  const auto r = run_offsetgen("generate --surface gyroid --order 1 --lang c,glsl --out-dir " + dir + "/a/b/gen");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(testing::read_file(dir + "/a/b/gen/gyroid_o1.h").find("gyroid_o1_offset"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir + "/a/b/gen/gyroid_o1.glsl"));
  // Spelled with a trailing slash, and again once it exists.
  for (int run = 0; run < 2; ++run) {
    const auto slash = run_offsetgen("generate --surface gyroid --order 1 --out-dir " + dir + "/gen/");
    EXPECT_EQ(slash.exit_code, 0) << slash.output;
    EXPECT_TRUE(fs::is_regular_file(dir + "/gen/gyroid_o1.h"));
  }
}

TEST(FileWriting, OutDirThatIsAFileIsRefusedSayingSo) {
  const std::string dir = scratch();
  write(dir + "/gen", "precious");
  // The file itself, and a directory to be made below it: both name the file.
  for (const std::string& out_dir : {dir + "/gen", dir + "/gen/", dir + "/gen/sub"}) {
    const auto r = run_offsetgen("generate --surface gyroid --order 1 --out-dir " + out_dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("'" + dir + "/gen' exists and is not a directory"), std::string::npos) << r.output;
  }
  EXPECT_EQ(testing::read_file(dir + "/gen"), "precious");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(FileWriting, OutDirThroughADanglingSymlinkIsRefusedSayingSo) {
  const std::string dir = scratch();
  fs::create_symlink("nowhere", dir + "/gen");
  const auto r = run_offsetgen("generate --surface gyroid --order 1 --out-dir " + dir + "/gen");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("symbolic link to a missing path"), std::string::npos) << r.output;
  EXPECT_EQ(entries(dir), 1u);
}

// The directory is made only right before the files are written: a request that fails makes nothing.
TEST(FileWriting, OutDirIsNotCreatedWhenTheRequestIsBad) {
  const std::string dir = scratch();
  const std::string out = " --out-dir " + dir + "/new/gen";
  for (const std::string& args :
       {"--surface gyroide" + out, "--surface gyroid --order 0" + out, "--expr 'cos(2*x' --name s" + out,
        "--surface gyroid --name class --lang c,numpy" + out, "--surface gyroid -o " + dir + "/x.h" + out}) {
    const auto r = run_offsetgen("generate " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(entries(dir), 0u) << args;
  }
}

TEST(FileWriting, EmptyOutputNamesAreRefused) {
  const std::string dir = scratch();
  for (const char* option : {"-o ''", "--out-dir ''"}) {
    const auto r = run_offsetgen(std::string("generate --surface gyroid --order 1 ") + option);
    EXPECT_EQ(r.exit_code, 2) << option << ": " << r.output;
    EXPECT_NE(r.output.find("empty"), std::string::npos) << r.output;
  }
  EXPECT_EQ(run_offsetgen("generate --surface gyroid --order 1 --output=").exit_code, 2);
  EXPECT_FALSE(fs::exists("gyroid_o1.h"));  // the working directory of the test run
}

TEST(FileWriting, ASymlinkIsWrittenThroughAndStaysALink) {
  const std::string dir = scratch();
  fs::create_directory(dir + "/real");
  write(dir + "/real/g.h", "old");
  fs::create_symlink("real/g.h", dir + "/link.h");
  ASSERT_TRUE(write_file_if_changed(dir + "/link.h", "new"));
  EXPECT_TRUE(fs::is_symlink(dir + "/link.h"));
  EXPECT_EQ(testing::read_file(dir + "/real/g.h"), "new");
  // A dangling link gets its target created.
  fs::create_symlink("real/later.h", dir + "/dangling.h");
  ASSERT_TRUE(write_file_if_changed(dir + "/dangling.h", "made"));
  EXPECT_TRUE(fs::is_symlink(dir + "/dangling.h"));
  EXPECT_EQ(testing::read_file(dir + "/real/later.h"), "made");
  // Through the CLI, too.
  const auto r = run_offsetgen("generate --surface gyroid --order 1 -o " + dir + "/link.h");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(dir + "/link.h"));
  EXPECT_NE(testing::read_file(dir + "/real/g.h").find("gyroid_o1_offset"), std::string::npos);
}

TEST(FileWriting, AnExistingFileKeepsItsModeOwnerAndHardLinks) {
  const std::string dir = scratch();
  const std::string file = dir + "/private.h";
  write(file, "old");
  ASSERT_EQ(::chmod(file.c_str(), 0600), 0);
  const bool root = ::geteuid() == 0;
  const uid_t owner = root ? 65534 : ::geteuid();  // nobody, where we may give files away
  const gid_t group = root ? 65534 : ::getegid();
  if (root) {
    ASSERT_EQ(::chown(file.c_str(), owner, group), 0);
  }
  ASSERT_TRUE(write_file_if_changed(file, "new"));
  struct stat st = stat_of(file);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
  EXPECT_EQ(st.st_uid, owner);
  EXPECT_EQ(st.st_gid, group);
  EXPECT_EQ(testing::read_file(file), "new");

  fs::create_hard_link(file, dir + "/other_name.h");
  ASSERT_TRUE(write_file_if_changed(file, "newer"));
  EXPECT_EQ(testing::read_file(dir + "/other_name.h"), "newer");
  EXPECT_TRUE(fs::equivalent(file, dir + "/other_name.h"));
  EXPECT_EQ(entries(dir), 2u) << "a temporary file was left behind";
}

TEST(FileWriting, ANewFileGetsTheUmaskNotMkstempsPrivateMode) {
  const std::string dir = scratch();
  const mode_t saved = ::umask(022);
  const bool written = write_file_if_changed(dir + "/fresh.h", "text");
  ::umask(027);
  const bool second = write_file_if_changed(dir + "/group.h", "text");
  ::umask(saved);
  ASSERT_TRUE(written && second);
  EXPECT_EQ(stat_of(dir + "/fresh.h").st_mode & 07777, 0644u);
  EXPECT_EQ(stat_of(dir + "/group.h").st_mode & 07777, 0640u);
}

TEST(FileWriting, UnchangedBytesLeaveTheFileAlone) {
  const std::string dir = scratch();
  write(dir + "/same.h", "same");
  const auto before = fs::last_write_time(dir + "/same.h") - std::chrono::hours(1);
  fs::last_write_time(dir + "/same.h", before);
  EXPECT_FALSE(write_file_if_changed(dir + "/same.h", "same"));
  EXPECT_EQ(fs::last_write_time(dir + "/same.h"), before);
}

}  // namespace
}  // namespace offsetgen
