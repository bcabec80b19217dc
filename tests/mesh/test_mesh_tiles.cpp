// `offsetgen mesh` in tiles (src/mesh/tiles.h): the tiles together give the untiled triangles, the
// streamed STL is one clean solid, a run split with --tile-range and joined with --merge gives the
// single run's bytes, and bad tile options exit 2 writing nothing.
#include "mesh_test_support.h"
#include "run/process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace offsetgen::mesh::testing {
namespace {

namespace fs = std::filesystem;

using Facet = std::array<std::array<float, 3>, 3>;

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
}

// The facets as a sorted list, each rotated to start at its smallest corner (orientation kept).
std::vector<Facet> facet_set(const std::string& stl) {
  std::vector<Facet> facets = read_stl(stl);
  for (Facet& f : facets) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(facets.begin(), facets.end());
  return facets;
}

const std::vector<std::string> kBlock = {"mesh", "--surface",   "gyroid", "--thickness",  "0.1", "--cells",
                                         "3",    "--cell-size", "8",      "--resolution", "40",  "--min-piece",
                                         "0"};

CliRun mesh_with(const std::vector<std::string>& base, const std::vector<std::string>& extra) {
  std::vector<std::string> args = base;
  args.insert(args.end(), extra.begin(), extra.end());
  return run_offsetgen(args);
}

TEST(MeshTiles, TiledAndUntiledBlocksGiveTheSameTriangleSet) {
  const std::string dir = scratch_dir("tiles-same");
  CliRun whole = mesh_with(kBlock, {"--tile", "0", "-o", dir + "/whole.stl"});
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  CliRun tiled = mesh_with(kBlock, {"--tile", "48", "-o", dir + "/tiled.stl"});
  ASSERT_EQ(tiled.exit_code, 0) << tiled.output;
  EXPECT_NE(tiled.output.find("tiles:      27 of 48 voxels a side; binary STL written tile by tile"), std::string::npos)
      << tiled.output;
  const std::vector<Facet> a = facet_set(dir + "/whole.stl"), b = facet_set(dir + "/tiled.stl");
  EXPECT_EQ(a.size(), b.size());
  EXPECT_TRUE(a == b) << "the tiles' triangles differ from the untiled run's";
}

// A 3x3x3 gyroid block in tiles of 48 voxels, with `extra` options: admesh finds one closed,
// consistently oriented part.
void expect_one_clean_solid(const std::string& name, const std::vector<std::string>& extra) {
  const std::string dir = scratch_dir(name);
  std::vector<std::string> args = {"mesh",        "--surface", "gyroid",       "--thickness", "0.1",    "--cells", "3",
                                   "--cell-size", "8",         "--resolution", "40",          "--tile", "48"};
  args.insert(args.end(), extra.begin(), extra.end());
  args.insert(args.end(), {"-o", dir + "/part.stl"});
  CliRun r = run_offsetgen(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string raw;
  auto report = admesh_report(dir + "/part.stl", &raw);
  EXPECT_EQ(report["facets added"], 0) << raw;
  EXPECT_EQ(report["backwards edges"], 0) << raw;
  EXPECT_EQ(report["disconnected facets"], 0) << raw;
  EXPECT_EQ(report["parts"], 1) << raw;
  EXPECT_GT(stl_volume(read_stl(dir + "/part.stl")), 0);
}

TEST(MeshTiles, AStreamedBlockIsOneCleanSolid) { expect_one_clean_solid("tiles-clean", {}); }

// Merged polygons (--adaptivity) meet the tile across each seam: the blocks on both sides of a seam
// are left unmerged, so both tiles compute the seam's points alike.
TEST(MeshTiles, AnAdaptiveStreamedBlockIsOneCleanSolid) {
  expect_one_clean_solid("tiles-adaptive", {"--adaptivity", "0.3"});
}

TEST(MeshTiles, SharesJoinedWithMergeGiveTheSingleRunsBytes) {
  const std::string dir = scratch_dir("tiles-merge");
  ASSERT_EQ(mesh_with(kBlock, {"--tile", "48", "-o", dir + "/single.stl"}).exit_code, 0);
  std::vector<std::string> merge = {"mesh", "--merge"};
  for (int i = 0; i < 4; ++i) {
    const std::string part = dir + "/part" + std::to_string(i) + ".stl";
    CliRun r = mesh_with(kBlock, {"--tile", "48", "--tile-range", std::to_string(i) + "/4", "-o", part});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    merge.push_back(part);
  }
  merge.insert(merge.end(), {"-o", dir + "/merged.stl"});
  CliRun r = run_offsetgen(merge);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("from 4 parts"), std::string::npos) << r.output;
  EXPECT_TRUE(read_bytes(dir + "/single.stl") == read_bytes(dir + "/merged.stl"));
}

