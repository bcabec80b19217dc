// `offsetgen step` as a user runs it. The file it writes is read back here with OpenCASCADE and
// checked independently of the tool's own summary: valid closed solids, its volume against the
// exact wall volume (column quadrature of this process's own wall functions), the distance of exact
// wall points (other lines than the tool's) to its faces. Bad input exits 2 and writes nothing; a
// tolerance out of reach exits 1 and writes nothing.
#include "step/deviation.h"
#include "step/step_file.h"
#include "step/symmetry_patch.h"
#include "step/wall_brep.h"
#include "wall/wall_field.h"

#include "exact_wall_volume.h"
#include "offsetgen_test_support.h"
#include "sibling_executable.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace offsetgen::step {
namespace {
namespace fs = std::filesystem;

// The runners every test folder shares (tests/support).
using test_support::run_offsetgen;
using test_support::scratch_dir;
std::string read_bytes(const std::string& path) { return test_support::read_file(path); }

constexpr double kCellSize = 10, kTolerance = 0.01;
const Point kCellMm{kCellSize, kCellSize, kCellSize};

// The cell each surface's tests write: a thickness its patch layout covers (Neovius' and F-RD's
// curvature limits are 0.106 and 0.107 cell: at 0.1 their offset sheets fold across the patch lines),
// and what offsetgen check says of its solids and faces (diamond: the wall and two corner tetrahedra).
struct CellCase {
  std::string thickness;
  std::string solids, faces;
  int quadrature_grid = 40;  // the exact volume's columns per side: more where the wall is thin and curved
};
const CellCase& cell_case(const std::string& surface) {
  static const std::map<std::string, CellCase> cases = {
      {"schwarzp", {"0.1", "1 solid (1 expected)", "96 B-spline, 6 planar"}},
      // Box patches (auto's choice for diamond, docs/step.md), the surface crossing two corners.
      {"diamond", {"0.1", "3 solids (3 expected)", "160 B-spline, 30 planar"}},
      {"neovius", {"0.05", "1 solid (1 expected)", "96 B-spline, 24 planar", 80}},
      {"iwp", {"0.1", "1 solid (1 expected)", "96 B-spline, 24 planar"}},
      {"frd", {"0.05", "1 solid (1 expected)", "384 B-spline, 24 planar", 80}},
      // Box patches: 64 pieces per sheet in the quarter-cell boxes; the surface crosses two corners.
      {"gyroid", {"0.1", "3 solids (3 expected)", "128 B-spline, 30 planar"}},
  };
  return cases.at(surface);
}

// One cell of a surface, written once for the tests below.
struct Written {
  std::string path;
  test_support::CommandResult run;
};
const Written& one_cell(const std::string& surface = "schwarzp") {
  static std::map<std::string, Written> written;
  auto it = written.find(surface);
  if (it == written.end()) {
    Written out;
    out.path = scratch_dir("one_cell_" + surface) + "/p.step";
    out.run = run_offsetgen({"step", "--surface", surface, "--thickness", cell_case(surface).thickness, "--cells", "1",
                             "--cell-size", "10", "--tolerance", "0.01", "-o", out.path});
    it = written.emplace(surface, out).first;
  }
  return it->second;
}

// The walls a file should hold, from this process's own generated functions.
struct Walls {
  explicit Walls(const std::string& surface, const std::string& thickness = "0.1")
      : field([&] {
          wall::WallRequest r;
          r.generation.surface = surface;
          r.thickness = thickness;
          return r;
        }()),
        worker(field) {
    field.compile();
  }
  // The sheet phi(p, side t(p) / 2) = 0, side +1 or -1.
  LevelFunction sheet(double side) {
    return [this, side](size_t n, const double* x, const double* y, const double* z, double* out) {
      std::vector<double> hs(n);
      for (size_t i = 0; i < n; ++i) hs[i] = side * 0.5 * field.thickness_at(x[i], y[i], z[i], worker);
      field.offsets(n, x, y, z, hs.data(), out);
    };
  }
  wall::WallField field;
  wall::WallField::Worker worker;
};

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A file read back: `solids` valid closed solids, and the exact walls (other lines than the tool's:
// another seed, another density) within the tolerance of its faces.
void expect_valid_solids_within_the_tolerance(const TopoDS_Shape& shape, const std::string& surface,
                                              const std::string& thickness, const std::array<int, 3>& cells,
                                              int solids) {
  const ShapeCheck c = check_shape(shape);
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.solids, solids);
  EXPECT_TRUE(c.closed);
  Walls walls(surface, thickness);
  for (double side : {1.0, -1.0}) {
    const std::vector<Point> points = exact_surface_points(walls.sheet(side), cells, 17, 64, 99);
    ASSERT_GT(points.size(), 500u * cells[0] * cells[1] * cells[2]);
    const Deviation d = measure_deviation(shape, points, kCellMm, 1.0);
    EXPECT_LE(d.max, kTolerance) << "side " << side;
  }
}

TEST(StepCli, SchwarzPCellIsOneValidClosedSolid) {
  const Written& w = one_cell();
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const ShapeCheck c = check_shape(read_step(w.path));
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.solids, 1);
  EXPECT_EQ(c.shells, 1);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(count_of(read_bytes(w.path), "MANIFOLD_SOLID_BREP"), 1u);
}

