// `offsetgen mesh` as a user runs it: the parts are closed, oriented, one piece (admesh), their
// volume matches the exact wall volume, vertices lie on the exact walls; bad input exits 2 and
// writes nothing.
#include "exact_wall_volume.h"
#include "mesh_test_support.h"
#include "sibling_executable.h"

#include "mesh/mesh_3mf.h"
#include "run/process.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>

#include <unistd.h>

namespace offsetgen::mesh::testing {
namespace {
namespace fs = std::filesystem;

// Cells of 10 mm; the summary's resolution is read back from the output.
int resolution_of(const std::string& output) {
  std::smatch m;
  const std::regex re(R"((\d+) voxels per cell)");
  return std::regex_search(output, m, re) ? std::stoi(m[1]) : 0;
}

class MeshAdmesh : public ::testing::TestWithParam<Case> {};

TEST_P(MeshAdmesh, IsClosedConsistentlyOrientedAndOnePart) { expect_clean_part(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    Parts, MeshAdmesh,
    ::testing::Values(Case{"gyroid", {"--surface", "gyroid", "--thickness", "0.1"}},
                      Case{"schwarzp", {"--surface", "schwarzp", "--thickness", "0.1"}},
                      Case{"diamond", {"--surface", "diamond", "--thickness", "0.1"}},
                      // 3 voxels across the thinnest wall; the automatic 4 runs under the slow label.
                      Case{"gyroid_graded",
                           {"--surface", "gyroid", "--thickness", "0.05 + 0.1*x/3", "--resolution", "60"}},
                      Case{"user_expression",
                           {"--expr", "cos(2*Pi*x) + cos(2*Pi*y) + cos(2*Pi*z) + a*cos(2*Pi*x)*cos(2*Pi*y)*cos(2*Pi*z)",
                            "--param", "a=0.5", "--name", "warped_p", "--thickness", "0.12"}}),
    [](const ::testing::TestParamInfo<Case>& c) { return c.param.name; });

// The gyroid block at t = 0.1 against its exact walls (the generated order-4 functions).
// Built on first use inside a test (not in SetUpTestSuite, where a failure would only mark the tests
// skipped): the mesh, its resolution and the exact walls.
struct AccuracyCase {
  int resolution = 0;
  std::vector<std::array<std::array<float, 3>, 3>> facets;
  std::unique_ptr<ExactWalls> walls;
  std::string error;
};

const AccuracyCase& accuracy_case() {
  static const AccuracyCase c = [] {
    AccuracyCase out;
    const std::string stl = scratch_dir("accuracy") + "/gyroid.stl";
    CliRun r = run_offsetgen(
        {"mesh", "--surface", "gyroid", "--thickness", "0.1", "--cells", "2", "--cell-size", "10", "-o", stl});
    if (r.exit_code != 0) {
      out.error = r.output;
      return out;
    }
    out.resolution = resolution_of(r.output);
    out.facets = read_stl(stl);
    out.walls = std::make_unique<ExactWalls>("gyroid", 4, 0.1);
    return out;
  }();
  return c;
}

class MeshAccuracy : public ::testing::Test {
 protected:
  void SetUp() override {
    const AccuracyCase& c = accuracy_case();
    ASSERT_TRUE(c.error.empty()) << c.error;
    ASSERT_GT(c.resolution, 0);
    resolution_ = c.resolution;
    facets_ = &c.facets;
    walls_ = c.walls.get();
  }
  int resolution_ = 0;
  const std::vector<std::array<std::array<float, 3>, 3>>* facets_ = nullptr;
  const ExactWalls* walls_ = nullptr;
};

TEST_F(MeshAccuracy, VolumeIsWithinHalfAPercentOfTheExactWallVolume) {
  // The block is 2^3 whole cells of 10 mm of the periodic walls: its exact volume is 8 cells' worth.
  const test_support::ExactWallVolume exact = test_support::exact_wall_volume("gyroid", "0.1", {2, 2, 2}, 10);
  EXPECT_LT(exact.standard_error / exact.volume, 1e-3);
  const double mesh = stl_volume(*facets_);
  EXPECT_LT(std::abs(mesh - exact.volume) / exact.volume, 0.005)
      << "mesh " << mesh << " mm^3, exact " << exact.volume << " mm^3 at " << resolution_ << " voxels per cell";
}

TEST_F(MeshAccuracy, VerticesLieWithinHalfAVoxelOfTheExactWalls) {
  ASSERT_GT(resolution_, 0);
  const double voxel = 1.0 / resolution_, half = 0.5 * voxel;
  std::vector<std::array<float, 3>> points;
  for (const auto& f : *facets_)
    for (const auto& p : f) points.push_back(p);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  size_t far = 0;
  double worst = 0;
  for (const auto& pf : points) {
    const double p[3] = {pf[0] / 10.0, pf[1] / 10.0, pf[2] / 10.0};  // cell units
    double box = HUGE_VAL;
    for (int a = 0; a < 3; ++a) box = std::min({box, std::abs(p[a]), std::abs(p[a] - 2)});
    // Distance to each wall: the gradient line through p crosses the wall within the bracket
    // [p - d g, p + d g] iff phi changes sign on it; the smallest such d is an upper bound.
    double nearest = box;
    for (double h : {0.05, -0.05}) {
      double g[3], length = 0;
      for (int a = 0; a < 3; ++a) {
        double q1[3] = {p[0], p[1], p[2]}, q2[3] = {p[0], p[1], p[2]};
        q1[a] += 1e-6;
        q2[a] -= 1e-6;
        g[a] = (walls_->phi(q1, h) - walls_->phi(q2, h)) / 2e-6;
        length += g[a] * g[a];
      }
      length = std::sqrt(length);
      if (!(length > 0)) continue;
      const double estimate = std::abs(walls_->phi(p, h)) / length;
      for (double d : {estimate * 1.01 + 1e-9, half}) {
        double lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
          lo[a] = p[a] - d * g[a] / length;
          hi[a] = p[a] + d * g[a] / length;
        }
        if ((walls_->phi(lo, h) <= 0) != (walls_->phi(hi, h) <= 0)) {
          nearest = std::min(nearest, d);
          break;
        }
      }
    }
    worst = std::max(worst, nearest);
    if (nearest > half) ++far;
  }
  EXPECT_EQ(far, 0u) << "of " << points.size() << " vertices; worst " << worst / voxel << " voxel";
}

// Bad input: a clear message, exit 2, and the output file untouched (absent, or its old bytes).
struct BadCase {
  std::string name;
  std::vector<std::string> args;
  std::string message;
};
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class MeshBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(MeshBadInput, ExitsWith2NamingTheProblemAndWritesNothing) {
  const BadCase& c = GetParam();
  const std::string dir = scratch_dir("bad-" + c.name);
  const std::string fresh = dir + "/fresh.stl", existing = dir + "/existing.stl";
  std::ofstream(existing) << "old bytes";
  for (const std::string& out : {fresh, existing}) {
    std::vector<std::string> args = {"mesh", "-o", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    for (auto& a : args)
      if (a == "OUT") a = out;
    CliRun r = run_offsetgen(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << "expected '" << c.message << "' in\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(fresh));
  std::ifstream in(existing);
  std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, "old bytes");
  for (const auto& entry : fs::directory_iterator(dir))  // no temporary left behind
    EXPECT_TRUE(entry.path() == fresh || entry.path() == existing) << entry.path();
}

INSTANTIATE_TEST_SUITE_P(
    Cases, MeshBadInput,
    ::testing::Values(
        BadCase{"no_wall", {"--surface", "gyroid"}, "no wall given"},
        BadCase{"zero_thickness", {"--surface", "gyroid", "--thickness", "0"}, "not a positive wall thickness"},
        BadCase{"negative_graded_thickness",
                {"--surface", "gyroid", "--thickness", "0.1 - 0.1*x", "--cells", "2"},
                "must be positive"},
        BadCase{"zero_cell_size",
                {"--surface", "gyroid", "--thickness", "0.1", "--cell-size", "0"},
                "--cell-size 0 is not a positive length"},
        BadCase{"negative_cell_size",
                {"--surface", "gyroid", "--thickness", "0.1", "--cell-size", "-5"},
                "is not a positive length"},
        BadCase{"zero_cells",
                {"--surface", "gyroid", "--thickness", "0.1", "--cells", "2x0"},
                "is not a positive number of cells"},
        BadCase{"wall_below_two_voxels",
                {"--surface", "gyroid", "--thickness", "0.1", "--resolution", "15"},
                "walls need at least 2 voxels"},
        BadCase{"unknown_surface", {"--surface", "nosuch", "--thickness", "0.1"}, "nosuch"},
        BadCase{"thickness_and_density",
                {"--surface", "gyroid", "--thickness", "0.1", "--density", "0.2"},
                "give one of --thickness, --density and --density-field"},
        BadCase{"density_above_its_limit", {"--surface", "gyroid", "--density", "0.99"}, "is above rho_max"},
        BadCase{"density_field_not_positive",
                {"--surface", "gyroid", "--density-field", "0.2 - 0.3*x"},
                "a relative density must lie in"},
        // Box cells ("distorted cells", --cell-size X,Y,Z): what they do not cover, and bad sizes.
        BadCase{"density_with_a_box_cell",
                {"--surface", "gyroid", "--density", "0.2", "--cell-size", "10,10,15"},
                "--density and --density-field need a cube cell"},
        BadCase{"resolution_with_a_box_cell",
                {"--surface", "gyroid", "--thickness", "1", "--cell-size", "10,10,15", "--resolution", "40"},
                "--resolution counts voxels per cell"},
        BadCase{"box_cell_size_with_a_zero_side",
                {"--surface", "gyroid", "--thickness", "1", "--cell-size", "10,0,15"},
                "--cell-size 0 is not a positive length"},
        BadCase{"box_cell_size_not_a_number",
                {"--surface", "gyroid", "--thickness", "1", "--cell-size", "10,ten,15"},
                "expected MM (a cube cell) or X,Y,Z"},
        BadCase{"cell_size_of_two_sides",
                {"--surface", "gyroid", "--thickness", "1", "--cell-size", "10,15"},
                "expected MM (a cube cell) or X,Y,Z"},
        BadCase{"two_d_surface",
                {"--expr", "cos(2*Pi*x) + cos(2*Pi*y)", "--name", "flat", "--thickness", "0.1"},
                "2D surface"}),
    [](const ::testing::TestParamInfo<BadCase>& c) { return c.param.name; });

// --density R meshes the sheet of relative density R: the part's volume over its box is R, up to
// the mesh's volume error and the offsets' (far smaller at order 4). The mesh loses a little volume
// at each wall, a voxel-size effect: the gyroid at rho = 0.2 (t = 0.065) measured -1.6% at 48
// voxels per cell, -0.46% at 96 and -0.27% at 128.
TEST(MeshDensity, TheMeshedPartHasTheRequestedRelativeDensity) {
  const std::string stl = scratch_dir("density") + "/rho.stl";
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--density", "0.2", "--cells", "1", "--resolution", "96",
                            "--cell-size", "10", "-o", stl});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double density = stl_volume(read_stl(stl)) / 1000;  // one cell of 10 mm
  EXPECT_NEAR(density, 0.2, 0.2 * 0.01);
  EXPECT_NE(r.output.find("; --density 0.2)"), std::string::npos) << r.output;
}

// --density-field grades the wall: rho falls linearly from 0.3 to 0.1 along 2 cells, so the part's
// density is close to the mean, 0.2 (not exact: the density relation holds per cell of a uniform
// sheet, and a graded sheet's volume differs at second order in the gradient).
TEST(MeshDensity, AGradedDensityFieldAveragesToItsMean) {
  const std::string stl = scratch_dir("density-field") + "/graded.stl";
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--density-field", "0.3 - 0.1*x", "--cells", "2x1x1",
                            "--resolution", "96", "--cell-size", "10", "-o", stl});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double density = stl_volume(read_stl(stl)) / 2000;  // two cells of 10 mm
  EXPECT_NEAR(density, 0.2, 0.2 * 0.02);
}

