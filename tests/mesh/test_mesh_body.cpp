// `offsetgen mesh --body`: a lattice inside a part, checked on bodies whose insides are known in
// closed form (a finely tessellated sphere and torus, written here as STL), with admesh, the closed-form
// volumes of docs/parts.md and the skin read off the written mesh. Real parts nobody here drew are
// meshed by tools/check_parts.sh (ctest label slow).
#include "mesh/mesh_files.h"
#include "mesh/triangle_mesh.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace offsetgen::mesh::testing {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

// The facets of a binary STL, without its 80-byte header (which names the body).
std::string stl_facets(const std::string& path) { return read_bytes(path).substr(80); }

struct Radii {
  double min = HUGE_VAL, max = 0;
  size_t in_band = 0;  // vertices strictly between the given radii
};
Radii radii(const std::string& stl, const std::array<double, 3>& c, double band_lo, double band_hi) {
  Radii r;
  for (const auto& f : read_stl(stl))
    for (const auto& v : f) {
      const double d = std::hypot(v[0] - c[0], v[1] - c[1], v[2] - c[2]);
      r.min = std::min(r.min, d);
      r.max = std::max(r.max, d);
      if (d > band_lo && d < band_hi) ++r.in_band;
    }
  return r;
}

constexpr double kRadius = 12, kSkin = 1.5;
const std::array<double, 3> kCentre{20, 20, 20};

// A gyroid of relative density 0.3 in 6 mm cells inside a 12 mm sphere with a 1.5 mm skin, at 0.25 mm
// voxels: one closed solid whose outer surface is the sphere, whose skin has no surface inside it, and
// whose volume is V_skin + rho V_core in closed form.
TEST(MeshBody, SphereWithSkinIsOneCleanSolidWithTheClosedFormVolume) {
  const std::string dir = scratch_dir("body-sphere");
  write_stl(sphere(kRadius, kCentre, 5), dir + "/sphere.stl");
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--density", "0.3", "--body", dir + "/sphere.stl", "--skin",
                            "1.5", "--cell-size", "6", "--voxel", "0.25", "-o", dir + "/part.stl"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_admesh_clean(dir + "/part.stl", summary_number(r.output, " mm over "));
  const double voxel = 0.25;
  // The outer surface is the sphere; nothing lies inside the skin; cavities begin at R - s.
  const Radii rad = radii(dir + "/part.stl", kCentre, kRadius - kSkin + voxel, kRadius - voxel);
  EXPECT_NEAR(rad.max, kRadius, voxel);
  EXPECT_EQ(rad.in_band, 0u) << "vertices inside the skin";
  const double measured_skin = summary_number(r.output, "measured: thinnest ");
  EXPECT_GE(measured_skin, kSkin - voxel);
  EXPECT_LE(measured_skin, kSkin + voxel);
  // 4/3 pi R^3 - 4/3 pi (R - s)^3 + rho 4/3 pi (R - s)^3 (the tessellation loses 0.05% of R^3).
  const double core = 4.0 / 3 * kPi * std::pow(kRadius - kSkin, 3);
  const double expected = 4.0 / 3 * kPi * std::pow(kRadius, 3) - core + 0.3 * core;
  const double volume = stl_volume(read_stl(dir + "/part.stl"));
  // About 27 cells in the core: the lattice's share of it is within a few percent of rho.
  EXPECT_NEAR(volume / expected, 1, 0.02);
}

// Without a skin the lattice is cut flush by the body: nothing outside it, and its volume is the
// lattice's share of the sphere.
TEST(MeshBody, SkinZeroCutsTheLatticeFlushByTheBody) {
  const std::string dir = scratch_dir("body-flush");
  write_stl(sphere(kRadius, kCentre, 4), dir + "/sphere.stl");
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--density", "0.3", "--body", dir + "/sphere.stl",
                            "--cell-size", "6", "--voxel", "0.25", "-o", dir + "/part.stl"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("cut flush"), std::string::npos) << r.output;
  const Radii rad = radii(dir + "/part.stl", kCentre, 0, 0);
  EXPECT_LE(rad.max, kRadius + 0.25);
  const double volume = stl_volume(read_stl(dir + "/part.stl"));
  EXPECT_NEAR(volume / (0.3 * 4.0 / 3 * kPi * std::pow(kRadius, 3)), 1, 0.05);
}