TEST(StepCli, DiamondCellIsThreeValidClosedSolidsTwoOfThemItsCornerTetrahedra) {
  // The diamond surface passes through the cube's corners with normal (1, 1, 1): at (0, 0, 0) and at
  // (1, 1, 1) the block keeps only a tetrahedron of the wall, x + y + z < sqrt(3) t / 2 (legs
  // 0.866 mm, 0.108 mm^3 for t = 1 mm), cut off from the rest.
  const Written& w = one_cell("diamond");
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const TopoDS_Shape shape = read_step(w.path);
  const ShapeCheck c = check_shape(shape);
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.solids, 3);
  EXPECT_EQ(c.shells, 3);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(count_of(read_bytes(w.path), "MANIFOLD_SOLID_BREP"), 3u);
  std::vector<double> volumes;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) volumes.push_back(check_shape(e.Current()).volume);
  std::sort(volumes.begin(), volumes.end());
  ASSERT_EQ(volumes.size(), 3u);
  const double corner = std::pow(std::sqrt(3.0) * 0.5, 3) / 6;
  EXPECT_NEAR(volumes[0], corner, 0.05 * corner);
  EXPECT_NEAR(volumes[1], corner, 0.05 * corner);
  EXPECT_GT(volumes[2], 300.0);
}

class StepCell : public ::testing::TestWithParam<std::string> {};

TEST_P(StepCell, VolumeIsWithinAThousandthOfTheExactWallVolume) {
  const Written& w = one_cell(GetParam());
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const ShapeCheck c = check_shape(read_step(w.path));
  const CellCase& cell = cell_case(GetParam());
  const test_support::ExactWallVolume exact =
      test_support::exact_wall_volume(GetParam(), cell.thickness, {1, 1, 1}, kCellSize, cell.quadrature_grid);
  EXPECT_LT(exact.standard_error / exact.volume, 1e-4);
  EXPECT_NEAR(c.volume, exact.volume, 1e-3 * exact.volume);
}

TEST_P(StepCell, ExactWallsLieWithinTheToleranceOfItsFaces) {
  const Written& w = one_cell(GetParam());
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const TopoDS_Shape shape = read_step(w.path);
  Walls walls(GetParam(), cell_case(GetParam()).thickness);
  for (double side : {1.0, -1.0}) {
    // Other lines than the tool's (another seed, another density).
    const std::vector<Point> points = exact_surface_points(walls.sheet(side), {1, 1, 1}, 17, 64, 99);
    ASSERT_GT(points.size(), 500u);
    const Deviation d = measure_deviation(shape, points, kCellMm, 1.0);
    EXPECT_LE(d.max, kTolerance) << "side " << side;
    EXPECT_GT(d.max, 0.0);  // a fitted surface is not the exact one
  }
}

