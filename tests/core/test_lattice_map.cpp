// Conforming lattices (--map, surfaces/lattice_map.h): the map's parsing, atan2 through lowering and
// differentiation, the checks on the domain, and the property that matters: walls exactly thick in
// physical units wherever the map stretches the cells.
#include "field/symbolic_diff.h"
#include "lowering/program.h"
#include "pipeline/generate.h"
#include "surfaces/lattice_map.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace offsetgen {
namespace {

std::string error_of(const GenerationRequest& request) {
  try {
    build_generation(request);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

GenerationRequest cylindrical_gyroid(const std::string& domain) {
  GenerationRequest r;
  r.surface = "gyroid";
  r.map = "cylindrical:12,5,5";
  r.domain = parse_domain(domain);
  return r;
}

TEST(LatticeMap, CylindricalPresetExpandsToItsFormula) {
  const LatticeMap map = parse_lattice_map("cylindrical:12,5,2.5", {}, 3);
  ASSERT_EQ(map.components.size(), 3u);
  EXPECT_EQ(map.components[0], "sqrt(x^2+y^2)/(5)");
  EXPECT_EQ(map.components[1], "12*atan2(y,x)/(2*Pi)");
  EXPECT_EQ(map.components[2], "z/(2.5)");
  EXPECT_EQ(map.kind, "cylindrical");
}

TEST(LatticeMap, RefusesWhatCannotCloseUpOrDoesNotFit) {
  auto message = [](const std::string& text, int dims) {
    try {
      parse_lattice_map(text, {}, dims);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("cylindrical:12.5,5,5", 3).find("whole number"), std::string::npos);
  EXPECT_NE(message("cylindrical:12,5", 3).find("expected 3 numbers"), std::string::npos);
  EXPECT_NE(message("cylindrical:12,-5,5", 3).find("positive"), std::string::npos);
  EXPECT_NE(message("conical:1,2,3", 3).find("unknown preset 'conical'"), std::string::npos);
  EXPECT_NE(message("polar:8,3", 3).find("2D map, but the surface is 3D"), std::string::npos);
  EXPECT_NE(message("x; y", 3).find("has 2 components"), std::string::npos);
  EXPECT_NE(message("x; y; w", 3).find("'w'"), std::string::npos);
}

TEST(LatticeMap, DomainNeedsTwoCornersWithLoBelowHi) {
  EXPECT_EQ(parse_domain("0,1,2:3,4,5").hi[2], 5);
  EXPECT_EQ(parse_domain("0,1:3,4").dims, 2);
  EXPECT_THROW(parse_domain("0,1,2"), InputError);
  EXPECT_THROW(parse_domain("0,1,2:3,1,5"), InputError);
  EXPECT_THROW(parse_domain("0,1,2:3,4"), InputError);
  EXPECT_THROW(parse_domain("0,a,2:3,4,5"), InputError);
}

TEST(Atan2, EvaluatesInEveryQuadrantAndFoldsConstants) {
  Program p({"y", "x"});
  p.add_output("a", p.atan2(p.input(0), p.input(1)));
  p.add_output("b", p.atan2(p.neg(p.input(0)), p.input(1)));  // -atan2(y, x), also on the cut's sides
  Evaluator evaluate(p);
  for (double y : {-2.0, -0.0, 0.0, 1.5})
    for (double x : {-3.0, -0.5, 0.5, 2.0}) {
      const auto& v = evaluate({y, x});
      EXPECT_EQ(v[0], std::atan2(y, x)) << y << " " << x;
      EXPECT_EQ(v[1], std::atan2(-y, x)) << y << " " << x;
    }
  Program c({"x"});
  EXPECT_TRUE(c.is_const(c.atan2(c.constant(1), c.constant(-1)), std::atan2(1.0, -1.0)));
}

// d/dx atan2(x, x + y): with the argument substituted by position, not by value (x also appears in
// the other argument).
TEST(Atan2, DerivativeOfSharedArgumentsIsExact) {
  const Symbols& sym = Symbols::get();
  const GiNaC::ex e = GiNaC::atan2(sym.X, sym.X + sym.Y);
  MemoDiff diff({sym.X, sym.Y, sym.Z});
  const GiNaC::ex d = diff.partial(e, MultiIndex{1, 0, 0});
  const double x = 0.7, y = -0.2;
  const double value =
      GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(d.subs(GiNaC::lst{sym.X == x, sym.Y == y}))).to_double();
  // atan2(x, x + y) = atan(x / (x + y)) for x + y > 0: derivative y / ((x + y)^2 + x^2).
  EXPECT_NEAR(value, y / ((x + y) * (x + y) + x * x), 1e-15);
}

TEST(MappedGeneration, RefusesADomainHoldingTheAxis) {
  const std::string e = error_of(cylindrical_gyroid("-20,-20,0:20,20,10"));
  EXPECT_NE(e.find("is singular at (x, y, z) = (0, 0,"), std::string::npos) << e;
  EXPECT_NE(e.find("--domain"), std::string::npos) << e;
}

TEST(MappedGeneration, RefusesAFieldThatJumpsAcrossTheCut) {
  GenerationRequest r = cylindrical_gyroid("-20,-5,0:-10,5,10");
  r.map = "sqrt(x^2+y^2)/5; 12.5*atan2(y,x)/(2*Pi); z/5";
  const std::string e = error_of(r);
  EXPECT_NE(e.find("jump across the cut of atan2"), std::string::npos) << e;
  r.map = "sqrt(x^2+y^2)/5; 12*atan2(y,x)/(2*Pi); z/5";  // whole cells: the same domain is fine
  EXPECT_EQ(error_of(r), "");
}

TEST(MappedGeneration, NeedsADomainAndRefusesDensity) {
  GenerationRequest r = cylindrical_gyroid("10,-5,0:20,5,10");
  r.domain.reset();
  EXPECT_NE(error_of(r).find("needs a domain"), std::string::npos);
  r = cylindrical_gyroid("10,-5,0:20,5,10");
  r.density = 0.2;
  EXPECT_NE(error_of(r).find("not periodic"), std::string::npos);
  r = cylindrical_gyroid("10,-5:20,5");
  EXPECT_NE(error_of(r).find("2 coordinates per corner"), std::string::npos);
  GenerationRequest unmapped;
  unmapped.surface = "gyroid";
  unmapped.domain = parse_domain("0,0,0:1,1,1");
  EXPECT_NE(error_of(unmapped).find("--domain applies to a mapped lattice"), std::string::npos);
}

// The bounds are taken over the domain: |grad G| of the cylindrical gyroid is largest at the inner
// radius, where the 12 cells around are narrowest (2 pi 10 / 12 = 5.2 mm against 5 mm radially).
TEST(MappedGeneration, BoundsComeFromTheDomain) {
  const Generation near = build_generation(cylindrical_gyroid("10,-5,0:20,5,10"));
  const Generation far = build_generation(cylindrical_gyroid("40,-5,0:50,5,10"));
  EXPECT_GT(near.construction->bounds().gradient, far.construction->bounds().gradient);
  EXPECT_LT(near.construction->bounds().gradient, 3.0);  // about 2 pi / 5 * sqrt(3): finite, no pole
  EXPECT_EQ(near.prefix, "gyroid_cylindrical_o4");
}

// The property: on points of G = 0, the offsets at +-h lie h away along the physical normal (order
// 4, h = 0.3 mm), where the map stretches the cells by up to 2 around the circumference.
TEST(MappedGeneration, WallsLieTheRequestedDistanceAlongThePhysicalNormal) {
  const Generation g = build_generation(cylindrical_gyroid("10,-5,0:20,5,10"));
  Evaluator field(g.programs.field), offset(g.programs.offset);
  auto F = [&](const std::array<double, 3>& p) { return field({p[0], p[1], p[2]})[0]; };
  auto gradient = [&](const std::array<double, 3>& p) {
    std::array<double, 3> d{};
    for (size_t i = 0; i < 3; ++i) {
      auto a = p, b = p;
      a[i] += 1e-6;
      b[i] -= 1e-6;
      d[i] = (F(a) - F(b)) / 2e-6;
    }
    return d;
  };
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const double h = 0.3;
  double worst = 0;
  int measured = 0;
  while (measured < 40) {
    std::array<double, 3> p{12 + 6 * u(rng), -3 + 6 * u(rng), 2 + 6 * u(rng)};
    for (int k = 0; k < 30; ++k) {
      const auto d = gradient(p);
      const double g2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], f = F(p);
      for (size_t i = 0; i < 3; ++i) p[i] -= f * d[i] / g2;
    }
    if (std::fabs(F(p)) > 1e-12) continue;
    auto n = gradient(p);
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n) c /= len;
    for (double side : {1.0, -1.0}) {
      // phi(p + s n, side h) changes sign at s = side h, to the method's accuracy.
      auto phi = [&](double s) { return offset({p[0] + s * n[0], p[1] + s * n[1], p[2] + s * n[2], side * h})[0]; };
      double a = side * h - 0.1, b = side * h + 0.1;
      ASSERT_LT(phi(a) * phi(b), 0) << "no wall near " << side * h;
      for (int k = 0; k < 60; ++k) {
        const double m = (a + b) / 2;
        (phi(a) * phi(m) <= 0 ? b : a) = m;
      }
      worst = std::max(worst, std::fabs((a + b) / 2 - side * h));
    }
    ++measured;
  }
  EXPECT_LT(worst, 1e-3) << "mm";
}

}  // namespace
}  // namespace offsetgen
