// `offsetgen mesh --network`: the network (strut) solid phi(p, h) < 0 instead of the sheet, as a block
// and inside a part's skin (issue 39): closed parts, and the block's volume fraction is the requested
// network density of the closed form (docs/density.md).
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace offsetgen::mesh::testing {
namespace {

struct NetworkCase {
  std::string surface;
};
void PrintTo(const NetworkCase& c, std::ostream* os) { *os << c.surface; }

class MeshNetwork : public ::testing::TestWithParam<NetworkCase> {};

TEST_P(MeshNetwork, ABlockIsOneCleanSolidWithTheRequestedDensity) {
  const std::string dir = scratch_dir("network-block-" + GetParam().surface);
  const std::string out = dir + "/net.stl";
  const CliRun r = run_offsetgen({"mesh", "--surface", GetParam().surface, "--network", "--density", "0.3", "--cells",
                                  "3", "--cell-size", "8", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_admesh_clean(out, 0);
  // The block's volume over the box: 0.3 of the closed form, within the mesher's error.
  const double fraction = stl_volume(read_stl(out)) / (24.0 * 24 * 24);
  EXPECT_NEAR(fraction, 0.3, 0.005) << r.output;
  EXPECT_NE(r.output.find("network solid phi(p, h) < 0, h -0.0"), std::string::npos) << r.output;
}

TEST_P(MeshNetwork, APartWithASkinIsClosedAndItsSkinWhole) {
  const std::string dir = scratch_dir("network-part-" + GetParam().surface);
  write_stl(sphere(12, {14, 14, 14}, 4), dir + "/sphere.stl");
  const std::string out = dir + "/part.stl";
  const CliRun r =
      run_offsetgen({"mesh", "--surface", GetParam().surface, "--network", "--density", "0.3", "--body",
                     dir + "/sphere.stl", "--skin", "1.2", "--cell-size", "6", "--voxel", "0.2", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_admesh_clean(out, summary_number(r.output, " mm over "));
  EXPECT_GE(summary_number(r.output, "measured: thinnest "), 1.2 - 0.2) << r.output;
  EXPECT_NEAR(summary_number(r.output, "density:    lattice "), 0.3, 0.02) << r.output;
}

INSTANTIATE_TEST_SUITE_P(Surfaces, MeshNetwork, ::testing::Values(NetworkCase{"gyroid"}, NetworkCase{"diamond"}),
                         [](const ::testing::TestParamInfo<NetworkCase>& p) { return p.param.surface; });

// Offsets the closed form does not cover, and a graded density (which grades sheets), are refused.
TEST(MeshNetworkInput, OutOfRangeNetworksExitWith2AndWriteNothing) {
  const std::string dir = scratch_dir("network-bad");
  const std::string out = dir + "/bad.stl";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--density", "0.99"}, "outside [0.0358, 0.9642]"},
      {{"--thickness", "0.3"}, "beyond gyroid's curvature limit"},
      {{"--thickness", "0.1 + 0.2*z"}, "beyond gyroid's curvature limit"},
      {{"--density-field", "0.3"}, "--density-field grades a sheet"},
  };
  for (const auto& [wall, words] : cases) {
    std::vector<std::string> args = {"mesh", "--surface", "gyroid", "--network", "--cells", "1", "-o", out};
    args.insert(args.end(), wall.begin(), wall.end());
    const CliRun r = run_offsetgen(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(words), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

}  // namespace
}  // namespace offsetgen::mesh::testing