// The solid's volume as a summary prints it ("volume: 1234.567890 mm^3"), or NaN.
double printed_volume(const std::string& output) {
  const size_t at = output.find("volume: ");
  return at == std::string::npos ? std::nan("") : std::strtod(output.c_str() + at + 8, nullptr);
}

// The export measures the solid it writes in memory; check reads the file back (with OpenCASCADE's
// shape healing) and measures again: the same B-rep, so the same volume to a ten-thousandth (the
// healing moves the gyroid's box patches' volume by 2e-5, diamond's by 4e-6).
TEST_P(StepCell, OffsetgenCheckPassesItsFileWithExit0AndMeasuresTheExportsVolume) {
  const Written& w = one_cell(GetParam());
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const test_support::CommandResult r = run_offsetgen({"check", w.path});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string& solids = cell_case(GetParam()).solids;
  const std::string& faces = cell_case(GetParam()).faces;
  for (const std::string& line :
       {"PASS  solid: valid (BRepCheck_Analyzer), " + solids, std::string("PASS  deviation of the exact walls"),
        std::string("PASS  volume"), faces, std::string("offsetgen check: all checks passed")})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
  const double exported = printed_volume(w.run.output), read_back = printed_volume(r.output);
  EXPECT_NEAR(read_back, exported, 1e-4 * exported) << w.run.output << r.output;
}

INSTANTIATE_TEST_SUITE_P(Surfaces, StepCell,
                         ::testing::Values("schwarzp", "diamond", "neovius", "iwp", "frd", "gyroid"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// `offsetgen step` of a wall from 0.5 mm to 1.5 mm along x over 2x1x1 cells of 10 mm.
constexpr const char* kGraded = "0.05 + 0.05*x";
test_support::CommandResult step_graded(const std::string& surface, const std::string& path) {
  return run_offsetgen({"step", "--surface", surface, "--thickness", kGraded, "--cells", "2x1x1", "--cell-size", "10",
                        "--tolerance", "0.01", "-o", path});
}

// A wall from 0.5 mm to 1.5 mm along x over two cells: the symmetry is gone, every one of the 96
// tetrahedra per sheet is fitted where it lies, and the file passes the same checks.
TEST(StepCli, GradedSchwarzPWallIsOneValidSolidWithinTheToleranceAndPassesCheck) {
  const std::string thickness = kGraded;
  const std::string path = scratch_dir("graded") + "/graded.step";
  const test_support::CommandResult r = step_graded("schwarzp", path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("each image fitted on its own (graded)"), std::string::npos) << r.output;
  const TopoDS_Shape shape = read_step(path);
  expect_valid_solids_within_the_tolerance(shape, "schwarzp", thickness, {2, 1, 1}, 1);
  // The cell at x in [0, 1] (t from 0.5 to 1 mm) holds less wall than the one at [1, 2] (1 to 1.5 mm):
  // the solid is graded, not a uniform wall.
  auto volume_in_cell = [&shape](double x0) {
    const TopoDS_Shape cell = BRepPrimAPI_MakeBox(gp_Pnt(x0, 0, 0), 10, 10, 10).Shape();
    return check_shape(BRepAlgoAPI_Common(shape, cell).Shape()).volume;
  };
  const double thin = volume_in_cell(0), thick = volume_in_cell(10);
  EXPECT_GT(thick, 1.5 * thin) << thin << " mm^3 and " << thick << " mm^3";
  const test_support::CommandResult checked = run_offsetgen({"check", path});
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("t = 0.05 + 0.05*x cell (0.5 to 1.5 mm in the block)"), std::string::npos)
      << checked.output;
  EXPECT_NE(checked.output.find("PASS  volume"), std::string::npos) << checked.output;
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
  const test_support::CommandResult r = run_offsetgen({"check", moved});
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
  const test_support::CommandResult r = run_offsetgen({"check", foreign});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no offsetgen-metadata in its header"), std::string::npos) << r.output;
}

TEST(StepCli, HelpNamesEverySurfaceThatHasAPatchLayout) {
  const test_support::CommandResult r = run_offsetgen(std::vector<std::string>{"step", "--help"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("by symmetry patches (" + patch_layout_surfaces() + ")"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("by box patches (gyroid, fischerkoch, splitp, lidinoid)"), std::string::npos) << r.output;
}

// Diamond's symmetry patches, asked for (auto takes box patches for diamond): another cut of the same
// wall, whose faces share their edges exactly, which passes the same checks (the wall and its two
// corner tetrahedra).
TEST(StepCli, DiamondCellBySymmetryPatchesIsThreeValidSolidsWithinTheToleranceAndPassesCheck) {
  const std::string path = scratch_dir("diamond_symmetry") + "/d.step";
  const test_support::CommandResult r =
      run_offsetgen({"step", "--surface", "diamond", "--thickness", "0.1", "--cells", "1", "--cell-size", "10",
                     "--tolerance", "0.01", "--patches", "symmetry", "-o", path});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("336 B-spline (bicubic, 6x6 control points per symmetry patch)"), std::string::npos)
      << r.output;
  expect_valid_solids_within_the_tolerance(read_step(path), "diamond", "0.1", {1, 1, 1}, 3);
  const test_support::CommandResult checked = run_offsetgen({"check", path});
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
}

// A user's expression (here Schwarz P shifted by a parameter) by box patches: the file's header
// carries the expression, its name and parameters, and check builds the same walls from them.
TEST(StepCli, UserExpressionByBoxPatchesIsValidWithinTheToleranceAndPassesCheck) {
  const std::string path = scratch_dir("expression") + "/e.step";
  const test_support::CommandResult r =
      run_offsetgen({"step", "--expr", "cos(2*Pi*x)+cos(2*Pi*y)+cos(2*Pi*z)-c", "--param", "c=0.3", "--name", "pc",
                     "--thickness", "0.1", "--cells", "1", "--cell-size", "10", "--tolerance", "0.01", "-o", path});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("per box patch"), std::string::npos) << r.output;
  const test_support::CommandResult checked = run_offsetgen({"check", path});
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("pc (F = cos(2*Pi*x)+cos(2*Pi*y)+cos(2*Pi*z)-c) wall"), std::string::npos)
      << checked.output;
  EXPECT_NE(checked.output.find("PASS  volume"), std::string::npos) << checked.output;
}

