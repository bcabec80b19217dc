// Density (src/density/, docs/density.md): the symbolic period-1 proof, the surface constants
// against exact values (planes, whose area, chi and V_0 are known in closed form) and against
// Gauss-Bonnet on the catalog, and the density relations and their emitted programs.
#include "density/density_model.h"
#include "density/periodicity.h"
#include "density/surface_constants.h"

#include "surfaces/catalog.h"
#include "surfaces/expression_input.h"

#include <gtest/gtest.h>

#include <cmath>

namespace offsetgen::density {
namespace {

constexpr double kPi = 3.141592653589793;

Surface expression(const std::string& text) { return parse_user_expression(text, {}, "s"); }

// A field without z, taken as a 3D surface (constant along z): planes are the exact test cases.
Surface extruded(const std::string& text) {
  Surface s = expression(text);
  s.dims = 3;
  return s;
}

TEST(DensityPeriodicity, CatalogSurfacesAreProvenPeriodic) {
  for (const auto& entry : catalog())
    EXPECT_EQ(density_unavailable(catalog_surface(entry.name)), std::nullopt) << entry.name;
}

TEST(DensityPeriodicity, PeriodOneExpressionsAreAccepted) {
  for (const char* text : {"cos(2*Pi*x) + cos(2*Pi*y) + cos(2*Pi*z) - 0.5", "sin(4*Pi*x)*cos(2*Pi*y) + sin(2*Pi*z)^2",
                           "cos(Pi*x)*sin(Pi*x) + cos(Pi*y)^2 + cos(2*Pi*z)",  // sign flips that cancel
                           "exp(cos(2*Pi*x)) + sin(2*Pi*(x + y + z)) - cosh(sin(2*Pi*y))"})
    EXPECT_EQ(density_unavailable(expression(text)), std::nullopt) << text;
}

TEST(DensityPeriodicity, OtherExpressionsAreRefusedNamingThePart) {
  struct Case {
    const char* text;
    const char* named;  // what the message must name
  };
  for (const Case& c :
       {Case{"cos(2*Pi*x) + cos(2*Pi*y) + z", "periodic in z"}, Case{"sin(x) + cos(2*Pi*y) + cos(2*Pi*z)", "'sin(x)'"},
        Case{"cos(Pi*x) + cos(2*Pi*y) + cos(2*Pi*z)", "it changes sign under x -> x + 1 and the other terms do not"},
        Case{"cos(Pi*x) + cos(Pi*y) + cos(Pi*z)", "period 2, not 1"},
        Case{"cos(2*Pi*x^2) + cos(2*Pi*y) + cos(2*Pi*z)", "periodic in x"}}) {
    const auto why = density_unavailable(expression(c.text));
    ASSERT_TRUE(why.has_value()) << c.text;
    EXPECT_NE(why->find(c.named), std::string::npos) << c.text << ": " << *why;
  }
  const auto flat = density_unavailable(expression("cos(2*Pi*x) + cos(2*Pi*y)"));
  ASSERT_TRUE(flat.has_value());
  EXPECT_NE(flat->find("3D"), std::string::npos) << *flat;
}

// Parallel planes: everything is known exactly, and a tilted family makes every column meet the
// surface obliquely (the partition of unity over the axes does all the work).
TEST(DensityConstants, ParallelPlanesGiveTheExactAreaChiAndVolume) {
  const SurfaceConstants axis = compute_surface_constants(extruded("sin(2*Pi*x)"));
  EXPECT_NEAR(axis.area, 2.0, 1e-9);  // x = 0 and x = 1/2
  EXPECT_EQ(axis.euler_characteristic, 0);
  EXPECT_NEAR(axis.volume_inside, 0.5, 1e-9);
  EXPECT_NEAR(axis.mean_integral, 0.0, 1e-9);

  const SurfaceConstants tilted = compute_surface_constants(extruded("sin(2*Pi*(x + y))"));
  EXPECT_NEAR(tilted.area, 2 * std::sqrt(2.0), 1e-7);  // planes 1 / (2 sqrt 2) apart
  EXPECT_EQ(tilted.euler_characteristic, 0);
  EXPECT_LE(tilted.chi_residual, kChiTolerance);
  EXPECT_NEAR(tilted.volume_inside, 0.5, 1e-7);
  EXPECT_NEAR(tilted.mean_integral, 0.0, 1e-7);

  // F < 0 where sin(2 pi x) < -sqrt(2)/2, on x in (5/8, 7/8): V_0 = 1/4.
  const SurfaceConstants shifted = compute_surface_constants(extruded("sin(2*Pi*x) + sqrt(2)/2"));
  EXPECT_NEAR(shifted.area, 2.0, 1e-9);
  EXPECT_NEAR(shifted.volume_inside, 0.25, 1e-8);
}

// A closed blob per cell (sphere topology, chi = +2), and the complementary phase.
TEST(DensityConstants, IsolatedBlobsHaveChiTwo) {
  for (const char* text :
       {"cos(2*Pi*x) + cos(2*Pi*y) + cos(2*Pi*z) - 2", "cos(2*Pi*x) + cos(2*Pi*y) + cos(2*Pi*z) + 2"}) {
    const SurfaceConstants k = compute_surface_constants(expression(text));
    EXPECT_EQ(k.euler_characteristic, 2) << text;
    EXPECT_LE(k.chi_residual, kChiTolerance) << text;
  }
}

// The Gauss-Bonnet self-check on the two cheapest catalog surfaces (all nine: SlowDensityConstants).
TEST(DensityConstants, GyroidAndSchwarzPHaveTheirGenus) {
  const SurfaceConstants g = surface_constants(catalog_surface("gyroid"));
  EXPECT_EQ(g.euler_characteristic, -8);  // genus 5 in the conventional cell
  EXPECT_LE(g.chi_residual, kChiTolerance);
  EXPECT_NEAR(g.area, 3.0916, 1e-3);        // the exact gyroid has 3.091444; the nodal one is close
  EXPECT_NEAR(g.volume_inside, 0.5, 1e-7);  // F -> -F is a translation of the gyroid
  EXPECT_NEAR(g.mean_integral, 0.0, 1e-7);
  const SurfaceConstants p = surface_constants(catalog_surface("schwarzp"));
  EXPECT_EQ(p.euler_characteristic, -4);  // genus 3
  EXPECT_LE(p.chi_residual, kChiTolerance);
  EXPECT_NEAR(p.volume_inside, 0.5, 1e-7);
  // Nodal P: the largest principal curvature is 2 pi, at (1/4, 1/4, 1/2) where F = 0 is a saddle
  // cos(X) + cos(Y) = 0 ... = -cos(Z) with k1 = -k2 = 2 pi (cell units).
  EXPECT_NEAR(p.max_curvature, 2 * kPi, 1e-6);
}

class SlowDensityConstants : public ::testing::TestWithParam<std::string> {};

TEST_P(SlowDensityConstants, ChiIsAnIntegerWithinTheSelfCheck) {
  const SurfaceConstants k = surface_constants(catalog_surface(GetParam()));
  EXPECT_LE(k.chi_residual, kChiTolerance);
  EXPECT_LE(std::fabs(k.gauss_integral - 2 * kPi * k.euler_characteristic), 2 * kPi * kChiTolerance);
  EXPECT_LT(k.euler_characteristic, 0);  // every catalog surface has genus > 1
  EXPECT_EQ(k.euler_characteristic % 2, 0);
  EXPECT_GT(k.area, 2.0);
  EXPECT_GT(k.volume_inside, 0.3);
  EXPECT_LT(k.volume_inside, 0.7);
  EXPECT_LE(k.area_error, 1e-7);
  EXPECT_LE(k.volume_error, 1e-7);
}

INSTANTIATE_TEST_SUITE_P(SlowCatalog, SlowDensityConstants,
                         ::testing::Values("gyroid", "schwarzp", "diamond", "neovius", "iwp", "fischerkoch", "lidinoid",
                                           "splitp", "frd"));

SurfaceConstants made_up_constants() {
  SurfaceConstants k;
  k.area = 3.5;
  k.euler_characteristic = -12;
  k.gauss_integral = 2 * kPi * k.euler_characteristic;
  k.volume_inside = 0.47;
  k.mean_integral = 0.88;
  k.max_curvature = 9.5;
  return k;
}

TEST(DensityModel, InversesUndoTheCubicsOverTheValidRange) {
  const DensityModel m(made_up_constants());
  EXPECT_NEAR(m.sheet_cubic(), kPi * -12 / 6, 1e-15);
  for (int i = 0; i <= 100; ++i) {
    const double t = m.thickness_limit() * i / 100;
    EXPECT_NEAR(m.sheet_thickness(m.sheet_density(t)), t, 1e-14) << t;
    const double h = m.offset_limit() * (2.0 * i / 100 - 1);
    EXPECT_NEAR(m.network_offset(m.network_density(h)), h, 1e-14) << h;
  }
  EXPECT_NEAR(m.network_density(0), 0.47, 1e-15);
  // The cubics of docs/density.md, written out.
  const double t = 0.05, h = -0.03;
  EXPECT_NEAR(m.sheet_density(t), 3.5 * t + kPi * -12 / 6 * t * t * t, 1e-15);
  EXPECT_NEAR(m.network_density(h), 0.47 + 3.5 * h + 0.88 * h * h + 2 * kPi * -12 / 3 * h * h * h, 1e-15);
}

TEST(DensityModel, OutOfRangeIsNaN) {
  const DensityModel m(made_up_constants());
  EXPECT_TRUE(std::isnan(m.sheet_density(-1e-12)));
  EXPECT_TRUE(std::isnan(m.sheet_density(m.thickness_limit() * (1 + 1e-12))));
  EXPECT_TRUE(std::isnan(m.sheet_thickness(-1e-12)));
  EXPECT_TRUE(std::isnan(m.sheet_thickness(m.sheet_density_limit() * (1 + 1e-12))));
  EXPECT_TRUE(std::isnan(m.network_density(m.offset_limit() * (1 + 1e-12))));
  EXPECT_TRUE(std::isnan(m.network_offset(m.network_density_min() - 1e-9)));
  EXPECT_TRUE(std::isnan(m.network_offset(m.network_density_max() + 1e-9)));
  EXPECT_TRUE(std::isnan(m.sheet_thickness(NAN)));
}

TEST(DensityModel, EmittedProgramsMatchTheModelAndReturnNaNOutOfRange) {
  const DensityModel m(made_up_constants());
  const DensityPrograms p = density_programs(m);
  double worst = 0;
  for (int i = 0; i <= 400; ++i) {
    const double u = i / 400.0;
    auto relative = [](double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-3); };
    const double t = u * m.thickness_limit(), rho = u * m.sheet_density_limit();
    worst = std::max(worst, relative(evaluate(p.density, {t})[0], m.sheet_density(t)));
    worst = std::max(worst, relative(evaluate(p.thickness_for_density, {rho})[0], m.sheet_thickness(rho)));
    const double h = (2 * u - 1) * m.offset_limit();
    const double rn = m.network_density_min() + u * (m.network_density_max() - m.network_density_min());
    worst = std::max(worst, relative(evaluate(p.network_density, {h})[0], m.network_density(h)));
    worst = std::max(worst, relative(evaluate(p.offset_for_density, {rn})[0], m.network_offset(rn)));
  }
  EXPECT_LE(worst, 1e-13);  // a fixed number of Newton steps is enough everywhere in range
  for (double bad : {-0.01, m.sheet_density_limit() + 1e-9, double(NAN)})
    EXPECT_TRUE(std::isnan(evaluate(p.thickness_for_density, {bad})[0])) << bad;
  for (double bad : {-1e-9, m.thickness_limit() + 1e-9}) EXPECT_TRUE(std::isnan(evaluate(p.density, {bad})[0])) << bad;
  for (double bad : {m.network_density_min() - 1e-9, m.network_density_max() + 1e-9, 1.5})
    EXPECT_TRUE(std::isnan(evaluate(p.offset_for_density, {bad})[0])) << bad;
  EXPECT_TRUE(std::isnan(evaluate(p.network_density, {-m.offset_limit() - 1e-9})[0]));
}

}  // namespace
}  // namespace offsetgen::density
