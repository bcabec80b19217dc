// The foot-point projection method (offset/projection_method.cpp): the lowered programs against its
// 40-digit reference, exactness where the foot point is known, safety without a clamp on grids that
// hold every lattice point, and its cost against the paper's construction.
#include "lowering/field_lowering.h"
#include "lowering/lower.h"
#include "offset/offset_reference.h"
#include "surfaces/expression_input.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>
#include <string>

namespace offsetgen {
namespace {

double shift(double got, double expected, const std::vector<GiNaC::numeric>& gradient) {
  double g2 = 0;
  for (const auto& c : gradient) g2 += c.to_double() * c.to_double();
  return std::fabs(got - expected) / std::max(std::sqrt(g2), 1.0);
}

TEST(Projection, OrdersAreEvenAndOddOrdersRoundUp) {
  const OffsetMethod& m = offset_method("projection");
  EXPECT_EQ(m.effective_order(1), 2);
  EXPECT_EQ(m.effective_order(2), 2);
  EXPECT_EQ(m.effective_order(3), 4);
  EXPECT_EQ(m.effective_order(16), 16);
  EXPECT_GE(m.max_order(), 16);
  auto b = testing::build("gyroid", 7, "projection");
  EXPECT_EQ(b->construction->facts().order, 8);
  EXPECT_EQ(b->construction->facts().requested_order, 7);
  EXPECT_EQ(b->construction->facts().metadata.at("projections"), 3);
}

// On a circle n(p) points exactly at the foot point, so every K gives F(q_K) = 0 on the offset
// circle, in exact rational arithmetic (|grad F| = 2(R + h) is rational there).
TEST(Projection, CircleOffsetIsExactForEveryK) {
  Surface circle = parse_user_expression("x^2 + y^2 - 9", {}, "circle");
  for (int order : {2, 4, 8}) {
    auto c = offset_method("projection").build(circle, order);
    OffsetReference exact(circle, *c);
    for (auto h : {GiNaC::numeric(1, 10), GiNaC::numeric(-1, 7), GiNaC::numeric(3, 5)}) {
      GiNaC::numeric phi = exact.offset({3 + h, 0}, h);
      EXPECT_TRUE(phi.is_zero()) << "order " << order << " h " << h << ": " << phi;
    }
  }
}

// The programs the emitters print, against the 40-digit evaluation of the same iteration: offset,
// normal and a graded wall, including h large enough for the angle-addition clamp (|h| > 1/(2 pi)).
TEST(Projection, ProgramsMatchThe40DigitReference) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), step(-0.06, 0.06);
  const GiNaC::ex thickness = parse_thickness_expression("0.02 + 0.06*x", {}, 3);
  for (const char* name : {"gyroid", "schwarzp", "neovius", "iwp"}) {
    for (int order : {2, 4, 8, 16}) {
      auto b = testing::build(name, order, "projection");
      LoweringOptions options;
      options.thickness = thickness;
      const SurfacePrograms programs = lower_surface(b->surface, *b->construction, options);
      OffsetReference reference(b->surface, *b->construction);
      Evaluator offset(programs.offset), normal(programs.normal), graded(*programs.graded);
      double worst = 0, worst_normal = 0, worst_graded = 0;
      for (int i = 0; i < 10; ++i) {
        const std::vector<double> p = {unit(rng), unit(rng), unit(rng)};
        const std::vector<GiNaC::numeric> x = {p[0], p[1], p[2]};
        const auto gradient = reference.field_gradient(x);
        const double h = i < 8 ? step(rng) : (i == 8 ? 0.3 : -0.45);  // the last two clamp
        worst = std::max(worst, shift(offset({p[0], p[1], p[2], h})[0], reference.offset(x, h).to_double(), gradient));
        const auto n = normal({p[0], p[1], p[2], h});
        const auto n_ref = reference.normal(x, h);
        for (size_t k = 0; k < 3; ++k) worst_normal = std::max(worst_normal, std::fabs(n[k] - n_ref[k].to_double()));
        const double g = graded(p)[0], g_ref = reference.graded(x, thickness).to_double();
        worst_graded = std::max(worst_graded, std::fabs(g - g_ref) / std::max(std::fabs(g_ref), 1e-3));
      }
      EXPECT_LT(worst, 1e-12) << name << " order " << order;
      EXPECT_LT(worst_normal, 1e-12) << name << " order " << order;
      EXPECT_LT(worst_graded, 1e-10) << name << " order " << order;
    }
  }
}

