// The WGSL snippets the build generates (tests/wgsl/CMakeLists.txt), each with the functions of its
// double C header: the WGSL output of a surface/order is compared with the C output of the same
// lowered program.
#pragma once

#include <ostream>
#include <vector>

namespace offsetgen::wgsl_test {

struct WgslCase {
  const char* prefix;   // e.g. "gyroid_o4", "gyroid_proj_o2", "userexpr_o3"
  const char* snippet;  // absolute path of the generated .wgsl
  double (*field)(double, double, double);
  double (*offset)(double, double, double, double);
  double (*shell)(double, double, double, double);
  void (*normal)(double, double, double, double, double*);
};

const std::vector<WgslCase>& wgsl_cases();

inline void PrintTo(const WgslCase& c, std::ostream* os) { *os << c.prefix; }

}  // namespace offsetgen::wgsl_test