// A gyroid wall from 0.5 mm to 1.5 mm along x over two cells, by box patches: each piece is fitted
// where it lies anyway, and the file passes the same checks.
TEST(StepCli, GradedGyroidWallOfBoxPatchesIsValidWithinTheToleranceAndPassesCheck) {
  const std::string path = scratch_dir("graded_gyroid") + "/graded.step";
  const test_support::CommandResult r = step_graded("gyroid", path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_valid_solids_within_the_tolerance(read_step(path), "gyroid", kGraded, {2, 1, 1}, 3);
  const test_support::CommandResult checked = run_offsetgen({"check", path});
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("PASS  volume"), std::string::npos) << checked.output;
}

// Same inputs, same bytes: symmetry patches (Schwarz P) and box patches (the gyroid, fitted on every
// core: which thread fits a patch does not change it).
class StepSameBytes : public ::testing::TestWithParam<std::string> {};

TEST_P(StepSameBytes, SameInputsWriteTheSameBytes) {
  const Written& w = one_cell(GetParam());
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const std::string again = scratch_dir("again_" + GetParam()) + "/p.step";
  const test_support::CommandResult r =
      run_offsetgen({"step", "--surface", GetParam(), "--thickness", cell_case(GetParam()).thickness, "--cells", "1",
                     "--cell-size", "10", "--tolerance", "0.01", "-o", again, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_bytes(again), read_bytes(w.path));
}

INSTANTIATE_TEST_SUITE_P(Routes, StepSameBytes, ::testing::Values("schwarzp", "gyroid"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// Box cells ("distorted cells", --cell-size X,Y,Z): the walls of the composed field
// G(x) = F(x/X, y/Y, z/Z), --thickness mm thick along the physical normal, from this process's own
// functions. sheet() takes cell units, as exact_surface_points gives them.
struct BoxCellWalls {
  BoxCellWalls(const std::string& surface, const std::string& thickness, const std::array<int, 3>& cells,
               const Point& sides)
      : cell(sides), field([&] {
          wall::WallRequest r;
          r.generation.surface = surface;
          r.generation.map = fmt::format("x/{}; y/{}; z/{}", sides[0], sides[1], sides[2]);
          r.generation.domain =
              Surface::Box{{0, 0, 0}, {cells[0] * sides[0], cells[1] * sides[1], cells[2] * sides[2]}};
          r.thickness = thickness;
          return r;
        }()) {
    field.compile();
  }
  LevelFunction sheet(double side) {
    return [this, side](size_t n, const double* x, const double* y, const double* z, double* out) {
      wall::WallField::Worker worker(field);
      std::vector<double> mx(n), my(n), mz(n), hs(n);
      for (size_t i = 0; i < n; ++i) {
        mx[i] = x[i] * cell[0];
        my[i] = y[i] * cell[1];
        mz[i] = z[i] * cell[2];
        hs[i] = side * 0.5 * field.thickness_at(mx[i], my[i], mz[i], worker);
      }
      field.offsets(n, mx.data(), my.data(), mz.data(), hs.data(), out);
    };
  }
  Point cell;
  wall::WallField field;
};

// A gyroid cell of 10 x 10 x 15 mm with a wall graded from 0.75 to 1.25 mm along x (mm, along the
// physical normal): valid closed solids filling the box cell, the exact walls of the composed field
// (other lines than the tool's) within the tolerance of its faces, and offsetgen check rebuilds the
// same walls from the file's header and passes it. (Uniform box-cell walls: the slow blocks read back
// by occt-draw and FreeCAD, tests/step/CMakeLists.txt.)
constexpr const char* kGradedMm = "0.75 + 0.05*x";
TEST(StepBoxCells, AGyroidBoxCellWithAGradedMillimetreWallIsValidWithinTheToleranceAndPassesCheck) {
  const std::string path = scratch_dir("box_cell") + "/g.step";
  const test_support::CommandResult r =
      run_offsetgen({"step", "--surface", "gyroid", "--thickness", kGradedMm, "--cells", "1", "--cell-size", "10,10,15",
                     "--tolerance", "0.01", "-o", path});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("t = 0.75 + 0.05*x mm (0.75 to 1.25 mm in the block, along the physical normal"),
            std::string::npos)
      << r.output;
  const TopoDS_Shape shape = read_step(path);
  const ShapeCheck c = check_shape(shape);
  EXPECT_TRUE(c.valid);
  EXPECT_TRUE(c.closed);
  EXPECT_GE(c.solids, 1);
  // The caps lie on the block's faces: its vertices span the box cell.
  Point lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (TopExp_Explorer e(shape, TopAbs_VERTEX); e.More(); e.Next()) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(e.Current()));
    for (int a = 0; a < 3; ++a) {
      lo[size_t(a)] = std::min(lo[size_t(a)], p.Coord(a + 1));
      hi[size_t(a)] = std::max(hi[size_t(a)], p.Coord(a + 1));
    }
  }
  const Point sides{10, 10, 15};
  for (size_t a = 0; a < 3; ++a) {
    EXPECT_NEAR(lo[a], 0, 1e-6) << "axis " << a;
    EXPECT_NEAR(hi[a], sides[a], 1e-6) << "axis " << a;
  }
  BoxCellWalls walls("gyroid", kGradedMm, {1, 1, 1}, {10, 10, 15});
  for (double side : {1.0, -1.0}) {
    const std::vector<Point> points = exact_surface_points(walls.sheet(side), {1, 1, 1}, 17, 64, 99);
    ASSERT_GT(points.size(), 500u);
    const Deviation d = measure_deviation(shape, points, walls.cell, 1.0);
    EXPECT_LE(d.max, kTolerance) << "side " << side;
  }
  const test_support::CommandResult checked = run_offsetgen({"check", path});
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  for (const std::string line : {"t = 0.75 + 0.05*x mm (0.75 to 1.25 mm in the block, along the physical normal), "
                                 "1x1x1 cells of 10 x 10 x 15 mm",
                                 "PASS  deviation of the exact walls", "PASS  volume"})
    EXPECT_NE(checked.output.find(line), std::string::npos) << line << "\n" << checked.output;
}

