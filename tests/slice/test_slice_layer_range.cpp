// `offsetgen slice --layer-range I/N` and `--merge` (docs/slice.md, "Many machines"): the shares of a
// small block, merged in order, are the single run's bytes (binary and ASCII CLI, SVG, SL1); a bad
// range and a bad merge (shares of another request, missing, doubled, out of order, damaged, the wrong
// extension) exit 2 and write nothing.
#include "offsetgen_test_support.h"
#include "slice_cli_cases.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;
using test_support::read_file;
using test_support::run_offsetgen;
using test_support::scratch_dir;

std::vector<std::string> block(const std::vector<std::string>& extra) { return test::small_block(extra); }

// Shares 0/3, 1/3, 2/3 merged into dir/merged/part.EXT equal the single run's dir/part.EXT.
void expect_merged_shares_equal_the_single_run(const std::string& ext, const std::vector<std::string>& options) {
  const std::string dir = scratch_dir("slice-layer-range-" + ext + (options.empty() ? "" : "-ascii"));
  fs::create_directories(dir + "/merged");
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.end(), options.begin(), options.end());
    return block(extra);
  };
  const std::string single = dir + "/part." + ext;
  ASSERT_EQ(run_offsetgen(with({"-o", single})).exit_code, 0);
  const std::string merged = dir + "/merged/part." + ext;
  const auto r = test::slice_shares_and_merge(with, dir, 3, ext, merged);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string a = read_file(single);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == read_file(merged)) << ext << ": the merged shares differ from the single run";
}

TEST(SliceLayerRange, BinaryCliSharesMergeToTheSingleRunsBytes) {
  expect_merged_shares_equal_the_single_run("cli", {});
}
TEST(SliceLayerRange, AsciiCliSharesMergeToTheSingleRunsBytes) {
  expect_merged_shares_equal_the_single_run("cli", {"--cli-ascii"});
}
TEST(SliceLayerRange, SvgSharesMergeToTheSingleRunsBytes) { expect_merged_shares_equal_the_single_run("svg", {}); }
TEST(SliceLayerRange, Sl1SharesMergeToTheSingleRunsBytes) { expect_merged_shares_equal_the_single_run("sl1", {}); }

TEST(SliceLayerRange, BadRangeExits2AndWritesNothing) {
  const std::string dir = scratch_dir("slice-layer-range-bad");
  const std::vector<test::RefusedCase> cases = {
      {{"--layer-range", "3/3", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "4/3", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "1/0", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "-1/3", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "one/3", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "1/3x", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "2", "-o", dir + "/a.cli.part"}, "expected I/N"},
      {{"--layer-range", "0/3", "-o", dir + "/a.cli"}, "NAME.EXT.part"},
      {{"--layer-range", "0/3", "-o", dir + "/a.stl.part"}, "unknown extension"},
  };
  test::expect_refused(cases, block, dir);
}

TEST(SliceLayerRange, BadMergeExits2AndWritesNothing) {
  const std::string dir = scratch_dir("slice-layer-range-bad-merge");
  const std::string s0 = dir + "/s0.cli.part", s1 = dir + "/s1.cli.part", s2 = dir + "/s2.cli.part";
  const std::string other = dir + "/other1.cli.part", whole = dir + "/whole.cli", cut = dir + "/cut1.cli.part";
  for (const auto& [range, path] :
       std::vector<std::pair<std::string, std::string>>{{"0/3", s0}, {"1/3", s1}, {"2/3", s2}}) {
    ASSERT_EQ(run_offsetgen(block({"--layer-range", range, "-o", path})).exit_code, 0);
  }
  ASSERT_EQ(run_offsetgen(block({"--tolerance", "0.01", "--layer-range", "1/3", "-o", other})).exit_code, 0);
  ASSERT_EQ(run_offsetgen(block({"-o", whole})).exit_code, 0);
  {
    const std::string bytes = read_file(s1);
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 100);
  }
  const std::string out = dir + "/out/merged.cli";
  fs::create_directories(dir + "/out");
  const std::vector<test::RefusedCase> cases = {
      {{s1, s0, s2}, "give the shares in order"},
      {{s0, s1}, "give all 3 shares"},
      {{s0, s1, s2, s2}, "the same file"},
      {{s0, s0, s2}, "the same file"},
      {{s0, other, s2}, "another run"},
      {{s0, whole, s2}, "is not a share"},
      {{s0, cut, s2}, "damaged"},
  };
  for (const auto& [parts, reason] : cases) {
    std::vector<std::string> args = {"slice", "--merge"};
    args.insert(args.end(), parts.begin(), parts.end());
    args.insert(args.end(), {"-o", out});
    const auto r = run_offsetgen(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
  }
  const auto r = run_offsetgen({"slice", "--merge", s0, s1, s2, "-o", dir + "/out/merged.sl1"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("another format"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir + "/out")) << "a refused merge left a file";
}

}  // namespace
}  // namespace offsetgen::slice
