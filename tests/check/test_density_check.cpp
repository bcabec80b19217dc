// check's density stage (check/volume_fraction.h, check/density_check.h): the column integration
// against solids of known volume, then the emitted density functions measured against the rho
// asked of them: gyroid at order 4 in the fast set, the issue's five surfaces at order 6 under Slow.
#include "check/density_check.h"
#include "check_test_support.h"

#include "pipeline/generate.h"
#include "run/glsl_compile.h"
#include "run/metadata.h"
#include "run/process.h"
#include "surfaces/expression_input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

namespace offsetgen::check {
namespace {

constexpr double kPi = 3.141592653589793;

// A ball of radius 0.3 in the unit box: 4/3 pi r^3, every column a chord found by root finding.
TEST(VolumeFraction, BallIsMeasuredWithinItsStatedError) {
  numeric::VolumeFractionSetup s;
  auto ball = [](const double* p) {
    const double dx = p[0] - 0.5, dy = p[1] - 0.45, dz = p[2] - 0.52;
    return dx * dx + dy * dy + dz * dz - 0.09;
  };
  s.g = ball;
  s.field = ball;
  s.field_slope_bound = 2 * std::sqrt(3.0);
  s.band = 1e-3;
  s.outside_follows_field = true;
  s.scan_step = 1.0 / 64;
  const numeric::VolumeFraction v = numeric::measure_volume_fraction(s, {});
  const double exact = 4.0 / 3 * kPi * 0.027;
  EXPECT_LE(std::fabs(v.value - exact), 4 * v.standard_error + 1e-12) << v.value << " +- " << v.standard_error;
  EXPECT_LE(v.standard_error, 1e-4);
  EXPECT_GT(v.standard_error, 0);  // the error is measured, not assumed
}

// Thin tilted walls |sin(2 pi (x + y + z))| < s: every column meets them obliquely. Exact fraction
// (2 / pi) asin(s). (Walls parallel to an axis, e.g. |sin(2 pi (x + y))| < s, defeat the stated
// error: every column along z then lies wholly inside or outside a wall, so the shifts all see the
// same aliasing; docs/density.md.)
TEST(VolumeFraction, ThinTiltedWallsAreMeasuredWithinItsStatedError) {
  const double s_wall = 0.05;
  numeric::VolumeFractionSetup s;
  s.field = [](const double* p) { return std::sin(2 * kPi * (p[0] + p[1] + p[2])); };
  s.g = [s_wall](const double* p) { return std::fabs(std::sin(2 * kPi * (p[0] + p[1] + p[2]))) - s_wall; };
  s.field_slope_bound = 2 * kPi * std::sqrt(3.0);
  s.band = s_wall;
  s.scan_step = 1.0 / 512;
  const numeric::VolumeFraction v = numeric::measure_volume_fraction(s, {});
  const double exact = 2 / kPi * std::asin(s_wall);
  EXPECT_LE(std::fabs(v.value - exact), 4 * v.standard_error + 1e-9) << v.value << " +- " << v.standard_error;
  EXPECT_LE(v.standard_error, 1e-5);
}

struct DensityFile {
  std::string path;
  run::FileMetadata meta;
  run::CompileResult compiled;
  Generation generation;
};

std::unique_ptr<DensityFile> compile_density_file(const std::string& surface, int order, double wall_density,
                                                  const std::string& method = kDefaultMethod) {
  auto f = std::make_unique<DensityFile>();
  GenerationRequest request;
  request.surface = surface;
  request.order = order;
  request.method = method;
  request.density = wall_density;
  request.precisions = {Precision::Double, Precision::Float};
  request.command = "check_tests";
  f->generation = generate(request);
  f->path = testing::scratch_dir("density-" + method + "-" + surface + std::to_string(order)) + "/" +
            f->generation.prefix + ".h";
  testing::write_text(f->path, f->generation.c_header());
  f->meta = run::read_metadata(f->path);
  run::CompileOptions options;
  options.cxx = false;  // -O2 as check uses it: the measurement evaluates the walls millions of times
  f->compiled = run::compile_and_load(f->path, f->meta, run::find_toolchain(), options);
  return f;
}

void expect_within_tolerance(const DensityReport& r) {
  EXPECT_LE(r.max_relation_error, 1e-12) << r.worst_relation;
  EXPECT_EQ(r.nan_failures, 0) << (r.nan_failure_examples.empty() ? "" : r.nan_failure_examples[0]);
  for (const DensityRow& row : r.rows) {
    EXPECT_LE(std::fabs(row.deviation), r.tolerance) << row.solid << " rho " << row.requested << ": measured "
                                                     << row.measured.value << " +- " << row.measured.standard_error;
    EXPECT_LE(row.measured.standard_error, r.tolerance / 2) << row.solid << " " << row.requested;
  }
}

TEST(DensityCheck, GyroidOrder4SheetWallAndNetworkAtHalfMatchTheRequestedDensity) {
  auto f = compile_density_file("gyroid", 4, 0.2);
  ASSERT_TRUE(f->compiled.ok);
  DensityCheckOptions o;
  o.sheet = {0.1, 0.3};
  o.network = {0.5};
  const DensityReport r =
      measure_density(f->compiled.library->functions(), f->meta, *f->generation.density, std::nullopt, o);
  ASSERT_EQ(r.rows.size(), 4u);  // two sheets, the network, _wall
  EXPECT_EQ(r.rows.back().solid, "wall");
  expect_within_tolerance(r);
  EXPECT_TRUE(r.has_float);
  EXPECT_LE(r.max_float_relation_error, 1e-5) << r.worst_float_relation;
}

// A density field falling from 0.3 to 0.1 across three cells: each cell's volume fraction against
// the mean of rho over that cell (the column grid goes through the tent transform there).
TEST(DensityCheck, DensityFieldCellsMatchTheMeanDensityOfEachCell) {
  GenerationRequest request;
  request.surface = "gyroid";
  request.order = 4;
  request.density_field = "0.3 - 0.2*x/3";
  request.command = "check_tests";
  const Generation g = generate(request);
  const std::string path = testing::scratch_dir("density-field") + "/" + g.prefix + ".h";
  testing::write_text(path, g.c_header());
  const run::FileMetadata meta = run::read_metadata(path);
  ASSERT_TRUE(meta.density_field.has_value());
  run::CompileOptions options;
  options.cxx = false;
  const run::CompileResult compiled = run::compile_and_load(path, meta, run::find_toolchain(), options);
  ASSERT_TRUE(compiled.ok);
  DensityCheckOptions o;
  o.sheet = {};
  o.network = {};
  o.block = {3, 1, 1};
  const DensityReport r = measure_density(compiled.library->functions(), meta, *g.density,
                                          parse_thickness_expression(*meta.density_field, {}, 3), o);
  ASSERT_EQ(r.cells.size(), 3u);
  const double means[3] = {0.3 - 0.2 / 6, 0.2, 0.1 + 0.2 / 6};
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.cells[i].requested, means[i], 1e-12);
    EXPECT_LE(std::fabs(r.cells[i].deviation), r.cell_tolerance)
        << "cell " << i << ": " << r.cells[i].measured.value << " +- " << r.cells[i].measured.standard_error;
  }
}

