// Pins the op-counting rules behind "Total ops: N" and the printer's output for small programs.
#include "emit/printer.h"
#include "lowering/program.h"

#include <gtest/gtest.h>

namespace offsetgen {
namespace {

TEST(OpCount, EachOperationCallComparisonAndSelectCountsOnce) {
  Program p({"x", "y"});
  NodeId x = p.input(0), y = p.input(1);
  NodeId s = p.call(Fn::Sin, x);                  // 1
  NodeId prod = p.mul(s, y);                      // 1
  NodeId sum = p.add(prod, p.constant(2.0));      // 1 (constants are free)
  NodeId q = p.div(sum, p.sqrt(y));               // 2
  NodeId c = p.select(p.less_eq(p.abs(q), p.constant(3.0)), q, p.neg(y));  // abs, <=, select, neg = 4
  p.add_output("a", c);
  p.add_output("b", prod);                         // reused nodes count once
  EXPECT_EQ(count_ops(p), 9);
}

TEST(OpCount, SharedSubexpressionsAreBuiltOnce) {
  Program p({"x"});
  NodeId x = p.input(0);
  NodeId a = p.call(Fn::Cos, p.mul(p.constant(2.0), x));
  NodeId b = p.call(Fn::Cos, p.mul(x, p.constant(2.0)));  // same node: commutative operands are ordered
  EXPECT_EQ(a, b);
  p.add_output("o", p.add(a, b));
  EXPECT_EQ(count_ops(p), 3);
}

TEST(OpCount, IntegerPowersAreMultipliesAndSignsCancel) {
  Program p({"x"});
  NodeId x = p.input(0);
  NodeId x4 = p.integer_power(x, 4);  // x2 = x*x, x4 = x2*x2
  p.add_output("o", p.mul(p.neg(x4), p.neg(p.constant(1.5))));
  EXPECT_EQ(count_ops(p), 3);
  PrintedBody body = print_program(p, Dialect("c", Precision::Double), {"x"});
  ASSERT_EQ(body.temporaries.size(), 1u);
  EXPECT_EQ(body.temporaries[0], "const double _t0 = x * x;");
  EXPECT_EQ(body.outputs[0].find("pow"), std::string::npos);
}

TEST(Printer, SpellsEachDialect) {
  Program p({"x"});
  NodeId x = p.input(0);
  p.add_output("o", p.sub(p.call(Fn::Sin, x), p.mul(p.constant(2.0), p.sqrt(x))));
  auto c = print_program(p, Dialect("c", Precision::Double), {"x"});
  auto f = print_program(p, Dialect("c", Precision::Float), {"x"});
  auto g = print_program(p, Dialect("glsl", Precision::Float), {"p.x"});
  EXPECT_EQ(c.temporaries.size(), 0u);
  EXPECT_NE(c.outputs[0].find("sin(x)"), std::string::npos) << c.outputs[0];
  EXPECT_NE(c.outputs[0].find("2.0"), std::string::npos) << c.outputs[0];
  EXPECT_NE(f.outputs[0].find("sinf(x)"), std::string::npos) << f.outputs[0];
  EXPECT_NE(f.outputs[0].find("2.0f"), std::string::npos) << f.outputs[0];
  EXPECT_NE(f.outputs[0].find("sqrtf(x)"), std::string::npos) << f.outputs[0];
  EXPECT_NE(g.outputs[0].find("sin(p.x)"), std::string::npos) << g.outputs[0];
  EXPECT_EQ(g.outputs[0].find("2.0f"), std::string::npos) << g.outputs[0];
}

TEST(Printer, ConstantsAreLossless) {
  Dialect c("c", Precision::Double);
  EXPECT_EQ(c.literal(6.283185307179586), "6.2831853071795862");
  EXPECT_EQ(c.literal(2.0), "2.0");
  EXPECT_EQ(c.literal(1e-5), "1.0000000000000001e-05");
  EXPECT_EQ(std::stod(c.literal(0.1)), 0.1);
  Dialect g("glsl", Precision::Float);
  EXPECT_EQ(g.literal(3.0), "3.0");
  EXPECT_EQ(g.literal(-3.0), "(-3.0)");
  EXPECT_EQ(g.literal(1e-30), "1.0e-30");
}

}  // namespace
}  // namespace offsetgen
