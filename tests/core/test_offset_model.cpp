// The symbolic construction against independent derivations, and properties of the lowering. The
// emitted code against the 40-digit reference: tests/check/test_values.cpp (Values.*).
#include "offset/offset_reference.h"
#include "offset/richardson.h"
#include "offset/richardson_method.h"
#include "surfaces/expression_input.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace offsetgen {
namespace {

// Circle f = x^2 + y^2 - R^2 (paper eqs. 18-19): phi^(1)(R+h, 0, h) = -h^2 and phi^(2)(R+h, 0, h) = 0
// exactly. Evaluated in exact rational arithmetic (sqrt of perfect squares stays exact).
TEST(CircleIdentities, FirstOrderIsMinusHSquaredAndSecondOrderIsExact) {
  Surface circle = parse_user_expression("x^2 + y^2 - 9", {}, "circle");
  for (int order : {1, 2}) {
    auto raw = build_richardson(circle, order, CellBounds{});
    OffsetReference exact(circle, *raw);
    for (auto h : {GiNaC::numeric(1, 10), GiNaC::numeric(-1, 7), GiNaC::numeric(3, 5)}) {
      GiNaC::numeric phi = exact.offset({3 + h, 0}, h);
      EXPECT_TRUE(phi.is_rational()) << phi;
      EXPECT_EQ(phi, order == 1 ? -h * h : GiNaC::numeric(0)) << "order " << order << " h " << h;
    }
  }
}

// phi^(m) built the naive way: GiNaC's own diff() on the explicit chain, no jets, no atoms.
GiNaC::ex naive_offset(const Surface& s, int order, const GiNaC::symbol& h) {
  const Symbols& sym = Symbols::get();
  auto weights = richardson_weights(order);
  GiNaC::ex phi = 0;
  for (int j = 1; j <= order; ++j) {
    GiNaC::ex psi = s.field;
    for (int k = 0; k < j; ++k) {
      GiNaC::ex norm2 = 0;
      for (int i = 0; i < s.dims; ++i) norm2 += GiNaC::pow(psi.diff(sym.natural(i)), 2);
      psi = psi - h / j * GiNaC::sqrt(norm2);
    }
    phi += weights[static_cast<size_t>(j - 1)] * psi;
  }
  return phi;
}

TEST(OffsetModel, JetChainsEqualNaiveNestedDifferentiation) {
  const Symbols& sym = Symbols::get();
  GiNaC::symbol h("h_naive");
  const long saved_digits = GiNaC::Digits;
  GiNaC::Digits = 30;  // the naive side must carry as many digits as the reference
  for (const char* name : {"gyroid", "neovius", "iwp"}) {
    Surface s = catalog_surface(name);
    for (int order = 1; order <= 3; ++order) {
      auto raw = build_richardson(s, order, CellBounds{});
      OffsetReference jets(s, *raw, 30);
      GiNaC::ex naive = naive_offset(s, order, h);
      for (int trial = 0; trial < 3; ++trial) {
        GiNaC::numeric x(1 + trial, 10), y(2 + trial, 7), z(3, 11 + trial), hv(trial - 1, 50);
        GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(s.scale));
        GiNaC::ex value = naive.subs(GiNaC::lst{sym.X == k * x, sym.Y == k * y, sym.Z == k * z, h == k * hv}).evalf();
        GiNaC::numeric expected = GiNaC::ex_to<GiNaC::numeric>(value);
        GiNaC::numeric got = jets.offset({x, y, z}, hv);
        EXPECT_LT(GiNaC::abs(got - expected).to_double(), 1e-25)
            << name << " order " << order << " got " << got << " expected " << expected;
      }
    }
  }
  GiNaC::Digits = saved_digits;
}

TEST(Lowering, CellLengthScalingIsExact) {
  // Schwarz P with cell length L = 2 written by hand equals the catalog function at (p/L, h/L).
  Surface big = parse_user_expression("cos(Pi*x) + cos(Pi*y) + cos(Pi*z)", {}, "big");
  auto construction = offset_method("richardson").build(big, 4);
  SurfacePrograms programs = lower_surface(big, *construction, {});
  auto unit = testing::build("schwarzp", 4);
  Evaluator scaled(programs.offset), reference(unit->programs.offset);
  for (double x : {0.1, 0.7, 1.3}) {
    const double y = 0.4, z = 1.9, h = 0.06;
    EXPECT_NEAR(scaled({x, y, z, h})[0], reference({x / 2, y / 2, z / 2, h / 2})[0], 1e-13);
  }
}

TEST(Lowering, CosAndSinAreEachEvaluatedOncePerArgumentAndThereIsNoPow) {
  auto b = testing::build("gyroid", 4);
  int calls = 0;
  for (NodeId id : schedule(b->programs.offset)) {
    const Node& n = b->programs.offset.node(id);
    EXPECT_NE(n.op, Op::Pow);
    if (n.op == Op::Call) ++calls;
  }
  EXPECT_EQ(calls, 6);  // sin and cos of 2*pi*x, 2*pi*y, 2*pi*z
}

TEST(OffsetModel, RawFormulasBlowUpWhereTheGradientVanishes) {
  // Gyroid at (1/8, 1/8, 1/8): grad F = 0. The unclamped G is undefined there;
  // this is what the safeguard exists for (tests/core/test_safeguard.cpp).
  auto b = testing::build("gyroid", 4);
  auto unclamped = build_richardson(b->surface, 4, CellBounds{});
  OffsetReference raw(b->surface, *unclamped, 40);
  GiNaC::numeric eighth(1, 8);
  // At 40 digits the gradient cancels to exactly zero there, and the raw chain divides by it.
  EXPECT_THROW(raw.offset({eighth, eighth, eighth}, GiNaC::numeric(1, 20)), std::exception);
  Evaluator safe(b->programs.offset);
  double phi = safe({0.125, 0.125, 0.125, 0.05})[0];
  EXPECT_TRUE(std::isfinite(phi));
  EXPECT_GT(phi, 0);
}

}  // namespace
}  // namespace offsetgen
