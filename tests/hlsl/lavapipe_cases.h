// The HLSL snippets tests/hlsl/CMakeLists.txt generates, each with the double C header generated
// from the same program (offsetgen_generate LANG c hlsl), for the lavapipe comparison.
#pragma once

#include <ostream>
#include <vector>

namespace offsetgen::hlsl_test {

struct LavapipeCase {
  const char* prefix;   // "gyroid_o4", "gyroid_proj_o2", "userexpr_o3"
  const char* snippet;  // absolute path of <prefix>.hlsl
  double (*field)(double, double, double);
  double (*offset)(double, double, double, double);
  double (*shell)(double, double, double, double);
  void (*normal)(double, double, double, double, double*);
};

// In CMake's order: surfaces x richardson orders 1-4, x projection orders 2 and 4, the user expression.
const std::vector<LavapipeCase>& lavapipe_cases();

inline void PrintTo(const LavapipeCase& c, std::ostream* os) { *os << c.prefix; }  // for GoogleTest

}  // namespace offsetgen::hlsl_test
