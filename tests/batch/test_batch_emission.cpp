// What the C emitter writes for the batch API: which `_n` functions, their signatures, the helpers
// per precision, the blocked loops, and the sin/cos/sqrt rewrite of the loop bodies.
#include "emit/c_batch.h"
#include "pipeline/generate.h"

#include <gtest/gtest.h>

#include <string>

namespace offsetgen {
namespace {

std::string header(const std::string& surface, int order, std::vector<Precision> precisions,
                   const std::string& expression = "", const std::string& name = "") {
  GenerationRequest request;
  request.surface = surface;
  request.expression = expression;
  request.name = name;
  request.order = order;
  request.precisions = std::move(precisions);
  request.command = "test";
  request.file_names["c"] = "test.h";
  return generate(request).c_header();
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(BatchEmission, RewritesOnlySinAndCosCalls) {
  EXPECT_EQ(rename_trig_calls("sin(a) + cos(b) * sinf(c) - cosf(d)", "offsetgen_batch_"),
            "offsetgen_batch_sin(a) + offsetgen_batch_cos(b) * offsetgen_batch_sinf(c) - offsetgen_batch_cosf(d)");
  EXPECT_EQ(rename_trig_calls("asin(a) + acos(b) + sinh(c) + cosh(d) + _tsin(e) + x_cos(f) + sin + cos + sqrt(g)",
                              "offsetgen_batch_"),
            "asin(a) + acos(b) + sinh(c) + cosh(d) + _tsin(e) + x_cos(f) + sin + cos + sqrt(g)");
  EXPECT_EQ(rename_trig_calls("(sin(cos(x)))", "offsetgen_batch_"), "(offsetgen_batch_sin(offsetgen_batch_cos(x)))");
}

TEST(BatchEmission, RewritesTheNamedCallsAndTheirFloatSpellings) {
  EXPECT_EQ(
      rename_calls("1.0 / sqrt(a) + sqrtf(b) * sin(c) + cbrt(d) + _tsqrt(e)", {"sin", "sqrt"}, "offsetgen_batch_"),
      "1.0 / offsetgen_batch_sqrt(a) + offsetgen_batch_sqrtf(b) * offsetgen_batch_sin(c) + cbrt(d) + _tsqrt(e)");
}

TEST(BatchEmission, DoubleOnlyHeaderHasDoubleBatchFunctions) {
  const std::string h = header("schwarzp", 2, {Precision::Double});
  EXPECT_TRUE(has(h,
                  "static inline void schwarzp_o2_offset_n(size_t n, const double *x, const double *y, "
                  "const double *z, const double *h, double *OFFSETGEN_RESTRICT out)"));
  EXPECT_TRUE(has(h,
                  "static inline void schwarzp_o2_shell_n(size_t n, const double *x, const double *y, "
                  "const double *z, const double *t, double *OFFSETGEN_RESTRICT out)"));
  EXPECT_TRUE(has(h, "OFFSETGEN_BATCH_MATH_DOUBLE_V2"));
  EXPECT_FALSE(has(h, "OFFSETGEN_BATCH_MATH_FLOAT_V2"));
  EXPECT_FALSE(has(h, "_offsetf_n"));
  EXPECT_FALSE(has(h, "_field_n"));
  EXPECT_FALSE(has(h, "_normal_n"));
  // The loop bodies call the helpers, never libm's sin/cos/sqrt; the fallback and the last n % 8
  // points call the scalar function.
  const std::string loops = h.substr(h.find("schwarzp_o2_offset_n(size_t"));
  EXPECT_FALSE(has(loops, " cos(")) << loops.substr(0, 2000);
  EXPECT_FALSE(has(loops, " sqrt(")) << loops.substr(0, 2000);
  EXPECT_TRUE(has(loops, "offsetgen_batch_cos("));
  EXPECT_TRUE(has(loops, "offsetgen_batch_sqrt("));
  EXPECT_TRUE(has(loops, "if (!(fabs(out[i]) <= HUGE_VAL)) out[i] = schwarzp_o2_offset(x[i], y[i], z[i], h[i]);"));
  EXPECT_TRUE(has(loops, "for (i = blocked; i < n; ++i) out[i] = schwarzp_o2_offset(x[i], y[i], z[i], h[i]);"));
  EXPECT_TRUE(has(loops, "const size_t blocked = n - n % 8;"));
  EXPECT_TRUE(has(loops, "OFFSETGEN_SIMD_LOOP\n        for (j = 0; j < 8; ++j) {"));
  EXPECT_TRUE(has(loops, "z[i + j]"));
}

TEST(BatchEmission, BothPrecisionsGiveFloatTwins) {
  const std::string h = header("gyroid", 2, {Precision::Double, Precision::Float});
  EXPECT_TRUE(has(h,
                  "static inline void gyroid_o2_offsetf_n(size_t n, const float *x, const float *y, "
                  "const float *z, const float *h, float *OFFSETGEN_RESTRICT out)"));
  EXPECT_TRUE(has(h,
                  "static inline void gyroid_o2_shellf_n(size_t n, const float *x, const float *y, "
                  "const float *z, const float *t, float *OFFSETGEN_RESTRICT out)"));
  EXPECT_TRUE(has(h, "OFFSETGEN_BATCH_MATH_FLOAT_V2"));
  EXPECT_TRUE(has(h, "const size_t blocked = n - n % 16;"));  // float: 16 points per block
  EXPECT_TRUE(has(h, "offsetgen_batch_sqrtf("));
  EXPECT_TRUE(has(h, "if (!(fabsf(out[i]) <= HUGE_VALF)) out[i] = gyroid_o2_shellf(x[i], y[i], z[i], t[i]);"));
  // Batch functions come after every scalar function they fall back on, before the guard's end.
  EXPECT_LT(h.find("gyroid_o2_shellf("), h.find("gyroid_o2_offset_n("));
  EXPECT_LT(h.find("gyroid_o2_offset_n("), h.rfind("#endif /* OFFSETGEN_GYROID_O2_H */"));
}

TEST(BatchEmission, FloatOnlyHeaderHasOnlyFloatBatch) {
  const std::string h = header("diamond", 1, {Precision::Float});
  EXPECT_TRUE(has(h, "diamond_o1_offsetf_n("));
  EXPECT_FALSE(has(h, "diamond_o1_offset_n("));
  EXPECT_FALSE(has(h, "OFFSETGEN_BATCH_MATH_DOUBLE_V2"));
}

TEST(BatchEmission, TwoDimensionalSignatureHasNoZ) {
  const std::string h = header("", 2, {Precision::Double}, "cos(2*Pi*x) + 0.5*sin(2*Pi*y)", "wave");
  EXPECT_TRUE(has(h,
                  "static inline void wave_offset_n(size_t n, const double *x, const double *y, "
                  "const double *h, double *OFFSETGEN_RESTRICT out)"));
}

TEST(BatchEmission, TheSameRequestGivesTheSameBytes) {
  EXPECT_EQ(header("neovius", 3, {Precision::Double, Precision::Float}),
            header("neovius", 3, {Precision::Double, Precision::Float}));
}

}  // namespace
}  // namespace offsetgen
