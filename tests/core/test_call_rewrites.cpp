// The GPU backends' rewrites of printed bodies (src/emit/call_rewrites.h): one sincos per argument
// that both sin and cos take, rsqrt for divisions by a square root; and the backends' reserved names.
#include "emit/backend.h"
#include "emit/call_rewrites.h"

#include <gtest/gtest.h>

namespace offsetgen {
namespace {

std::string cuda_sincos(const std::string& argument, const std::string& s, const std::string& c) {
  return "    double " + s + ", " + c + ";\n    sincos(" + argument + ", &" + s + ", &" + c + ");\n";
}

TEST(CallRewrites, OneSincosPerSharedArgumentBeforeItsFirstUse) {
  const std::string body =
      "    const double _t0 = 2.0 * x;\n"
      "    const double _t1 = cos(_t0) * asin(_t0);\n"
      "    const double _t2 = sin(_t0) + sin(y);\n"
      "    return _t1 * _t2 * cos(_t0);\n";
  EXPECT_EQ(fuse_sincos(body, "sin", "cos", cuda_sincos),
            "    const double _t0 = 2.0 * x;\n"
            "    double _s0, _c0;\n"
            "    sincos(_t0, &_s0, &_c0);\n"
            "    const double _t1 = _c0 * asin(_t0);\n"
            "    const double _t2 = _s0 + sin(y);\n"
            "    return _t1 * _t2 * _c0;\n");
}

TEST(CallRewrites, NestedCallsFuseInnermostFirst) {
  const std::string body = "    return sin(cos(x)) + cos(cos(x)) + sin(x);\n";
  const std::string fused = fuse_sincos(body, "sin", "cos", cuda_sincos);
  EXPECT_EQ(fused,
            "    double _s0, _c0;\n    sincos(x, &_s0, &_c0);\n"
            "    double _s1, _c1;\n    sincos(_c0, &_s1, &_c1);\n"
            "    return _s1 + _c1 + _s0;\n");
}

TEST(CallRewrites, NothingToFuseLeavesTheBodyAlone) {
  const std::string body = "    return sinf(x) * cosf(y);\n";
  EXPECT_EQ(fuse_sincos(body, "sinf", "cosf", cuda_sincos), body);
}

TEST(CallRewrites, DivisionsBySquareRootsBecomeRsqrt) {
  EXPECT_EQ(use_rsqrt("    return 1.0 / sqrt(a + b);\n", "sqrt", "rsqrt"), "    return rsqrt(a + b);\n");
  EXPECT_EQ(use_rsqrt("    return (x + 1.0) / sqrtf(a * (b + c));\n", "sqrtf", "rsqrtf"),
            "    return (x + 1.0) * rsqrtf(a * (b + c));\n");
  EXPECT_EQ(use_rsqrt("    return 21.0 / sqrt(a);\n", "sqrt", "rsqrt"), "    return 21.0 * rsqrt(a);\n");
  // A reciprocal of a square-root temporary: the root stays for its other uses.
  EXPECT_EQ(
      use_rsqrt("    const float _t3 = sqrt(_t1 * _t1 + _t2);\n    const float _t4 = 1.0f / _t3;\n", "sqrt", "rsqrt"),
      "    const float _t3 = sqrt(_t1 * _t1 + _t2);\n    const float _t4 = rsqrt(_t1 * _t1 + _t2);\n");
  // Not when the temporary is more than the square root.
  const std::string partial = "    const double _t3 = sqrt(a) + b;\n    const double _t4 = 1.0 / _t3;\n";
  EXPECT_EQ(use_rsqrt(partial, "sqrt", "rsqrt"), partial);
}

TEST(GpuBackendNames, ReservedNamesAreRefusedWithTheReason) {
  const Backend& cuda = backend("cuda");
  EXPECT_TRUE(cuda.reserved("threadIdx").has_value());
  EXPECT_TRUE(cuda.reserved("make_float3").has_value());
  EXPECT_TRUE(cuda.reserved("cudaMalloc").has_value());
  EXPECT_TRUE(cuda.reserved("class").has_value());  // C++
  EXPECT_FALSE(cuda.reserved("gyroid_o4_offset").has_value());
  const Backend& opencl = backend("opencl");
  EXPECT_TRUE(opencl.reserved("kernel").has_value());
  EXPECT_TRUE(opencl.reserved("__global").has_value());
  EXPECT_TRUE(opencl.reserved("half").has_value());
  EXPECT_TRUE(opencl.reserved("float16").has_value());
  EXPECT_TRUE(opencl.reserved("image2d_t").has_value());
  EXPECT_FALSE(opencl.reserved("gyroid_o4_offsetf").has_value());
}

}  // namespace
}  // namespace offsetgen