// PLY is streamed too, its tiles' seam points welded by position: the untiled mesh's counts.
TEST(MeshTiles, PlyInTilesIsWeldedToTheUntiledCounts) {
  const std::string dir = scratch_dir("tiles-ply");
  CliRun whole = mesh_with(kBlock, {"--tile", "0", "-o", dir + "/whole.ply"});
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  CliRun tiled = mesh_with(kBlock, {"--tile", "48", "-o", dir + "/tiled.ply"});
  ASSERT_EQ(tiled.exit_code, 0) << tiled.output;
  EXPECT_NE(tiled.output.find("binary PLY written tile by tile"), std::string::npos) << tiled.output;
  auto counts = [](const std::string& summary) {
    const size_t at = summary.find("\n  mesh:");
    return summary.substr(at, summary.find("vertices", at) - at);
  };
  EXPECT_EQ(counts(whole.output), counts(tiled.output));
  // The same bytes but for the header's counts, which the streamed file writes with 10 digits.
  EXPECT_EQ(fs::file_size(dir + "/whole.ply") + 2 * 10 - std::to_string(843264).size() - std::to_string(421238).size(),
            fs::file_size(dir + "/tiled.ply"));
}

TEST(MeshTiles, BadTileOptionsExitWith2AndWriteNothing) {
  const std::string dir = scratch_dir("tiles-bad");
  const std::string out = dir + "/part.stl";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--tile", "12", "-o", out}, "multiple of 8"},
      {{"--tile", "-8", "-o", out}, "multiple of 8"},
      {{"--tile-range", "4/4", "-o", out}, "0 <= I < N"},
      {{"--tile-range", "1-4", "-o", out}, "I/N"},
      {{"--tile-range", "0/2", "-o", dir + "/part.ply"}, "partial binary STL"},
  };
  for (const auto& [extra, expected] : cases) {
    CliRun r = mesh_with(kBlock, extra);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << "expected '" << expected << "' in: " << r.output;
  }
  EXPECT_FALSE(fs::exists(out));
  // --merge refuses parts of different runs and files that are no parts.
  ASSERT_EQ(mesh_with(kBlock, {"--tile", "48", "--tile-range", "0/2", "-o", dir + "/a0.stl"}).exit_code, 0);
  std::vector<std::string> other = kBlock;
  other[4] = "0.12";
  ASSERT_EQ(mesh_with(other, {"--tile", "48", "--tile-range", "1/2", "-o", dir + "/b1.stl"}).exit_code, 0);
  std::ofstream(dir + "/junk.stl") << "solid junk\nendsolid\n";
  CliRun r = run_offsetgen({"mesh", "--merge", dir + "/a0.stl", dir + "/b1.stl", "-o", out});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("another run"), std::string::npos) << r.output;
  r = run_offsetgen({"mesh", "--merge", dir + "/a0.stl", dir + "/junk.stl", "-o", out});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not a binary STL part"), std::string::npos) << r.output;
  r = run_offsetgen({"mesh", "--merge", dir + "/a0.stl", "-o", dir + "/a0.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// Out of memory is an error that names the stage and what to lower, exit 3, with nothing left behind,
// never an abort: an untiled 8^3 block (2.4 GB as one grid) under a 1 GB address-space limit.
TEST(MeshTiles, OutOfMemoryExitsWith3NamingTheStageAndLeavesNoFile) {
  const std::string dir = scratch_dir("tiles-oom");
  const std::string command = "ulimit -v 1000000; exec " + std::string(OFFSETGEN_EXE) +
                              " mesh --surface gyroid --thickness 0.1 --cells 8 --cell-size 8 --resolution 40 "
                              "--tile 0 -o " +
                              dir + "/part.stl";
  const run::ProcessResult r = run::run_process({"bash", "-c", command});
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("out of memory while"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--tile 256"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir)) << "a file was left in " << dir;
}

}  // namespace
}  // namespace offsetgen::mesh::testing
