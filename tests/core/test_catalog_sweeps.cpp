// The catalog's sweep table (lowering/catalog_sweeps.h) is what the sweeps compute now, bit for bit,
// and only unmapped catalog surfaces use it. On a failure after an intended change to the sweeps or
// the catalog: tools/update_golden.sh rewrites the table, then rebuild and run it again.
#include "lowering/catalog_sweeps.h"
#include "offset/offset_model.h"
#include "pipeline/catalog_sweep_table.h"
#include "pipeline/generate.h"
#include "surfaces/expression_input.h"
#include "surfaces/lattice_map.h"
#include "test_support.h"
#include "validate/cell_domain.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

namespace offsetgen {
namespace {

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

TEST(CatalogSweeps, TheTableIsAFreshSweepBitForBit) {
  const std::vector<CatalogSweeps> fresh = sweep_catalog();
  const std::vector<CatalogSweeps>& table = catalog_sweeps_table();
  ASSERT_EQ(table.size(), fresh.size())
      << "the table and the catalog differ: run tools/update_golden.sh (it rewrites src/lowering/catalog_sweeps.inc)";
  for (size_t i = 0; i < fresh.size(); ++i) {
    SCOPED_TRACE(fresh[i].name);
    EXPECT_STREQ(table[i].name, fresh[i].name);
    EXPECT_STREQ(table[i].formula, fresh[i].formula);
    EXPECT_EQ(bits(table[i].bounds.gradient), bits(fresh[i].bounds.gradient));
    EXPECT_EQ(bits(table[i].bounds.hessian), bits(fresh[i].bounds.hessian));
    for (size_t k = 0; k < fresh[i].band_minima.size(); ++k)
      EXPECT_EQ(bits(table[i].band_minima[k]), bits(fresh[i].band_minima[k])) << "band " << k;
  }
  // The committed file is exactly what offsetgen_catalog_sweeps writes.
  EXPECT_EQ(testing::read_file(test_support::source_dir() + "/src/lowering/catalog_sweeps.inc"),
            catalog_sweeps_source(fresh));
}

// One entry serves every method and order: the sweep over the atoms each construction defines
// (Richardson's model at orders 1-4, projection's second derivatives) gives the table's bits.
TEST(CatalogSweeps, EveryConstructionsOwnSweepGivesTheTablesBits) {
  for (const CatalogEntry& entry : catalog()) {
    SCOPED_TRACE(entry.name);
    const Surface surface = catalog_surface(entry.name);
    const CatalogSweeps* known = catalog_sweeps(surface);
    ASSERT_NE(known, nullptr);
    for (int order = 1; order <= 4; ++order) {
      const OffsetModel model = build_offset_model(surface, order, /*with_gradient=*/true);
      const CellBounds swept = swept_cell_bounds(surface, model.atoms, model.field_atoms);
      EXPECT_EQ(bits(swept.gradient), bits(known->bounds.gradient)) << "richardson order " << order;
      EXPECT_EQ(bits(swept.hessian), bits(known->bounds.hessian)) << "richardson order " << order;
    }
    const auto projection = offset_method("projection").build(surface, 4);
    EXPECT_EQ(bits(projection->bounds().gradient), bits(known->bounds.gradient));
    EXPECT_EQ(bits(projection->bounds().hessian), bits(known->bounds.hessian));
  }
}

// Anything but an unmapped catalog formula is swept: the same gyroid written as an expression, the
// catalog gyroid on a map, and a catalog surface whose formula is not the one in the table.
TEST(CatalogSweeps, ExpressionsAndMappedSurfacesAreSwept) {
  const Surface expression = parse_user_expression(
      "2*(sin(2*Pi*x)*cos(2*Pi*y) + sin(2*Pi*y)*cos(2*Pi*z) + sin(2*Pi*z)*cos(2*Pi*x))", {}, "twice_gyroid");
  EXPECT_EQ(catalog_sweeps(expression), nullptr);
  // Swept, its M is twice the catalog gyroid's (the table would have given the gyroid's own).
  const auto built = offset_method("richardson").build(expression, 2);
  const CatalogSweeps* gyroid = catalog_sweeps(catalog_surface("gyroid"));
  ASSERT_NE(gyroid, nullptr);
  EXPECT_NEAR(built->bounds().gradient, 2 * gyroid->bounds.gradient, 1e-6 * gyroid->bounds.gradient);

  GenerationRequest mapped;
  mapped.surface = "gyroid";
  mapped.map = "cylindrical:12,5,5";
  mapped.domain = parse_domain("10,-5,0:20,5,10");
  EXPECT_EQ(catalog_sweeps(resolve_surface(mapped)), nullptr);

  Surface edited = catalog_surface("gyroid");
  edited.source_expr = "sin(X)*cos(Y)";
  EXPECT_EQ(catalog_sweeps(edited), nullptr);
}

// Definedness is still checked for expressions: the table spares only the catalog's sweep.
TEST(CatalogSweeps, AnUndefinedExpressionIsStillRefused) {
  GenerationRequest request;
  request.expression = "log(x - 0.5) + sin(2*Pi*y)";
  request.name = "undefined";
  try {
    build_generation(request);
    ADD_FAILURE() << "an expression undefined on half the cell was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not defined"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace offsetgen