TEST(MeshBadOutput, AnUnwritableOrUnknownPathExitsWith2BeforeAnyWork) {
  const std::string dir = scratch_dir("bad-output");
  CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--thickness", "0.1", "-o", dir + "/missing/part.stl"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  r = run_offsetgen({"mesh", "--surface", "gyroid", "--thickness", "0.1", "-o", dir + "/part.obj"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("unknown mesh format"), std::string::npos) << r.output;
  fs::create_directories(dir + "/locked");
  fs::permissions(dir + "/locked", fs::perms::owner_read | fs::perms::owner_exec);
  r = run_offsetgen({"mesh", "--surface", "gyroid", "--thickness", "0.1", "-o", dir + "/locked/part.stl"});
  if (::geteuid() != 0) {  // root writes anywhere
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("not writable"), std::string::npos) << r.output;
  }
  fs::permissions(dir + "/locked", fs::perms::owner_all);
}

TEST(MeshOutput, SameInputsGiveTheSameBytesAndPlyMatchesStl) {
  const std::string dir = scratch_dir("determinism");
  const std::vector<std::string> base = {"mesh",    "--surface", "schwarzp",     "--thickness", "0.2",
                                         "--cells", "1x1x2",     "--resolution", "24"};
  auto with = [&](const std::string& out, std::vector<std::string> extra = {}) {
    std::vector<std::string> a = base;
    a.insert(a.end(), {"-o", out});
    a.insert(a.end(), extra.begin(), extra.end());
    return run_offsetgen(a);
  };
  ASSERT_EQ(with(dir + "/a.stl", {"--threads", "1"}).exit_code, 0);
  ASSERT_EQ(with(dir + "/b.stl", {"--threads", "2"}).exit_code, 0);
  CliRun ply = with(dir + "/c.ply");
  ASSERT_EQ(ply.exit_code, 0) << ply.output;
  std::ifstream a(dir + "/a.stl", std::ios::binary), b(dir + "/b.stl", std::ios::binary);
  std::string sa((std::istreambuf_iterator<char>(a)), {}), sb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_EQ(sa, sb);
  EXPECT_NE(ply.output.find("binary PLY"), std::string::npos);
  EXPECT_LT(fs::file_size(dir + "/c.ply"), fs::file_size(dir + "/a.stl"));
  CliRun adaptive = with(dir + "/d.stl", {"--adaptivity", "0.5"});
  ASSERT_EQ(adaptive.exit_code, 0) << adaptive.output;
  EXPECT_LT(fs::file_size(dir + "/d.stl"), fs::file_size(dir + "/a.stl"));
  auto report = admesh_report(dir + "/d.stl");
  EXPECT_EQ(report["facets added"], 0);
  EXPECT_EQ(report["backwards edges"], 0);
  EXPECT_EQ(report["disconnected facets"], 0);
}

