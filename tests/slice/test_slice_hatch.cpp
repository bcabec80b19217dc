// `offsetgen slice --hatch` and `--beam-offset` (CLI), read back by the tests' own CLI reader: every
// layer's hatches after its polylines in one record, parallel at the layer's angle (ANGLE + k ROTATE),
// on lines SPACING apart, each ending on a written contour and running inside the solid, filling its
// area; the contours offset inward lie the offset from the plain run's contours; the summary's counts
// are the file's; the same bytes twice and on 1 or 2 threads; a share merged is the single run; bad
// input exits 2 and writes nothing.
#include "cli_reader.h"
#include "offsetgen_test_support.h"
#include "plane_geometry.h"
#include "slice_cli_cases.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;
using test_support::read_file;
using test_support::run_offsetgen;
using test_support::scratch_dir;
using namespace test;

const double kPi = std::acos(-1.0);
const double kTolerance = 0.005;  // the command's default --tolerance

// 2 x 2 x 2 cells of 8 mm at 0.25 mm: 64 layers.
std::vector<std::string> block(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"slice", "--surface",   "gyroid", "--density",      "0.2", "--cells",
                                   "2",     "--cell-size", "8",      "--layer-height", "0.25"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

std::vector<Ring> rings_of(const CliLayer& layer) {
  std::vector<Ring> rings;
  for (const Polyline& p : layer.polylines) rings.emplace_back(p.points.begin(), p.points.end() - 1);
  return rings;
}

double area_of(const std::vector<Ring>& rings) {
  double a = 0;
  for (const Ring& r : rings) a += ring_area(r);
  return a;
}

struct HatchCheck {
  size_t hatches = 0;
  double length = 0, area = 0;
};

// Checks every layer's hatches against its polylines; `on_contour`: how far an endpoint may be from
// them (mm, the file's rounding).
HatchCheck check_hatches(const CliFile& f, double spacing, double angle, double rotation, double on_contour) {
  HatchCheck total;
  for (size_t k = 0; k < f.layers.size(); ++k) {
    const CliLayer& layer = f.layers[k];
    const std::vector<Ring> rings = rings_of(layer);
    EXPECT_EQ(layer.hatch_records, layer.hatches.empty() ? 0u : 1u) << "layer " << k;
    const double a = std::fmod(angle + double(k) * rotation, 180.0) * kPi / 180;
    const double dx = std::cos(a), dy = std::sin(a);
    double worst_end = 0, worst_line = 0, worst_angle = 0;
    size_t outside = 0;
    for (const HatchLine& h : layer.hatches) {
      worst_end = std::max({worst_end, distance_to_rings(h.start, rings), distance_to_rings(h.end, rings)});
      const double len = std::hypot(h.end[0] - h.start[0], h.end[1] - h.start[1]);
      total.length += len;
      if (len > 0.5)
        worst_angle =
            std::max(worst_angle, std::abs((h.end[0] - h.start[0]) * dy - (h.end[1] - h.start[1]) * dx) / len);
      const Pt mid{0.5 * (h.start[0] + h.end[0]), 0.5 * (h.start[1] + h.end[1])};
      const double t = (-mid[0] * dy + mid[1] * dx) / spacing - 0.5;
      worst_line = std::max(worst_line, std::abs(t - std::round(t)) * spacing);
      if (!inside_rings(mid, rings)) ++outside;
    }
    EXPECT_LE(worst_end, on_contour) << "layer " << k << ": a hatch ends off the contours";
    EXPECT_LE(worst_end, kTolerance);
    EXPECT_LE(worst_line, 1e-4) << "layer " << k << ": a hatch off its line (mm)";
    EXPECT_LE(worst_angle, 1e-4) << "layer " << k << ": a hatch not at " << a * 180 / kPi << " degrees";
    EXPECT_EQ(outside, 0u) << "layer " << k << ": hatches whose midpoint is outside the solid";
    total.hatches += layer.hatches.size();
    total.area += area_of(rings);
  }
  return total;
}

void expect_hatched_file(const std::vector<std::string>& format, const std::string& name, double on_contour) {
  const std::string dir = scratch_dir(name), path = dir + "/h.cli";
  std::vector<std::string> extra = {"--hatch", "0.1,30,66.67", "-o", path};
  extra.insert(extra.end(), format.begin(), format.end());
  const auto r = run_offsetgen(block(extra));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CliFile f = read_cli(read_file(path));
  ASSERT_EQ(f.layers.size(), 64u);
  const HatchCheck c = check_hatches(f, 0.1, 30, 66.67, on_contour);
  // Lines 0.1 mm apart across walls about 1 mm wide: length x spacing is the area to a few percent.
  EXPECT_NEAR(c.length * 0.1 / c.area, 1.0, 0.02) << "hatch length " << c.length << " mm, area " << c.area;
  // The summary counts what the file holds.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(: (\d+) hatches, ([0-9.]+) m of them)"))) << r.output;
  EXPECT_EQ(std::stoul(m[1].str()), c.hatches);
  EXPECT_NEAR(std::stod(m[2].str()) * 1000, c.length, 1.0);
}

TEST(SliceHatch, AsciiHatchesAreParallelSpacedEndOnTheContoursAndFillTheSolid) {
  expect_hatched_file({"--cli-ascii"}, "slice-hatch-ascii", 1e-6);
}

TEST(SliceHatch, BinaryHatchesReadBackAsRecord132WithinFloat32Rounding) {
  expect_hatched_file({}, "slice-hatch-binary", 1e-5);
}

TEST(SliceHatch, BeamOffsetContoursLieTheOffsetFromThePlainContoursAndHatchesFillThem) {
  const std::string dir = scratch_dir("slice-beam-offset");
  const double offset = 0.05;
  ASSERT_EQ(run_offsetgen(block({"--cli-ascii", "-q", "-o", dir + "/plain.cli"})).exit_code, 0);
  const auto r = run_offsetgen(block(
      {"--cli-ascii", "-q", "--beam-offset", fmt::format("{}", offset), "--hatch", "0.1", "-o", dir + "/offset.cli"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CliFile plain = read_cli(read_file(dir + "/plain.cli"));
  const CliFile shrunk = read_cli(read_file(dir + "/offset.cli"));
  ASSERT_EQ(plain.layers.size(), shrunk.layers.size());
  size_t vertices = 0;
  for (size_t k = 0; k < plain.layers.size(); ++k) {
    const std::vector<Ring> before = rings_of(plain.layers[k]), after = rings_of(shrunk.layers[k]);
    EXPECT_LT(area_of(after), area_of(before)) << "layer " << k;
    double worst = 0;
    for (const Polyline& p : shrunk.layers[k].polylines) {
      EXPECT_EQ(p.points.front(), p.points.back());
      EXPECT_EQ(p.dir, signed_area(p.points) > 0 ? 1 : 0);
      for (const Pt& v : p.points) {
        // The inward offset's boundary is the set at the offset's distance from the contour (round
        // joins: arcs at a quarter of the tolerance; 1 nm grid, 7 decimals).
        worst = std::max(worst, std::abs(distance_to_rings(v, before) - offset));
        EXPECT_TRUE(inside_rings(v, before)) << "layer " << k;
        ++vertices;
      }
    }
    EXPECT_LE(worst, 0.25 * kTolerance + 1e-6) << "layer " << k;
  }
  EXPECT_GT(vertices, 10000u);
  check_hatches(shrunk, 0.1, 0, 66.67, 1e-6);
}

TEST(SliceHatch, HatchedFileSameBytesTwiceAndOnOneOrTwoThreads) {
  const std::string dir = scratch_dir("slice-hatch-bytes");
  std::string first;
  for (const char* threads : {"1", "2", "2"}) {
    const std::string path = dir + "/t" + threads + ".cli";
    ASSERT_EQ(run_offsetgen(block({"-q", "-j", threads, "--hatch", "0.15,10,45", "--beam-offset", "0.03", "-o", path}))
                  .exit_code,
              0);
    const std::string bytes = read_file(path);
    if (first.empty()) first = bytes;
    EXPECT_TRUE(bytes == first) << "-j " << threads << " wrote other bytes";
  }
}

TEST(SliceHatch, LayerRangeSharesWithHatchesMergeToTheSingleRunsBytes) {
  const std::string dir = scratch_dir("slice-hatch-shares");
  const std::vector<std::string> hatch = {"-q", "--hatch", "0.2", "--beam-offset", "0.02"};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.end(), hatch.begin(), hatch.end());
    return block(extra);
  };
  ASSERT_EQ(run_offsetgen(with({"-o", dir + "/single.cli"})).exit_code, 0);
  const auto merged = test::slice_shares_and_merge(with, dir, 2, "cli", dir + "/merged.cli");
  ASSERT_EQ(merged.exit_code, 0) << merged.output;
  EXPECT_TRUE(read_file(dir + "/single.cli") == read_file(dir + "/merged.cli"));
  // A share of a run without hatches is another request.
  ASSERT_EQ(run_offsetgen(block({"-q", "--layer-range", "1/2", "-o", dir + "/plain1.cli.part"})).exit_code, 0);
  const auto mixed = run_offsetgen(
      {"slice", "-q", "--merge", dir + "/s0.cli.part", dir + "/plain1.cli.part", "-o", dir + "/mixed.cli"});
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  EXPECT_FALSE(fs::exists(dir + "/mixed.cli"));
}

TEST(SliceHatch, BadHatchOrBeamOffsetExits2WithTheReasonAndWritesNothing) {
  const std::string dir = scratch_dir("slice-hatch-bad");
  const std::vector<test::RefusedCase> cases = {
      {{"--hatch", "0", "-o", dir + "/a.cli"}, "is not positive"},
      {{"--hatch", "-0.1", "-o", dir + "/a.cli"}, "is not positive"},
      {{"--hatch", "0.1,x", "-o", dir + "/a.cli"}, "is not a number"},
      {{"--hatch", "0.1,1,2,3", "-o", dir + "/a.cli"}, "at most three numbers"},
      {{"--hatch", "1e-6", "-o", dir + "/a.cli"}, "use a larger spacing"},
      {{"--hatch", "0.1", "-o", dir + "/a.svg"}, "is not .cli"},
      {{"--hatch", "0.1", "-o", dir + "/a.sl1"}, "is not .cli"},
      {{"--hatch", "0.1", "-o", dir + "/layers/"}, "is not .cli"},
      {{"--beam-offset", "0.05", "-o", dir + "/a.sl1"}, "is not .cli"},
      {{"--beam-offset", "0", "-o", dir + "/a.svg"}, "is not .cli"},
      {{"--beam-offset", "-0.01", "-o", dir + "/a.cli"}, "is not a length >= 0"},
      {{"--beam-offset", "nan", "-o", dir + "/a.cli"}, "is not a length >= 0"},
  };
  test::expect_refused(cases, block, dir);
}

}  // namespace
}  // namespace offsetgen::slice