// The small-angle polynomials stand in for sin and cos at the foot-point estimates only where they
// are exact: the same offset lowered with direct trig agrees to rounding.
TEST(Projection, AngleAdditionAgreesWithDirectTrig) {
  Surface s = catalog_surface("lidinoid");  // multiples 2X: double angles on top of the kernels
  ASSERT_TRUE(is_trigonometric_polynomial(s.field));
  auto c = offset_method("projection").build(s, 6);
  Program fast({"x", "y", "z", "h"}), direct({"x", "y", "z", "h"});
  // The normal at q_K: every estimate's trig by angle addition (the offset takes F(q_K) from a Taylor
  // polynomial at q_(K-1); ProgramsMatchThe40DigitReference covers that).
  {
    FieldLowering at(fast, s, c->atoms(), c->field());
    const auto n = c->lower_normal(at, at.natural(fast.input(3)));
    for (size_t i = 0; i < n.size(); ++i) fast.add_output("n" + std::to_string(i), n[i]);
  }
  // The same iteration written out with trig evaluated at each estimate.
  {
    FieldLowering at(direct, s, c->atoms(), c->field());
    const Environment* estimate = &at.base();
    NodeId h = at.natural(direct.input(3));
    for (int j = 0; j <= 2; ++j) {
      std::vector<NodeId> g = at.gradient(*estimate), squares, q;
      for (NodeId v : g) squares.push_back(direct.mul(v, v));
      NodeId inverse = direct.div(direct.constant(1), direct.sqrt(direct.sum(squares)));
      for (size_t i = 0; i < 3; ++i) q.push_back(direct.sub(at.point()[i], direct.mul(h, direct.mul(g[i], inverse))));
      estimate = &at.at(q);
    }
    std::vector<NodeId> g = at.gradient(*estimate), squares;
    for (NodeId v : g) squares.push_back(direct.mul(v, v));
    NodeId inverse = direct.div(direct.constant(1), direct.sqrt(direct.sum(squares)));
    for (size_t i = 0; i < g.size(); ++i) direct.add_output("n" + std::to_string(i), direct.mul(g[i], inverse));
  }
  // Every sin and cos is taken of an argument at p: none depends on h.
  std::vector<char> uses_h(fast.nodes().size(), 0);
  int calls = 0;
  for (NodeId id : schedule(fast)) {
    const Node& node = fast.node(id);
    auto& flag = uses_h[static_cast<size_t>(id)];
    flag = node.op == Op::Input && node.input == 3;
    for (int operand : {node.a, node.b, node.c})
      if (operand >= 0) flag = flag || uses_h[static_cast<size_t>(operand)];
    if (node.op == Op::Call) {
      ++calls;
      EXPECT_FALSE(uses_h[static_cast<size_t>(node.a)]) << "trig of a foot-point estimate's argument";
    }
  }
  EXPECT_GE(calls, 6);
  Evaluator a(fast), b(direct);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0), step(-0.15, 0.15);
  for (int i = 0; i < 500; ++i) {
    const double x = unit(rng), y = unit(rng), z = unit(rng), h = step(rng);
    const auto fast_n = a({x, y, z, h}), direct_n = b({x, y, z, h});
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(fast_n[k], direct_n[k], 1e-12) << x << " " << y << " " << z << " " << h;
  }
}

TEST(Projection, TrigonometricPolynomialsAreRecognised) {
  EXPECT_TRUE(is_trigonometric_polynomial(catalog_surface("gyroid").field));
  EXPECT_TRUE(is_trigonometric_polynomial(catalog_surface("frd").field));
  const Surface sphere = parse_user_expression("x^2 + y^2 + z^2 - 1/4", {}, "sphere");
  EXPECT_FALSE(is_trigonometric_polynomial(sphere.field));
  const Surface mixed = parse_user_expression("cos(2*Pi*x) + cos(2*Pi*y) + z", {}, "mixed");
  EXPECT_FALSE(is_trigonometric_polynomial(mixed.field));
}

