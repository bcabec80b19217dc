// What the slice command tests share: a small block's command line, and requests that must be refused.
#pragma once

#include "offsetgen_test_support.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace offsetgen::slice::test {

// `slice -q`, 1 gyroid cell of 4 mm at density 0.2, 0.2 mm layers (20 layers), then `extra`.
inline std::vector<std::string> small_block(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"slice",   "-q", "--surface",   "gyroid", "--density",      "0.2",
                                   "--cells", "1",  "--cell-size", "4",      "--layer-height", "0.2"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// Extra arguments, and what the refusal's message must name.
using RefusedCase = std::pair<std::vector<std::string>, std::string>;
using CommandLine = std::function<std::vector<std::string>(const std::vector<std::string>& extra)>;

// Each case's command exits 2 naming its reason, and `dir` (where their -o point) stays empty.
inline void expect_refused(const std::vector<RefusedCase>& cases, const CommandLine& command, const std::string& dir) {
  for (const auto& [extra, reason] : cases) {
    const auto r = test_support::run_offsetgen(command(extra));
    EXPECT_EQ(r.exit_code, 2) << fmt::format("{}", fmt::join(extra, " ")) << "\n" << r.output;
    EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a refused run wrote something";
}

// Slices shares 0/N to N-1/N of `command` into dir/sI.EXT.part and joins them with --merge into
// `merged`; the merge's result (a share that fails is a test failure, and the merge is not run).
inline test_support::CommandResult slice_shares_and_merge(const CommandLine& command, const std::string& dir, int count,
                                                          const std::string& ext, const std::string& merged) {
  std::vector<std::string> merge = {"slice", "-q", "--merge"};
  for (int i = 0; i < count; ++i) {
    const std::string share = fmt::format("{}/s{}.{}.part", dir, i, ext);
    const auto r = test_support::run_offsetgen(command({"--layer-range", fmt::format("{}/{}", i, count), "-o", share}));
    if (r.exit_code != 0) {
      ADD_FAILURE() << "share " << i << "/" << count << " exited " << r.exit_code << "\n" << r.output;
      return r;
    }
    merge.push_back(share);
  }
  merge.insert(merge.end(), {"-o", merged});
  return test_support::run_offsetgen(merge);
}

}  // namespace offsetgen::slice::test
