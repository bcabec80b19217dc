// `offsetgen slice` as a user runs it, its files read back by code that is not the writer: a CLI
// reader written here (binary long records and ASCII) checks the header's layer count, closed
// polylines, dir against the signed area, and every vertex off the box's sides on the wall's zero set
// (the emitted functions evaluated there: 1e-6 mm in ASCII, plus float32 rounding in binary); the
// same bytes twice and on 1 or 2 threads; bad input exits 2 and leaves no file; the SL1 archive
// opened with Python's zipfile (its keys, one PNG per layer of the screen's size).
#include "cli_reader.h"
#include "offsetgen_test_support.h"
#include "slice_test_support.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;
using test_support::read_file;
using test_support::run_command;
using test_support::run_offsetgen;
using test_support::scratch_dir;
using namespace test;  // the CLI reader

const double kCell = 8, kLayer = 0.25;
// The part's options; slice() replaces those `extra` gives again and appends the rest.
const std::vector<std::pair<std::string, std::string>> kPart = {
    {"--surface", "gyroid"}, {"--density", "0.2"}, {"--cells", "2"}, {"--cell-size", "8"}, {"--layer-height", "0.25"}};

std::vector<std::string> part_args(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"slice", "-q"};
  for (const auto& [option, value] : kPart)
    if (std::find(extra.begin(), extra.end(), option) == extra.end()) args.insert(args.end(), {option, value});
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

test_support::CommandResult slice(const std::vector<std::string>& extra) { return run_offsetgen(part_args(extra)); }

// Reads the file and checks it against the wall: returns the number of vertices checked on the wall.
size_t check_cli(const std::string& path, double vertex_tolerance) {
  const CliFile f = read_cli(read_file(path));
  EXPECT_EQ(f.units, 1.0);
  EXPECT_EQ(f.header_layers, static_cast<long>(f.layers.size()));
  EXPECT_EQ(f.layers.size(), 64u);  // 16 mm at 0.25 mm
  if (!f.binary) {
    EXPECT_TRUE(f.ended);
  }
  const wall::WallField& field = test::gyroid_field();
  size_t checked = 0;
  for (size_t k = 0; k < f.layers.size(); ++k) {
    const CliLayer& layer = f.layers[k];
    EXPECT_NEAR(layer.z, kLayer * double(k + 1), 1e-6);
    std::vector<std::array<double, 2>> on_wall;
    for (const Polyline& p : layer.polylines) {
      EXPECT_EQ(p.id, 1);
      EXPECT_GE(p.points.size(), 4u);
      EXPECT_EQ(p.points.front(), p.points.back()) << "an open polyline in layer " << k;
      const double area = signed_area(p.points);
      EXPECT_EQ(p.dir, area > 0 ? 1 : 0) << "dir against the signed area " << area;
      for (const auto& v : p.points) {
        const double eps = 1e-6;
        const bool side = std::abs(v[0]) < eps || std::abs(v[0] - 2 * kCell) < eps || std::abs(v[1]) < eps ||
                          std::abs(v[1] - 2 * kCell) < eps;
        EXPECT_GE(v[0], -eps);
        EXPECT_LE(v[0], 2 * kCell + eps);
        EXPECT_GE(v[1], -eps);
        EXPECT_LE(v[1], 2 * kCell + eps);
        if (!side) on_wall.push_back(v);
      }
    }
    const std::vector<double> d = test::wall_distances(field, on_wall, layer.z - 0.5 * kLayer, kCell);
    size_t worst = 0;
    for (size_t i = 0; i < d.size(); ++i)
      if (d[i] > d[worst]) worst = i;
    if (!d.empty()) {
      EXPECT_LT(d[worst], vertex_tolerance) << "layer " << k << ": (" << on_wall[worst][0] << ", " << on_wall[worst][1]
                                            << ") is " << d[worst] << " mm off the wall";
    }
    checked += d.size();
  }
  return checked;
}