// -o part.3mf: a 3MF package (a zip) holding the same triangles as the STL, in millimetres, with the
// same bytes on every run (lib3mf's random UUIDs are replaced by ones derived from the mesh).
// Read back with Python's zipfile, an independent reader.
TEST(MeshOutput, ThreeMfHoldsTheStlsTrianglesInMillimetresWithTheSameBytesEachRun) {
  if (!can_write_3mf())
    GTEST_FAIL()
        << "offsetgen was built without lib3mf: apt-get install lib3mf-dev (tools/install_deps.sh), then reconfigure";
  const std::string dir = scratch_dir("threemf");
  const std::vector<std::string> base = {"mesh", "--surface", "gyroid", "--thickness", "0.15", "--resolution", "24"};
  auto with = [&](const std::string& out) {
    std::vector<std::string> a = base;
    a.insert(a.end(), {"-o", out});
    return run_offsetgen(a);
  };
  CliRun first = with(dir + "/a.3mf");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("(3MF,"), std::string::npos) << first.output;
  ASSERT_EQ(with(dir + "/b.3mf").exit_code, 0);
  ASSERT_EQ(with(dir + "/c.stl").exit_code, 0);
  std::ifstream a(dir + "/a.3mf", std::ios::binary), b(dir + "/b.3mf", std::ios::binary);
  std::string sa((std::istreambuf_iterator<char>(a)), {}), sb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_EQ(sa, sb);
  ASSERT_GT(sa.size(), 4u);
  EXPECT_EQ(sa.substr(0, 4), std::string("PK\x03\x04", 4));
  const run::ProcessResult counted =
      run::run_process({"python3", "-c",
                        "import sys, zipfile; m = zipfile.ZipFile(sys.argv[1]).read('3D/3dmodel.model').decode(); "
                        "print(m.count('<triangle '), 'unit=\"millimeter\"' in m)",
                        dir + "/a.3mf"});
  ASSERT_EQ(counted.exit_code, 0) << counted.output;
  const size_t triangles = read_stl(dir + "/c.stl").size();
  EXPECT_EQ(counted.output, fmt::format("{} True\n", triangles));
}

// Only meshing loads OpenVDB and TBB: offsetgen execs offsetgen-mesh for `mesh`, so generate, list
// and --version do not pay their start-up.
TEST(MeshExecutable, OnlyOffsetgenMeshLinksOpenVdbAndTbb) {
  const std::string plain = test_support::shared_libraries(OFFSETGEN_EXE);
  EXPECT_EQ(plain.find("libopenvdb"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("libtbb"), std::string::npos) << plain;
  const std::string mesher = test_support::shared_libraries(OFFSETGEN_MESH_EXE);
  EXPECT_NE(mesher.find("libopenvdb"), std::string::npos) << mesher;
}

TEST(MeshExecutable, WithoutOffsetgenMeshBesideItMeshSaysItIsMissingAndExits3) {
  test_support::expect_a_missing_sibling_exits_3("mesh", OFFSETGEN_MESH_EXE,
                                                 {"--surface", "gyroid", "--thickness", "0.1"}, "part.stl");
}

}  // namespace
}  // namespace offsetgen::mesh::testing