// The density functions and _wall in GLSL: the host shader calls every one of them, and all four
// targets compile and link (NaN as intBitsToFloat, highp arguments).
TEST(DensityCheck, GlslSnippetWithDensityFunctionsCompilesForAllFourTargets) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed (glslang-tools)";
  GenerationRequest request;
  request.surface = "schwarzp";
  request.order = 2;
  request.density = 0.25;
  request.languages = {"glsl"};
  request.command = "check_tests";
  const Generation g = generate(request);
  const run::FileMetadata meta = run::parse_metadata(g.glsl_snippet());
  ASSERT_TRUE(meta.has_density);
  ASSERT_TRUE(meta.wall_density.has_value());
  const std::string host = run::glsl_host_shader(g.glsl_snippet(), meta, run::GlslTarget::Gl330, nullptr);
  for (const char* call :
       {"_wall(", "_density(q.w)", "_thickness_for_density(q.w)", "_network_density(q.w)", "_offset_for_density(q.w)"})
    EXPECT_NE(host.find(call), std::string::npos) << call;
  for (const auto& r : run::compile_glsl(g.glsl_snippet(), meta, "schwarzp_o2.glsl"))
    EXPECT_TRUE(r.ok) << r.name << "\n" << r.output;
}

// The issue's acceptance: sheets at 0.05, 0.1, 0.2, 0.3 and networks at 0.2, 0.5, 0.8 where the
// validity limit allows, within 2e-4. The networks of Schwarz P (|h| = 0.137) and I-WP (0.097 at
// rho = 0.8) lie at 86% and 93% of the focal distance, where Richardson's series converges slowly
// (order 6: -3.3e-4 and -1.1e-3; order 8: -1.6e-4 and -2.8e-3): projection at order 12 meets it on
// all five (docs/density.md).
struct AcceptanceCase {
  std::string surface;
  int grid;  // columns per side: enough for a stated error below tolerance / 2 on every row
};

// Stable test names: the case prints as its surface, not as bytes.
void PrintTo(const AcceptanceCase& c, std::ostream* os) { *os << c.surface << ", grid " << c.grid; }

class SlowDensityCheck : public ::testing::TestWithParam<AcceptanceCase> {};

TEST_P(SlowDensityCheck, ProjectionOrder12SheetsAndNetworksMatchTheRequestedDensity) {
  auto f = compile_density_file(GetParam().surface, 12, 0.1, "projection");
  ASSERT_TRUE(f->compiled.ok);
  DensityCheckOptions o;
  o.sampling.grid = GetParam().grid;
  const DensityReport r =
      measure_density(f->compiled.library->functions(), f->meta, *f->generation.density, std::nullopt, o);
  expect_within_tolerance(r);
  EXPECT_GE(r.rows.size(), 6u);  // Neovius: four sheets, the network at 0.5 (0.2, 0.8 beyond h_max), _wall
}

// I-WP's network at rho = 0.8 passes 0.007 cell from its focal points: at 40 columns per side its
// stated error is 1.2e-4, at 80 it is 5.6e-6.
INSTANTIATE_TEST_SUITE_P(SlowIssue13, SlowDensityCheck,
                         ::testing::Values(AcceptanceCase{"gyroid", 40}, AcceptanceCase{"schwarzp", 40},
                                           AcceptanceCase{"diamond", 40}, AcceptanceCase{"neovius", 40},
                                           AcceptanceCase{"iwp", 64}),
                         [](const ::testing::TestParamInfo<AcceptanceCase>& c) { return c.param.surface; });

}  // namespace
}  // namespace offsetgen::check
