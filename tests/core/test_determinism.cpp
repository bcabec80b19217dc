#include "pipeline/generate.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace offsetgen {
namespace {

TEST(Determinism, SameRequestGivesSameBytesInProcess) {
  GenerationRequest r;
  r.surface = "neovius";
  r.order = 4;
  r.languages = {"c", "glsl"};
  r.precisions = {Precision::Double, Precision::Float};
  Generation a = generate(r), b = generate(r);
  EXPECT_EQ(a.c_header(), b.c_header());
  EXPECT_EQ(a.glsl_snippet(), b.glsl_snippet());
}

// Separate processes get different address-space layouts, hence different GiNaC hash orders.
TEST(Determinism, SameCommandGivesSameBytesAcrossProcesses) {
  std::string first;
  for (int run = 0; run < 4; ++run) {
    std::string dir = testing::scratch_dir("determinism" + std::to_string(run));
    auto r = testing::run_offsetgen("generate --surface lidinoid --order 3 --lang all --out-dir " + dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::string bytes = testing::read_file(dir + "/lidinoid_o3.h") + testing::read_file(dir + "/lidinoid_o3.glsl");
    if (run == 0) first = bytes;
    EXPECT_EQ(bytes, first) << "run " << run;
  }
}

}  // namespace
}  // namespace offsetgen