// Insideness comes from OpenVDB's sign flood fill, not from the facets' orientation: the same sphere
// with every facet turned inward gives the same bytes.
TEST(MeshBody, InvertedFacetsGiveTheSameBytes) {
  const std::string dir = scratch_dir("body-inverted");
  TriangleMesh s = sphere(kRadius, kCentre, 3);
  write_stl(s, dir + "/out.stl");
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  write_stl(s, dir + "/in.stl");
  for (const std::string name : {"out", "in"}) {
    CliRun r =
        run_offsetgen({"mesh", "--surface", "schwarzp", "--thickness", "0.15", "--body", dir + "/" + name + ".stl",
                       "--skin", "1", "--cell-size", "8", "--voxel", "0.4", "-o", dir + "/part_" + name + ".stl"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  EXPECT_TRUE(stl_facets(dir + "/part_out.stl") == stl_facets(dir + "/part_in.stl"));
}

// A torus has a hole through it: the part keeps it, and its core is 2 pi^2 R (r - s)^2.
TEST(MeshBody, TorusKeepsItsHoleAndHasTheClosedFormVolume) {
  const std::string dir = scratch_dir("body-torus");
  const double big = 14, small = 6, skin = 1;
  write_stl(torus(big, small, {30, 30, 10}, 256, 96), dir + "/torus.stl");
  CliRun r = run_offsetgen({"mesh", "--surface", "diamond", "--density", "0.35", "--body", dir + "/torus.stl", "--skin",
                            "1", "--cell-size", "5", "--voxel", "0.2", "-o", dir + "/part.stl"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_admesh_clean(dir + "/part.stl", summary_number(r.output, " mm over "));
  double nearest_axis = HUGE_VAL;
  for (const auto& f : read_stl(dir + "/part.stl"))
    for (const auto& v : f) nearest_axis = std::min(nearest_axis, std::hypot(v[0] - 30.0, v[1] - 30.0));
  EXPECT_NEAR(nearest_axis, big - small, 0.2);
  const double body = 2 * kPi * kPi * big * small * small, core = 2 * kPi * kPi * big * std::pow(small - skin, 2);
  const double expected = body - core + 0.35 * core;
  const double volume = stl_volume(read_stl(dir + "/part.stl"));
  EXPECT_NEAR(volume / expected, 1, 0.02);
}

// A torus about the z axis, filled with a cylindrical gyroid (--map): the map's axis runs through the
// torus's hole, outside the body, so it is accepted; one clean solid that keeps the hole.
TEST(MeshMap, TorusAroundTheAxisIsFilledWithACylindricalLattice) {
  const std::string dir = scratch_dir("map-torus");
  const double big = 12, small = 5;
  write_stl(torus(big, small, {0, 0, 0}, 192, 64), dir + "/torus.stl");
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--map", "cylindrical:12,4,4", "--thickness", "0.6",
                            "--body", dir + "/torus.stl", "--skin", "1", "--voxel", "0.15", "-o", dir + "/part.stl"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("map:        u = sqrt(x^2+y^2)/(4)"), std::string::npos);
  EXPECT_NE(r.output.find("lies outside the body"), std::string::npos);
  expect_admesh_clean(dir + "/part.stl", summary_number(r.output, " mm over "));
  double nearest_axis = HUGE_VAL;
  for (const auto& f : read_stl(dir + "/part.stl"))
    for (const auto& v : f) nearest_axis = std::min(nearest_axis, std::hypot(double(v[0]), double(v[1])));
  EXPECT_NEAR(nearest_axis, big - small, 0.2);
}

// The map's axis inside the body: refused (exit 2) naming the point, and nothing is written. A
// mapped block holding the axis is refused the same way; one clear of it is meshed.
TEST(MeshMap, ASingularPointWhereWallsAreKeptIsRefused) {
  const std::string dir = scratch_dir("map-refused");
  write_stl(sphere(8, {0, 0, 0}, 3), dir + "/ball.stl");
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--map", "cylindrical:8,4,4", "--thickness", "0.6", "--body",
                            dir + "/ball.stl", "-o", dir + "/part.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("inside the body"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/part.stl"));
  r = run_offsetgen({"mesh", "--surface", "gyroid", "--map", "cylindrical:8,4,4", "--thickness", "0.6", "--domain",
                     "-5,-5,0:5,5,4", "-o", dir + "/block.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is singular at (x, y, z) = (0, 0,"), std::string::npos) << r.output;
  r = run_offsetgen({"mesh", "--surface", "gyroid", "--map", "cylindrical:8,4,4", "--thickness", "0.6", "--cells", "2",
                     "--body", dir + "/ball.stl", "-o", dir + "/part.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_offsetgen({"mesh", "--surface", "gyroid", "--map", "cylindrical:8,4,4", "--thickness", "0.6", "--domain",
                     "6,-3,0:12,3,4", "--voxel", "0.15", "-o", dir + "/block.stl"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_admesh_clean(dir + "/block.stl", -1);  // a block without skin may hold several pieces
}

// --fillet blends the walls into the skin with a smooth minimum: more material where they meet, and
// still one clean solid.
TEST(MeshBody, AFilletAddsMaterialWhereWallsMeetTheSkinAndStaysClean) {
  const std::string dir = scratch_dir("body-fillet");
  write_stl(sphere(kRadius, kCentre, 4), dir + "/sphere.stl");
  double volume[2] = {0, 0};
  for (int fillet = 0; fillet < 2; ++fillet) {
    const std::string out = dir + "/part" + std::to_string(fillet) + ".stl";
    std::vector<std::string> args = {"mesh",   "--surface",         "gyroid", "--density", "0.3",
                                     "--body", dir + "/sphere.stl", "--skin", "1.5",       "--cell-size",
                                     "6",      "--voxel",           "0.25",   "-o",        out};
    if (fillet) args.insert(args.end(), {"--fillet", "1"});
    CliRun r = run_offsetgen(args);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    if (fillet) {
      EXPECT_NE(r.output.find("1 mm fillet"), std::string::npos) << r.output;
      expect_admesh_clean(out, summary_number(r.output, " mm over "));
    }
    volume[fillet] = stl_volume(read_stl(out));
  }
  EXPECT_GT(volume[1], volume[0] * 1.002);
  EXPECT_LT(volume[1], volume[0] * 1.1);
}

TEST(MeshBodyInput, AnOpenBodyIsRefusedWithWhereItIsOpenAndRepairClosesIt) {
  const std::string dir = scratch_dir("body-open");
  TriangleMesh s = sphere(kRadius, kCentre, 3);
  s.triangles.pop_back();
  write_stl(s, dir + "/open.stl");
  const std::vector<std::string> base = {"mesh",   "--surface",       "gyroid",      "--thickness", "0.15",
                                         "--body", dir + "/open.stl", "--cell-size", "8",           "--voxel",
                                         "0.5"};
  std::vector<std::string> args = base;
  args.insert(args.end(), {"-o", dir + "/part.stl"});
  CliRun r = run_offsetgen(args);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("3 open edges"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--repair"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/part.stl"));
  args.push_back("--repair");
  r = run_offsetgen(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("filled 1 hole"), std::string::npos) << r.output;
  expect_admesh_clean(dir + "/part.stl", -1);
}

TEST(MeshBodyInput, BadBodiesExitWith2NamingTheProblemAndWriteNothing) {
  const std::string dir = scratch_dir("body-bad");
  write_stl(sphere(kRadius, kCentre, 2), dir + "/sphere.stl");
  write_stl(sphere(0.3, kCentre, 2), dir + "/tiny.stl");
  std::ofstream(dir + "/empty.stl").close();
  std::ofstream(dir + "/sphere.xyz") << "1 2 3\n";
  const std::string out = dir + "/part.stl";
  auto run = [&](const std::string& body, std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"mesh", "--surface", "gyroid", "--thickness", "0.15", "--body", body, "-o", out};
    a.insert(a.end(), extra.begin(), extra.end());
    return run_offsetgen(a);
  };
  const std::vector<std::pair<CliRun, std::string>> cases = {
      {run(dir + "/empty.stl"), "empty.stl"},
      {run(dir + "/missing.stl"), "missing.stl"},
      {run(dir + "/sphere.xyz"), ".xyz"},
      {run(dir + "/tiny.stl"), "smaller than one cell"},
      {run(dir + "/sphere.stl", {"--skin", "12"}), "leaves no core"},
      {run(dir + "/sphere.stl", {"--skin", "-1"}), "--skin"},
      {run(dir + "/sphere.stl", {"--fillet", "1"}), "needs --skin"},
      {run(dir + "/sphere.stl", {"--scale", "0"}), "--scale"},
      {run(dir + "/sphere.stl", {"--origin", "1,2"}), "X,Y,Z"},
      {run(dir + "/sphere.stl", {"--cells", "2"}), "excludes"},
  };
  for (const auto& [r, expected] : cases) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << "expected '" << expected << "' in: " << r.output;
  }
  EXPECT_FALSE(fs::exists(out));
  // The tiny body's error says how to scale it.
  EXPECT_NE(cases[3].first.output.find("--scale 1000"), std::string::npos) << cases[3].first.output;
  // Never overwrite the body.
  const std::string before = read_bytes(dir + "/sphere.stl");
  CliRun r = run_offsetgen(
      {"mesh", "--surface", "gyroid", "--thickness", "0.15", "--body", dir + "/sphere.stl", "-o", dir + "/sphere.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is the body itself"), std::string::npos) << r.output;
  EXPECT_EQ(read_bytes(dir + "/sphere.stl"), before);
  // --skin without --body is a usage error.
  r = run_offsetgen({"mesh", "--surface", "gyroid", "--thickness", "0.15", "--skin", "1", "-o", out});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--body"), std::string::npos) << r.output;
}

// A body over 2 m across gets a warning that names --scale (here the skin then refuses it).
TEST(MeshBodyInput, ABodyOfImplausibleSizeGetsAWarningNamingScale) {
  const std::string dir = scratch_dir("body-huge");
  write_stl(sphere(1500, {0, 0, 0}, 1), dir + "/huge.stl");
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--thickness", "0.15", "--body", dir + "/huge.stl", "--skin",
                            "2000", "-o", dir + "/part.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("warning: the body is 3000 mm across"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--scale 0.001"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace offsetgen::mesh::testing
