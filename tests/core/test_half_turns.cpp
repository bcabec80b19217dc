// The half-turn form of the trig at the base point (Program::note_half_turns, in_half_turns): which
// sin/cos nodes lowering notes, that the rewritten programs compute the same values, and that the
// double evaluation of sinpi/cospi reduces its argument exactly.
#include "emit/dialect.h"
#include "emit/printer.h"
#include "lowering/program.h"
#include "neovius_o4.h"  // generated/: the points near its zero set
#include "offset/offset_reference.h"
#include "surfaces/expression_input.h"
#include "test_support.h"
#include "zero_set_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace offsetgen {
namespace {

// Sin or Cos calls the outputs of `p` still reach.
int plain_trig_calls(const Program& p) {
  int calls = 0;
  for (NodeId id : schedule(p)) {
    const Node& n = p.node(id);
    if (n.op == Op::Call && (n.fn == Fn::Sin || n.fn == Fn::Cos)) ++calls;
  }
  return calls;
}

// The largest |difference| of the outputs of `a` and `b` over random cell points (and h in +-0.1).
double largest_difference(const Program& a, const Program& b) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> cell(-1.5, 1.5), h(-0.1, 0.1);
  Evaluator ea(a), eb(b);
  double worst = 0;
  for (int i = 0; i < 500; ++i) {
    std::vector<double> in;
    for (size_t k = 0; k < a.inputs().size(); ++k) in.push_back(k < 3 ? cell(rng) : h(rng));
    const auto& va = ea(in);
    const std::vector<double> copy = va;
    const auto& vb = eb(in);
    for (size_t k = 0; k < copy.size(); ++k) worst = std::max(worst, std::fabs(copy[k] - vb[k]));
  }
  return worst;
}

TEST(HalfTurns, SinPiAndCosPiReduceExactlyAtQuarterTurns) {
  for (double n = -8; n <= 8; n += 1) {
    EXPECT_EQ(apply_function(Fn::SinPi, n), 0.0) << n;
    EXPECT_EQ(std::fabs(apply_function(Fn::CosPi, n)), 1.0) << n;
    EXPECT_EQ(apply_function(Fn::CosPi, n + 0.5), 0.0) << n;
    EXPECT_EQ(std::fabs(apply_function(Fn::SinPi, n + 0.5)), 1.0) << n;
  }
  EXPECT_EQ(apply_function(Fn::SinPi, 1.5), -1.0);
  EXPECT_EQ(apply_function(Fn::CosPi, 1.0), -1.0);
  for (double a : {0.1, -0.37, 0.8, 2.3, -5.55, 1e3 + 0.25}) {
    EXPECT_NEAR(apply_function(Fn::SinPi, a), std::sin(M_PI * a), 1e-12) << a;
    EXPECT_NEAR(apply_function(Fn::CosPi, a), std::cos(M_PI * a), 1e-12) << a;
  }
}

// Every sin and cos of the catalog TPMS is of a multiple of 2 pi x_i at p: every one is noted, by
// both methods (projection's displaced points reuse them by angle addition), and the rewritten
// programs agree with the originals.
TEST(HalfTurns, EveryTrigOfTheCatalogSurfacesIsInHalfTurnsAndKeepsItsValues) {
  for (const std::string method : {"richardson", "projection"}) {
    for (const std::string surface : {"gyroid", "schwarzp", "neovius", "diamond"}) {
      auto b = testing::build(surface, 4, method);
      for (const Program* p : {&b->programs.field, &b->programs.offset, &b->programs.normal}) {
        EXPECT_GT(plain_trig_calls(*p), 0) << surface << " " << method;
        EXPECT_FALSE(p->half_turns().empty()) << surface << " " << method;
        const Program turned = in_half_turns(*p);
        EXPECT_EQ(plain_trig_calls(turned), 0) << surface << " " << method;
        EXPECT_LT(largest_difference(*p, turned), 1e-12) << surface << " " << method;
      }
    }
  }
}

TEST(HalfTurns, TheArgumentOfTwoPiXIsTwoX) {
  auto b = testing::build("gyroid", 1);
  const Program turned = in_half_turns(b->programs.field);
  const PrintedBody body = print_program(turned, Dialect("opencl", Precision::Float), {"p.x", "p.y", "p.z"});
  std::string text;
  for (const auto& line : body.temporaries) text += line + "\n";
  text += body.outputs.at(0);
  for (const std::string expected : {"p.x * 2.0f", "p.y * 2.0f", "p.z * 2.0f", "sinpi(", "cospi("})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
  EXPECT_EQ(text.find("6.28"), std::string::npos) << text;
  EXPECT_EQ(text.find("sin("), std::string::npos) << text;
  EXPECT_EQ(text.find("cos("), std::string::npos) << text;
}

// A user expression in pi (scale 2 pi) is noted; one without pi (scale 1: sin(x) is not a rational
// number of half-turns of x) is not, and keeps its sin and cos.
TEST(HalfTurns, OnlyRationalMultiplesOfPiAreNoted) {
  const auto& richardson = offset_method("richardson");
  {
    Surface s = parse_user_expression("cos(2*Pi*x)*cos(2*Pi*y) + a*sin(4*Pi*z)", {{"a", "0.3"}}, "u");
    auto c = richardson.build(s, 3);
    const SurfacePrograms programs = lower_surface(s, *c, {});
    EXPECT_EQ(plain_trig_calls(in_half_turns(programs.offset)), 0);
    EXPECT_LT(largest_difference(programs.offset, in_half_turns(programs.offset)), 1e-12);
  }
  {
    Surface s = parse_user_expression("cos(x)*cos(y) + sin(z)", {}, "v");
    auto c = richardson.build(s, 2);
    const SurfacePrograms programs = lower_surface(s, *c, {});
    EXPECT_TRUE(programs.offset.half_turns().empty());
    EXPECT_EQ(plain_trig_calls(in_half_turns(programs.offset)), plain_trig_calls(programs.offset));
  }
}

// Where phi is steep (Neovius, order 4, h near 0.1), the rounding of 2 pi x alone moves the double
// zero set by 1.7e-13 (docs/neovius_o4_float.md); in half-turns the program stays at rounding level
// against the 40-digit reference, on the points the CUDA and OpenCL tests use.
TEST(HalfTurns, SteepNeoviusOrder4InDoubleStaysAtRoundingLevel) {
  auto b = testing::build("neovius", 4);
  const Program turned = in_half_turns(b->programs.offset);
  OffsetReference reference(b->surface, *b->construction);
  Evaluator original(b->programs.offset), half_turns(turned);
  double worst_original = 0, worst_half_turns = 0;
  for (const auto& z : test::near_zero_set_points(&neovius_o4_field, 2000)) {
    double g[3];
    test::field_gradient(&neovius_o4_field, z.p, g);
    const double scale = test::length(g);
    const double o = original({z.p[0], z.p[1], z.p[2], z.h})[0];
    const double t = half_turns({z.p[0], z.p[1], z.p[2], z.h})[0];
    if (std::fabs(o - t) < 1e-14 * scale) continue;  // the 40-digit reference only where they differ
    const double r = reference.offset({z.p[0], z.p[1], z.p[2]}, z.h).to_double();
    worst_original = std::max(worst_original, std::fabs(o - r) / scale);
    worst_half_turns = std::max(worst_half_turns, std::fabs(t - r) / scale);
  }
  EXPECT_GT(worst_original, 1e-13);  // the sample holds steep points
  EXPECT_LT(worst_half_turns, 2e-14);
}

}  // namespace
}  // namespace offsetgen
