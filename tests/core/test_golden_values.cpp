// Compiles the committed golden headers (as C++ here; as strict C99 by the golden_c99_* tests) and
// checks their values against the 40-digit symbolic reference, and the float twins against double.
#include "offset/offset_reference.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "diamond_o1.h"
#include "diamond_o2.h"
#include "diamond_o3.h"
#include "diamond_o4.h"
#include "gyroid_proj_o2.h"
#include "gyroid_proj_o4.h"
#include "gyroid_proj_o6.h"
#include "gyroid_proj_o8.h"
#include "schwarzp_proj_o2.h"
#include "schwarzp_proj_o4.h"
#include "schwarzp_proj_o6.h"
#include "schwarzp_proj_o8.h"
#include "neovius_proj_o2.h"
#include "neovius_proj_o4.h"
#include "neovius_proj_o6.h"
#include "neovius_proj_o8.h"
#include "diamond_proj_o2.h"
#include "diamond_proj_o4.h"
#include "diamond_proj_o6.h"
#include "diamond_proj_o8.h"
#include "gyroid_o1.h"
#include "gyroid_o2.h"
#include "gyroid_o3.h"
#include "gyroid_o4.h"
#include "neovius_o1.h"
#include "neovius_o2.h"
#include "neovius_o3.h"
#include "neovius_o4.h"
#include "schwarzp_o1.h"
#include "schwarzp_o2.h"
#include "schwarzp_o3.h"
#include "schwarzp_o4.h"

namespace offsetgen {
namespace {

struct Emitted {
  const char* method;
  const char* surface;
  int order;
  double (*offset)(double, double, double, double);
  double (*shell)(double, double, double, double);
  float (*offsetf)(float, float, float, float);
  void (*normal)(double, double, double, double, double*);
};

#define OFFSETGEN_ENTRY(s, m) \
  Emitted{"richardson", #s, m, s##_o##m##_offset, s##_o##m##_shell, s##_o##m##_offsetf, s##_o##m##_normal}
#define OFFSETGEN_ORDERS(s) OFFSETGEN_ENTRY(s, 1), OFFSETGEN_ENTRY(s, 2), OFFSETGEN_ENTRY(s, 3), OFFSETGEN_ENTRY(s, 4)
#define OFFSETGEN_PROJ(s, m)                                                                             \
  Emitted{"projection", #s, m, s##_proj_o##m##_offset, s##_proj_o##m##_shell, s##_proj_o##m##_offsetf, \
          s##_proj_o##m##_normal}
#define OFFSETGEN_PROJ_ORDERS(s) OFFSETGEN_PROJ(s, 2), OFFSETGEN_PROJ(s, 4), OFFSETGEN_PROJ(s, 6), OFFSETGEN_PROJ(s, 8)
// clang-format off
const Emitted kGolden[] = {
    OFFSETGEN_ORDERS(gyroid), OFFSETGEN_ORDERS(schwarzp), OFFSETGEN_ORDERS(neovius), OFFSETGEN_ORDERS(diamond),
    OFFSETGEN_PROJ_ORDERS(gyroid), OFFSETGEN_PROJ_ORDERS(schwarzp), OFFSETGEN_PROJ_ORDERS(neovius),
    OFFSETGEN_PROJ_ORDERS(diamond)};
// clang-format on

TEST(GoldenValues, CompiledHeadersMatchThe40DigitReference) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0), step(-0.05, 0.05);
  for (const Emitted& e : kGolden) {
    auto b = testing::build(e.surface, e.order, e.method);
    OffsetReference reference(b->surface, *b->construction);
    double worst = 0, worst_float = 0, worst_normal = 0;
    Evaluator normal(b->programs.normal);
    for (int i = 0; i < 20; ++i) {
      const double x = unit(rng), y = unit(rng), z = unit(rng), h = step(rng);
      std::vector<GiNaC::numeric> p = {x, y, z};
      double grad = 0;
      for (const auto& g : reference.field_gradient(p)) grad += g.to_double() * g.to_double();
      const double ref = reference.offset(p, h).to_double();
      const double got = e.offset(x, y, z, h);
      worst = std::max(worst, std::fabs(got - ref) / std::max(std::sqrt(grad), 1.0));
      worst_float = std::max(worst_float, std::fabs(double(e.offsetf(float(x), float(y), float(z), float(h))) - got));
      EXPECT_NEAR(e.shell(x, y, z, 2 * std::fabs(h)),
                  e.offset(x, y, z, std::fabs(h)) * e.offset(x, y, z, -std::fabs(h)), 1e-12);
      double n[3];
      e.normal(x, y, z, h, n);
      auto expected = normal({x, y, z, h});
      for (int c = 0; c < 3; ++c)
        worst_normal = std::max(worst_normal, std::fabs(n[c] - expected[static_cast<size_t>(c)]));
      EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
    }
    EXPECT_LT(worst, 1e-12) << e.method << " " << e.surface << " o" << e.order;
    EXPECT_LT(worst_float, 2e-5) << e.method << " " << e.surface << " o" << e.order;
    EXPECT_LT(worst_normal, 1e-13) << e.method << " " << e.surface << " o" << e.order;
    std::cout << e.surface << " o" << e.order << ": zero-set shift " << worst << ", float deviation " << worst_float
              << "\n";
  }
}

}  // namespace
}  // namespace offsetgen