// Three equal sides are a cube cell: the wall in cell units and today's file, byte for byte.
TEST(StepBoxCells, ThreeEqualSidesWriteTheSameBytesAsOneCellSize) {
  const Written& w = one_cell("schwarzp");
  ASSERT_EQ(w.run.exit_code, 0) << w.run.output;
  const std::string path = scratch_dir("equal_sides") + "/p.step";
  const test_support::CommandResult r =
      run_offsetgen({"step", "--surface", "schwarzp", "--thickness", cell_case("schwarzp").thickness, "--cells", "1",
                     "--cell-size", "10,10,10", "--tolerance", "0.01", "-o", path, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_bytes(path), read_bytes(w.path));
}

TEST(StepExecutable, OnlyOffsetgenStepLinksOpenCascade) {
  const std::string plain = test_support::shared_libraries(OFFSETGEN_EXE);
  EXPECT_EQ(plain.find("libTKernel"), std::string::npos) << plain;
  const std::string step = test_support::shared_libraries(OFFSETGEN_STEP_EXE);
  EXPECT_NE(step.find("libTKernel"), std::string::npos) << step;
}

TEST(StepExecutable, WithoutOffsetgenStepBesideItStepSaysItIsMissingAndExits3) {
  test_support::expect_a_missing_sibling_exits_3("step", OFFSETGEN_STEP_EXE,
                                                 {"--surface", "schwarzp", "--thickness", "0.1"}, "p.step");
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
  std::vector<std::string> args = {"step"};
  if (!given("--cell-size")) args.insert(args.end(), {"--cell-size", "10"});
  if (!given("--cells")) args.insert(args.end(), {"--cells", "1"});
  if (!given("-o")) args.insert(args.end(), {"-o", out});
  args.insert(args.end(), r.args.begin(), r.args.end());
  const test_support::CommandResult run = run_offsetgen(args);
  EXPECT_EQ(run.exit_code, r.exit_code) << run.output;
  EXPECT_NE(run.output.find(r.says), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(fs::path(out).parent_path())) << "no temporary left behind";
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, StepRefuses,
    ::testing::Values(
        Refusal{"symmetry_patches_of_the_gyroid",
                {"--surface", "gyroid", "--thickness", "0.1", "--tolerance", "0.01", "--patches", "symmetry"},
                2,
                "'gyroid' has no mirror planes to cut it into symmetry patches"},
        Refusal{"lidinoid_whose_pieces_turn_too_far_for_the_boxes",
                {"--surface", "lidinoid", "--thickness", "0.05", "--tolerance", "0.01"},
                2,
                "cannot cut this wall into boxes down to 1/16 cell"},
        Refusal{"neovius_beyond_its_patch_layout",
                {"--surface", "neovius", "--thickness", "0.1", "--tolerance", "0.01"},
                2,
                "not the graph the patch layout needs"},
        Refusal{"diamond_whose_pieces_turn_too_far_for_the_boxes",
                {"--surface", "diamond", "--thickness", "0.3", "--tolerance", "0.01"},
                2,
                "cannot cut this wall into boxes down to 1/16 cell"},
        Refusal{"diamond_beyond_its_patch_layout",
                {"--surface", "diamond", "--thickness", "0.3", "--tolerance", "0.01", "--patches", "symmetry"},
                2,
                "not the graph the patch layout needs"},
        Refusal{"user_expression_not_periodic",
                {"--expr", "x^2+y^2+z^2-0.2", "--name", "ball", "--thickness", "0.1", "--tolerance", "0.01"},
                2,
                "needs the surface's curvature limit"},
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
        // Box cells ("distorted cells", --cell-size X,Y,Z): what they do not cover, and bad sizes.
        Refusal{"density_with_a_box_cell",
                {"--surface", "schwarzp", "--density", "0.2", "--cell-size", "10,10,15", "--tolerance", "0.01"},
                2,
                "--density needs a cube cell"},
        Refusal{"symmetry_patches_with_a_box_cell",
                {"--surface", "schwarzp", "--thickness", "1", "--cell-size", "10,10,15", "--patches", "symmetry"},
                2,
                "--patches symmetry needs a cube cell"},
        Refusal{"box_cell_wall_beyond_its_curvature_bound",
                {"--surface", "schwarzp", "--thickness", "6", "--cell-size", "10,10,15"},
                2,
                "bounded for the box cell"},
        Refusal{"cell_size_with_a_zero_side",
                {"--surface", "schwarzp", "--thickness", "1", "--cell-size", "10,0,15"},
                2,
                "--cell-size 0 is not a positive length"},
        Refusal{"cell_size_with_a_negative_side",
                {"--surface", "schwarzp", "--thickness", "1", "--cell-size", "10,10,-15"},
                2,
                "--cell-size -15 is not a positive length"},
        Refusal{"cell_size_not_a_number",
                {"--surface", "schwarzp", "--thickness", "1", "--cell-size", "10,ten,15"},
                2,
                "expected MM (a cube cell) or X,Y,Z"},
        Refusal{"cell_size_of_two_sides",
                {"--surface", "schwarzp", "--thickness", "1", "--cell-size", "10,15"},
                2,
                "expected MM (a cube cell) or X,Y,Z"},
        Refusal{"cell_size_of_four_sides",
                {"--surface", "schwarzp", "--thickness", "1", "--cell-size", "10,10,15,15"},
                2,
                "expected MM (a cube cell) or X,Y,Z"},
        Refusal{"not_a_step_name", {"--surface", "schwarzp", "--thickness", "0.1", "-o", "p.stl"}, 2, "end in .step"},
        // The request is validated once, by the library (step_request.h), not by the CLI before it.
        Refusal{"unknown_patches",
                {"--surface", "schwarzp", "--thickness", "0.1", "--patches", "faces"},
                2,
                "--patches faces: give auto, symmetry or box"},
        Refusal{"too_few_control_points",
                {"--surface", "schwarzp", "--thickness", "0.1", "--max-control-points", "3"},
                2,
                "a cubic patch needs at least 4 a side"},
        Refusal{"neither_thickness_nor_density", {"--surface", "schwarzp"}, 2, "give one of --thickness T"},
        Refusal{"both_thickness_and_density",
                {"--surface", "schwarzp", "--thickness", "0.1", "--density", "0.2"},
                2,
                "give one of --thickness T"},
        Refusal{"missing_directory",
                {"--surface", "schwarzp", "--thickness", "0.1", "--tolerance", "0.01", "-o", "/nonexistent/dir/p.step"},
                2,
                "/nonexistent/dir"},
        Refusal{"graded_beyond_curvature_limit",
                {"--surface", "schwarzp", "--thickness", "0.1 + 0.3*x", "--cells", "2x1x1", "--tolerance", "0.01"},
                2,
                "curvature limit"},
        // A tolerance that 4 x 4 control points cannot reach: measured, exit 1, nothing written.
        Refusal{"tolerance_out_of_reach",
                {"--surface", "schwarzp", "--thickness", "0.1", "--tolerance", "1e-5", "--max-control-points", "4"},
                1,
                "exceeds --tolerance"},
        // A 0.15 mm gyroid wall within 0.01 mm everywhere, but its volume off by 0.19%: the fit's small
        // signed error over the faces is too much for so thin a wall. Exit 1, nothing written.
        Refusal{"volume_beyond_a_thousandth_on_a_thin_wall",
                {"--surface", "gyroid", "--thickness", "0.015", "--tolerance", "0.01"},
                1,
                "differs from the exact wall's"}),
    [](const ::testing::TestParamInfo<Refusal>& r) { return r.param.name; });

}  // namespace
}  // namespace offsetgen::step
