// `offsetgen step` as a user runs it. The file it writes is read back here with OpenCASCADE and
// checked independently of the tool's own summary: one valid closed solid, its volume against the
// exact wall volume (column quadrature of this process's own wall functions), the distance of exact
// wall points (other lines than the tool's) to its faces. Bad input exits 2 and writes nothing; a
// tolerance out of reach exits 1 and writes nothing.
#include "check/volume_fraction.h"
#include "mesh/wall_field.h"
#include "run/process.h"
#include "step/deviation.h"
#include "step/step_file.h"
#include "step/wall_brep.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace offsetgen::step {
namespace {
namespace fs = std::filesystem;

std::string scratch_dir(const std::string& name) {
  fs::path dir = fs::path(OFFSETGEN_STEP_TEST_TMP) / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

run::ProcessResult run_offsetgen(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {OFFSETGEN_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  return run::run_process(argv);
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

constexpr double kThickness = 0.1, kCellSize = 10, kTolerance = 0.01;

// One Schwarz P cell, written once for the tests below.
struct Written {
  std::string path;
  run::ProcessResult run;
};
const Written& one_cell() {
  static const Written w = [] {
    Written out;
    out.path = scratch_dir("one_cell") + "/p.step";
    out.run = run_offsetgen({"step", "--surface", "schwarzp", "--thickness", "0.1", "--cells", "1", "--cell-size", "10",
                             "--tolerance", "0.01", "-o", out.path});
    return out;
  }();
  return w;
}

struct Walls {
  Walls()
      : field([] {
          mesh::WallRequest r;
          r.generation.surface = "schwarzp";
          r.thickness = "0.1";
          return r;
        }()) {
    field.compile();
  }
  LevelFunction sheet(double h) const {
    return [this, h](size_t n, const double* x, const double* y, const double* z, double* out) {
      const std::vector<double> hs(n, h);
      field.offsets(n, x, y, z, hs.data(), out);
    };
  }
  mesh::WallField field;
};

TEST(StepCli, SchwarzPCellIsOneValidClosedSolid) {
  const Written& w = one_cell();
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const ShapeCheck c = check_shape(read_step(w.path));
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.solids, 1);
  EXPECT_EQ(c.shells, 1);
  EXPECT_TRUE(c.closed);
  EXPECT_NE(read_bytes(w.path).find("MANIFOLD_SOLID_BREP"), std::string::npos);
}

TEST(StepCli, SchwarzPCellVolumeIsWithinAThousandthOfTheExactWallVolume) {
  const Written& w = one_cell();
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const ShapeCheck c = check_shape(read_step(w.path));
  Walls walls;
  mesh::WallField::Worker worker(walls.field);
  check::VolumeFractionSetup v;
  v.g = [&](const double* p) {
    double value = 0;
    walls.field.walls(1, p, p + 1, p + 2, &value, worker);
    return value;
  };
  v.field = [&](const double* p) { return walls.field.field(p[0], p[1], p[2]); };
  v.field_slope_bound = walls.field.field_lipschitz();
  v.band = walls.field.field_lipschitz() * 0.5 * kThickness * (1 + 1e-9);
  v.scan_step = kThickness / 4;
  check::VolumeFractionOptions options;
  options.seed = 7;  // not the tool's
  const check::VolumeFraction exact = check::measure_volume_fraction(v, options);
  const double exact_volume = exact.value * std::pow(kCellSize, 3);
  EXPECT_LT(exact.standard_error / exact.value, 1e-4);
  EXPECT_NEAR(c.volume, exact_volume, 1e-3 * exact_volume);
}

TEST(StepCli, SchwarzPCellExactWallsLieWithinTheToleranceOfItsFaces) {
  const Written& w = one_cell();
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const TopoDS_Shape shape = read_step(w.path);
  Walls walls;
  for (double h : {0.5 * kThickness, -0.5 * kThickness}) {
    // Other lines than the tool's (another seed, another density).
    const std::vector<Point> points = exact_surface_points(walls.sheet(h), {1, 1, 1}, 17, 64, 99);
    ASSERT_GT(points.size(), 500u);
    const Deviation d = measure_deviation(shape, points, kCellSize, 1.0);
    EXPECT_LE(d.max, kTolerance) << "h = " << h;
    EXPECT_GT(d.max, 0.0);  // a fitted surface is not the exact one
  }
}

TEST(StepCheck, AFileOfOffsetgenStepPassesWithItsMeasuresAndExit0) {
  ASSERT_EQ(one_cell().run.exit_code, 0) << one_cell().run.output;
  const run::ProcessResult r = run_offsetgen({"check", one_cell().path});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* line :
       {"PASS  solid: valid (BRepCheck_Analyzer), 1 solid, one closed shell", "PASS  deviation of the exact walls",
        "PASS  volume", "96 B-spline, 6 planar", "offsetgen check: all checks passed"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
}

// A control point moved by 2 mm: the file still reads, but no longer matches the walls its header names.
TEST(StepCheck, AMovedControlPointFailsWithExit1) {
  ASSERT_EQ(one_cell().run.exit_code, 0) << one_cell().run.output;
  std::string text = read_bytes(one_cell().path);
  size_t at = 0;
  for (int k = 0; k < 1200; ++k) at = text.find("CARTESIAN_POINT('',(", at + 1);
  ASSERT_NE(at, std::string::npos);
  const size_t x = at + std::string("CARTESIAN_POINT('',(").size();
  const size_t comma = text.find(',', x);
  text.replace(x, comma - x, std::to_string(std::stod(text.substr(x, comma - x)) + 2.0));
  const std::string moved = scratch_dir("moved") + "/moved.step";
  std::ofstream(moved, std::ios::binary) << text;
  const run::ProcessResult r = run_offsetgen({"check", moved});
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("FAILED"), std::string::npos) << r.output;
}

TEST(StepCheck, AStepFileWithoutOffsetgenMetadataIsRefusedWithExit2) {
  ASSERT_EQ(one_cell().run.exit_code, 0) << one_cell().run.output;
  std::string text = read_bytes(one_cell().path);
  const size_t at = text.find("offsetgen-metadata");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("offsetgen-metadata").size(), "some-other-program");
  const std::string foreign = scratch_dir("foreign") + "/foreign.stp";
  std::ofstream(foreign, std::ios::binary) << text;
  const run::ProcessResult r = run_offsetgen({"check", foreign});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no offsetgen-metadata in its header"), std::string::npos) << r.output;
}

TEST(StepCli, SameInputsWriteTheSameBytes) {
  const Written& w = one_cell();
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const std::string again = scratch_dir("again") + "/p.step";
  const run::ProcessResult r = run_offsetgen({"step", "--surface", "schwarzp", "--thickness", "0.1", "--cells", "1",
                                              "--cell-size", "10", "--tolerance", "0.01", "-o", again, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_bytes(again), read_bytes(w.path));
}

TEST(StepExecutable, OnlyOffsetgenStepLinksOpenCascade) {
  const run::ProcessResult plain = run::run_process({"ldd", OFFSETGEN_EXE});
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find("libTKernel"), std::string::npos) << plain.output;
  const run::ProcessResult step = run::run_process({"ldd", OFFSETGEN_STEP_EXE});
  ASSERT_EQ(step.exit_code, 0) << step.output;
  EXPECT_NE(step.output.find("libTKernel"), std::string::npos) << step.output;
}

TEST(StepExecutable, WithoutOffsetgenStepBesideItStepSaysItIsMissingAndExits3) {
  const std::string dir = scratch_dir("lone-offsetgen");
  const std::string lone = dir + "/offsetgen";
  fs::copy_file(OFFSETGEN_EXE, lone);
  const run::ProcessResult r =
      run::run_process({lone, "step", "--surface", "schwarzp", "--thickness", "0.1", "-o", dir + "/p.step"});
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find(dir + "/" + fs::path(OFFSETGEN_STEP_EXE).filename().string() + ", which is missing"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir + "/p.step"));
  // Its help and usage errors still come from offsetgen itself.
  const run::ProcessResult help = run::run_process({lone, "step", "--help"});
  EXPECT_EQ(help.exit_code, 0) << help.output;
  EXPECT_NE(help.output.find("Usage: offsetgen step [OPTIONS]"), std::string::npos) << help.output;
  EXPECT_EQ(run::run_process({lone, "step", "--bogus"}).exit_code, 2);
}

struct Refusal {
  std::string name;
  std::vector<std::string> args;
  int exit_code;
  std::string says;
};
void PrintTo(const Refusal& r, std::ostream* os) { *os << r.name; }

class StepRefuses : public ::testing::TestWithParam<Refusal> {};

TEST_P(StepRefuses, WithItsExitCodeAReasonAndNoFile) {
  const Refusal& r = GetParam();
  const std::string out = scratch_dir("refused_" + r.name) + "/p.step";
  auto given = [&r](const std::string& option) {
    return std::find(r.args.begin(), r.args.end(), option) != r.args.end();
  };
  std::vector<std::string> args = {"step", "--cell-size", "10"};
  if (!given("--cells")) args.insert(args.end(), {"--cells", "1"});
  if (!given("-o")) args.insert(args.end(), {"-o", out});
  args.insert(args.end(), r.args.begin(), r.args.end());
  const run::ProcessResult run = run_offsetgen(args);
  EXPECT_EQ(run.exit_code, r.exit_code) << run.output;
  EXPECT_NE(run.output.find(r.says), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(fs::path(out).parent_path())) << "no temporary left behind";
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, StepRefuses,
    ::testing::Values(
        Refusal{
            "gyroid", {"--surface", "gyroid", "--thickness", "0.1", "--tolerance", "0.01"}, 2, "gyroid' is refused"},
        Refusal{"user_expression",
                {"--expr", "cos(2*Pi*x)+cos(2*Pi*y)+cos(2*Pi*z)", "--name", "p", "--thickness", "0.1", "--tolerance",
                 "0.01"},
                2,
                "--expr surfaces are refused"},
        Refusal{
            "zero_tolerance", {"--surface", "schwarzp", "--thickness", "0.1", "--tolerance", "0"}, 2, "--tolerance"},
        Refusal{"negative_tolerance",
                {"--surface", "schwarzp", "--thickness", "0.1", "--tolerance", "-0.01"},
                2,
                "--tolerance"},
        Refusal{"beyond_curvature_limit",
                {"--surface", "schwarzp", "--thickness", "0.6", "--tolerance", "0.01"},
                2,
                "curvature limit"},
        Refusal{"zero_cells",
                {"--surface", "schwarzp", "--thickness", "0.1", "--cells", "2x0"},
                2,
                "not a positive number of cells"},
        Refusal{"not_a_step_name", {"--surface", "schwarzp", "--thickness", "0.1", "-o", "p.stl"}, 2, "end in .step"},
        Refusal{"missing_directory",
                {"--surface", "schwarzp", "--thickness", "0.1", "--tolerance", "0.01", "-o", "/nonexistent/dir/p.step"},
                2,
                "/nonexistent/dir"},
        Refusal{"graded",
                {"--surface", "schwarzp", "--thickness", "0.05 + 0.05*x", "--tolerance", "0.01"},
                2,
                "graded thickness"},
        // A tolerance that 4 x 4 control points cannot reach: measured, exit 1, nothing written.
        Refusal{"tolerance_out_of_reach",
                {"--surface", "schwarzp", "--thickness", "0.1", "--tolerance", "1e-5", "--max-control-points", "4"},
                1,
                "exceeds --tolerance"}),
    [](const ::testing::TestParamInfo<Refusal>& r) { return r.param.name; });

}  // namespace
}  // namespace offsetgen::step