// A sphere's wall (radius 0.35 cell, t = 0.04) cut at z = 0.25 and 0.75 cell: an annulus per layer,
// its outer loop counter-clockwise and its hole clockwise, every vertex on the circles of radius
// sqrt((0.35 +- 0.02)^2 - 0.25^2) cell (the offsets of a sphere are spheres), and each loop's area that
// of its circle less at most the chords' segments (perimeter x tolerance).
TEST(SliceCli, SphereWallLayersAreAnnuliOnTheExactCircles) {
  const std::string dir = scratch_dir("slice-sphere");
  const auto r = run_offsetgen({"slice", "-q", "--expr", "(x-0.5)^2 + (y-0.5)^2 + (z-0.5)^2 - 0.1225", "--thickness",
                                "0.04", "--cells", "1", "--cell-size", "10", "--layer-height", "5", "--cli-ascii", "-o",
                                dir + "/sphere.cli"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CliFile f = read_cli(read_file(dir + "/sphere.cli"));
  ASSERT_EQ(f.layers.size(), 2u);
  const double radius[2] = {10 * std::sqrt(0.37 * 0.37 - 0.0625), 10 * std::sqrt(0.33 * 0.33 - 0.0625)};
  for (const CliLayer& layer : f.layers) {
    ASSERT_EQ(layer.polylines.size(), 2u);
    for (const Polyline& p : layer.polylines) {
      const int outer = p.dir == 1 ? 0 : 1;
      const double area = signed_area(p.points), exact = M_PI * radius[outer] * radius[outer];
      EXPECT_EQ(area > 0, p.dir == 1);
      EXPECT_LE(std::abs(area), exact);
      EXPECT_GT(std::abs(area), exact - 2 * M_PI * radius[outer] * 0.005);
      for (const auto& v : p.points) EXPECT_NEAR(std::hypot(v[0] - 5, v[1] - 5), radius[outer], 1e-6);
    }
    EXPECT_NE(layer.polylines[0].dir, layer.polylines[1].dir) << "an outer loop and a hole";
  }
}

TEST(SliceCli, AsciiCliReadBackHasEveryVertexWithin1e6MmOfTheWall) {
  const std::string dir = scratch_dir("slice-ascii");
  const auto r = slice({"--cli-ascii", "-o", dir + "/part.cli"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(check_cli(dir + "/part.cli", 1e-6), 10000u);
}

TEST(SliceCli, BinaryCliReadBackHasEveryVertexWithinFloat32RoundingOfTheWall) {
  const std::string dir = scratch_dir("slice-binary");
  const auto r = slice({"-o", dir + "/part.cli"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // float32 near 16 mm rounds by up to 9.5e-7 mm per coordinate.
  EXPECT_GT(check_cli(dir + "/part.cli", 1e-6 + std::sqrt(2.0) * 9.6e-7), 10000u);
}

// Same file names (an SL1 archive holds its own name as jobDir) in different directories; a block one
// cell tall in layers of 0.5 mm.
void expect_same_bytes(const std::string& ext) {
  const std::string dir = scratch_dir("slice-determinism-" + ext);
  for (const std::string run : {"one", "two", "three"}) fs::create_directories(dir + "/" + run);
  const std::vector<std::string> part = {"--cells", "2,2,1", "--layer-height", "0.5"};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.end(), part.begin(), part.end());
    return extra;
  };
  ASSERT_EQ(slice(with({"-j", "2", "-o", dir + "/one/part." + ext})).exit_code, 0);
  ASSERT_EQ(slice(with({"-j", "2", "-o", dir + "/two/part." + ext})).exit_code, 0);
  ASSERT_EQ(slice(with({"-j", "1", "-o", dir + "/three/part." + ext})).exit_code, 0);
  const std::string a = read_file(dir + "/one/part." + ext);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == read_file(dir + "/two/part." + ext)) << ext << " differs between runs";
  EXPECT_TRUE(a == read_file(dir + "/three/part." + ext)) << ext << " differs between 1 and 2 threads";
}

TEST(SliceCli, CliSameBytesTwiceAndOnOneOrTwoThreads) { expect_same_bytes("cli"); }
TEST(SliceCli, Sl1SameBytesTwiceAndOnOneOrTwoThreads) { expect_same_bytes("sl1"); }

TEST(SliceCli, BadInputExits2AndWritesNothing) {
  const std::string dir = scratch_dir("slice-bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--layer-height", "0", "-o", dir + "/a.cli"}, "--layer-height"},
      {{"--layer-height", "-0.1", "-o", dir + "/a.cli"}, "--layer-height"},
      {{"--layer-height", "9", "-o", dir + "/a.cli"}, "above a cell"},
      {{"--tolerance", "0", "-o", dir + "/a.cli"}, "--tolerance"},
      {{"-o", dir + "/a.stl"}, "unknown extension"},
      {{"--cells", "9", "-o", dir + "/a.sl1"}, "larger than the SL1 screen"},
      {{"--cli-ascii", "-o", dir + "/a.svg"}, "--cli-ascii"},
      {{"--printer", "sl1s", "-o", dir + "/a.sl1"}, "--printer"},
      // A box cell ("distorted cells") is meshed and written as STEP, not sliced yet; a bad size either way.
      {{"--cell-size", "8,8,12", "-o", dir + "/a.cli"}, "slice takes a cube cell only"},
      {{"--cell-size", "8,eight", "-o", dir + "/a.cli"}, "expected MM (a cube cell) or X,Y,Z"},
  };
  for (const auto& [extra, reason] : cases) {
    const std::vector<std::string> args = part_args(extra);
    const auto r = run_offsetgen(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "a refused run left a file";
}

TEST(SliceCli, Sl1ArchiveOpensWithItsKeysAndOnePngPerLayerOfTheScreensSize) {
  const std::string dir = scratch_dir("slice-sl1");
  for (const auto& [ext, width, height, model] :
       {std::tuple<std::string, int, int, std::string>{"sl1", 1440, 2560, "SL1"}, {"sl1s", 1620, 2560, "SL1S"}}) {
    const std::string path = dir + "/part." + ext;
    const auto r = slice({"--layer-height", "0.5", "-o", path});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string script =
        "import sys, struct, zipfile\n"
        "z = zipfile.ZipFile(sys.argv[1])\n"
        "assert z.testzip() is None\n"
        "names = z.namelist()\n"
        "cfg = dict(l.split(' = ', 1) for l in z.read('config.ini').decode().splitlines())\n"
        "ini = dict(l.split(' = ', 1) for l in z.read('prusaslicer.ini').decode().splitlines())\n"
        "pngs = [n for n in names if n.endswith('.png')]\n"
        "sizes = set()\n"
        "for n in pngs:\n"
        "    b = z.read(n)\n"
        "    assert b[:8] == b'\\x89PNG\\r\\n\\x1a\\n'\n"
        "    w, h, depth, colour = struct.unpack('>IIBB', b[16:26])\n"
        "    sizes.add((w, h, depth, colour))\n"
        "print(names[0], names[1], pngs[0], len(pngs), sorted(sizes), cfg['numFast'], cfg['numSlow'],\n"
        "      cfg['printerModel'], cfg['jobDir'], cfg['layerHeight'], 'fileCreationTimestamp' in cfg,\n"
        "      ini['printer_technology'], ini['display_pixels_x'], ini['display_pixels_y'],\n"
        "      ini['display_orientation'], ini['display_mirror_x'], ini['layer_height'], "
        "ini['initial_layer_height'])\n";
    const auto py = run_command({"python3", "-c", script, path});
    ASSERT_EQ(py.exit_code, 0) << py.output;
    EXPECT_EQ(py.output,
              fmt::format("config.ini prusaslicer.ini part00000.png 32 [({}, {}, 8, 0)] 32 0 {} part 0.5 False SLA "
                          "2560 {} portrait 1 0.5 0.5\n",
                          width, height, model, width));
  }
}

}  // namespace
}  // namespace offsetgen::slice