// |q_K - p| <= |h|, so |phi - F(p)| <= M |h| (natural units) for every h, clamp or not: the
// property that rules out phantom walls without a safeguard clamp.
TEST(Projection, OffsetStaysWithinMHOfTheField) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0), step(-0.5, 0.5);
  for (const CatalogEntry& entry : catalog()) {
    for (int order : {2, 8}) {
      auto b = testing::build(entry.name, order, "projection");
      Evaluator field(b->programs.field), offset(b->programs.offset);
      const double m = b->bounds().gradient * 2 * M_PI;  // cell units
      for (int i = 0; i < 2000; ++i) {
        const double x = unit(rng), y = unit(rng), z = unit(rng), h = step(rng);
        const double difference = std::fabs(offset({x, y, z, h})[0] - field({x, y, z})[0]);
        ASSERT_LE(difference, m * std::fabs(h) * (1 + 1e-9) + 1e-12) << entry.name << " o" << order;
      }
    }
  }
}

// Cost: the paper's construction grows about 5x per order; the projection adds one step per two
// orders (ops as the emitted C counts them, sin and cos as one each).
TEST(Projection, CostsAFractionOfRichardsonAtHighOrder) {
  auto r8 = testing::build("gyroid", 8), p8 = testing::build("gyroid", 8, "projection");
  auto p16 = testing::build("gyroid", 16, "projection");
  EXPECT_LT(count_ops(p8->programs.offset), 0.05 * count_ops(r8->programs.offset));
  EXPECT_LT(count_ops(p16->programs.offset), 2.5 * count_ops(p8->programs.offset));
}

struct SafetyCase {
  std::string surface;
  int order;
};
void PrintTo(const SafetyCase& c, std::ostream* os) { *os << c.surface << "_o" << c.order; }

class ProjectionSafety : public ::testing::TestWithParam<SafetyCase> {};

// The grids of the safeguard test (every multiple of 1/8, t in {0.01, 0.05, 0.1}): finite values
// everywhere, and no point provably farther than t/2 from F = 0 inside a wall.
TEST_P(ProjectionSafety, FiniteEverywhereAndNeverTheWrongSideFarFromTheSurface) {
  const auto& [name, order] = GetParam();
  auto b = testing::build(name, order, "projection");
  const double m = b->bounds().gradient * 2 * M_PI;  // cell units
  Evaluator field(b->programs.field), offset(b->programs.offset), shell(b->programs.shell), normal(b->programs.normal);
  const int n = 16;  // holds every multiple of 1/8
  long far = 0, non_finite = 0, wrong_side = 0;
  for (double t : {0.01, 0.05, 0.1}) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= n; ++k) {
          const double x = double(i) / n, y = double(j) / n, z = double(k) / n;
          const double F = field({x, y, z})[0];
          const double Phi = shell({x, y, z, t})[0];
          non_finite += !std::isfinite(Phi);
          if (std::fabs(F) > t / 2 * m) {
            ++far;
            wrong_side += !(Phi > 0);
          }
          for (double h : {t / 2, -t / 2}) {
            const double phi = offset({x, y, z, h})[0];
            non_finite += !std::isfinite(phi);
            if (std::fabs(F) > std::fabs(h) * m) wrong_side += (phi > 0) != (F > 0);
            for (double c : normal({x, y, z, h})) non_finite += !std::isfinite(c);
          }
        }
  }
  EXPECT_EQ(non_finite, 0);
  EXPECT_EQ(wrong_side, 0);
  EXPECT_GT(far, 0);
}

std::vector<SafetyCase> safety_cases() {
  std::vector<SafetyCase> cases;
  for (const CatalogEntry& entry : catalog())
    for (int order = 2; order <= 16; order += 2) cases.push_back({entry.name, order});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllSurfacesOrders2To16, ProjectionSafety, ::testing::ValuesIn(safety_cases()),
                         [](const auto& test) { return test.param.surface + "_o" + std::to_string(test.param.order); });

}  // namespace
}  // namespace offsetgen
