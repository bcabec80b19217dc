#include "offset/richardson.h"

#include <gtest/gtest.h>

namespace offsetgen {
namespace {

GiNaC::numeric q(int p, int r = 1) { return GiNaC::numeric(p, r); }

TEST(RichardsonWeights, MatchPaperTable1) {
  using V = std::vector<GiNaC::numeric>;
  EXPECT_EQ(richardson_weights(1), (V{q(1)}));
  EXPECT_EQ(richardson_weights(2), (V{q(-1), q(2)}));
  EXPECT_EQ(richardson_weights(3), (V{q(1, 2), q(-4), q(9, 2)}));
  EXPECT_EQ(richardson_weights(4), (V{q(-1, 6), q(4), q(-27, 2), q(32, 3)}));
}

TEST(RichardsonWeights, SolveTheDefiningEquationsExactlyUpToOrder12) {
  for (int m = 1; m <= 12; ++m) {
    auto w = richardson_weights(m);
    ASSERT_EQ(static_cast<int>(w.size()), m);
    GiNaC::numeric sum = 0;
    for (const auto& wj : w) sum += wj;
    EXPECT_EQ(sum, 1) << "order " << m;
    for (int i = 1; i < m; ++i) {
      GiNaC::numeric moment = 0;
      for (int j = 1; j <= m; ++j) moment += w[static_cast<size_t>(j - 1)] / GiNaC::numeric(j).power(i);
      EXPECT_EQ(moment, 0) << "order " << m << " moment " << i;
    }
  }
}

TEST(RichardsonWeights, RejectOrderZero) { EXPECT_THROW(richardson_weights(0), std::invalid_argument); }

}  // namespace
}  // namespace offsetgen
