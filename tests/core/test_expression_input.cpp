#include "surfaces/catalog.h"
#include "surfaces/expression_input.h"

#include <gtest/gtest.h>

namespace offsetgen {
namespace {

TEST(Catalog, HasTheNineRequiredSurfaces) {
  for (const char* name : {"gyroid", "schwarzp", "diamond", "neovius", "iwp", "fischerkoch", "lidinoid", "splitp", "frd"}) {
    Surface s = catalog_surface(name);
    EXPECT_EQ(s.dims, 3) << name;
    EXPECT_FALSE(s.citation.empty()) << name;
  }
  EXPECT_EQ(catalog().size(), 9u);
}

TEST(Catalog, PaperFormulasAreExact) {
  const Symbols& sym = Symbols::get();
  GiNaC::ex X = sym.X, Y = sym.Y, Z = sym.Z;
  using GiNaC::cos;
  using GiNaC::sin;
  EXPECT_TRUE((catalog_surface("gyroid").field - (sin(X) * cos(Y) + sin(Y) * cos(Z) + sin(Z) * cos(X))).expand().is_zero());
  EXPECT_TRUE((catalog_surface("schwarzp").field - (cos(X) + cos(Y) + cos(Z))).expand().is_zero());
  EXPECT_TRUE((catalog_surface("neovius").field - (3 * (cos(X) + cos(Y) + cos(Z)) + 4 * cos(X) * cos(Y) * cos(Z)))
                  .expand()
                  .is_zero());
  EXPECT_TRUE((catalog_surface("diamond").field - (sin(X) * sin(Y) * sin(Z) + sin(X) * cos(Y) * cos(Z) +
                                                   cos(X) * sin(Y) * cos(Z) + cos(X) * cos(Y) * sin(Z)))
                  .expand()
                  .is_zero());
  EXPECT_TRUE(catalog_surface("gyroid").scale.is_equal(2 * GiNaC::Pi));
}

TEST(Catalog, UnknownNameListsTheKnownOnes) {
  try {
    catalog_surface("gyroide");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gyroid, schwarzp"), std::string::npos) << e.what();
  }
}

TEST(ExpressionInput, AbsorbsTwoPiAndKeepsDecimalsExact) {
  Surface s = parse_user_expression("cos(2*Pi*x)*cos(2*Pi*y) + a*sin(2*Pi*z)", {{"a", "0.3"}}, "mysurf");
  const Symbols& sym = Symbols::get();
  EXPECT_TRUE(s.scale.is_equal(2 * GiNaC::Pi));
  EXPECT_TRUE((s.field - (GiNaC::cos(sym.X) * GiNaC::cos(sym.Y) + GiNaC::numeric(3, 10) * GiNaC::sin(sym.Z))).expand().is_zero());
  EXPECT_EQ(s.dims, 3);
}

TEST(ExpressionInput, KeepsScaleOneWhenPiDoesNotFactorOut) {
  Surface s = parse_user_expression("x^2 + y^2 - 1/4", {}, "circle");
  EXPECT_TRUE(s.scale.is_equal(1));
  EXPECT_EQ(s.dims, 2);
}

void expect_error(const std::string& expr, const std::map<std::string, std::string>& params, const std::string& words) {
  try {
    parse_user_expression(expr, params, "s");
    FAIL() << "no error for " << expr;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(ExpressionInput, RejectsBadInputWithAClearReason) {
  expect_error("cos(x", {}, "cannot parse");
  expect_error("2*a", {{"a", "1"}}, "does not depend on x, y or z");
  expect_error("abs(x) + y", {}, "non-smooth function 'abs' at column 1");
  expect_error("x + floor(y)", {}, "non-smooth function 'floor' at column 5");
  expect_error("x + frobnicate(y)", {}, "unknown function 'frobnicate'");
  expect_error("a*x + y", {}, "unknown parameter 'a' at column 1");
  expect_error("x + y", {{"a", "1"}}, "'a' is given but the expression does not use it");
  expect_error("a*x + y", {{"a", "x"}}, "must be a constant");
  EXPECT_THROW(split_param("a"), InputError);
  EXPECT_THROW(split_param("=3"), InputError);
  EXPECT_THROW(split_param("1a=3"), InputError);
}

// Syntax errors point at the column of the text as typed (GiNaC's own messages say "line 0,
// column 0", show its rewritten text and name its source files).
TEST(ExpressionInput, SyntaxErrorsNameTheColumnAndNothingOfGiNaC) {
  struct Case {
    const char* text;
    const char* words;
  };
  for (const Case& c : {Case{"sin(x) + * cos(y)", "unexpected '*' where a number, name or '(' is expected at column 10"},
                        Case{"sin(x) + (cos(y)", "this '(' is never closed at column 10"},
                        Case{"sin(x) 3", "unexpected '3' after a complete expression at column 8"},
                        Case{"0.5*x) + y", "unbalanced ')' at column 6"},
                        Case{"x + 1.5e", "malformed exponent in a number at column 8"}}) {
    try {
      parse_user_expression(c.text, {}, "s");
      ADD_FAILURE() << "no error for " << c.text;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(c.words), std::string::npos) << message;
      EXPECT_NE(message.find(std::string("    ") + c.text + "\n"), std::string::npos) << message;  // caret line
      EXPECT_EQ(message.find("GiNaC"), std::string::npos) << message;
      EXPECT_EQ(message.find("parser.cpp"), std::string::npos) << message;
      EXPECT_EQ(message.find("line 0"), std::string::npos) << message;
    }
  }
  // Python's ** is accepted as a power.
  EXPECT_NO_THROW(parse_user_expression("x**2 + y**2 - 0.25", {}, "s"));
}

TEST(ExpressionInput, GiNaCsOwnErrorsLoseTheirSourceLocation) {
  try {
    parse_user_expression("1/0 + x", {}, "s");
    FAIL();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'1/0 + x'"), std::string::npos) << message;
    EXPECT_NE(message.find("division by zero"), std::string::npos) << message;
    EXPECT_EQ(message.find("\n"), std::string::npos) << message;
  }
}

TEST(ExpressionInput, ThicknessNamesTheColumnOfAParseError) {
  EXPECT_NO_THROW(parse_thickness_expression("0.01 + 0.02*x", {}, 3));
  try {
    parse_thickness_expression("0.01 + * x", {}, 3);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("thickness"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("column 8"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_thickness_expression("0.1*z", {}, 2), InputError);
}

}  // namespace
}  // namespace offsetgen
