// Batch test case: wave2d_o3.h compiled with the "fast" flags (see CMakeLists.txt).
#include "wave2d_o3.h"
#include "wave2d_o3_ld.h"

#include "batch_cases.h"

namespace offsetgen::batch_test {

void add_wave2d_o3(Cases& c) {
  c.doubles.push_back(OFFSETGEN_BATCH_CASE2(double, wave2d_o3, offset, , "fast", 3, true, ld_wave2d_o3));
  c.doubles.push_back(OFFSETGEN_BATCH_CASE2(double, wave2d_o3, shell, , "fast", 3, true, ld_wave2d_o3));
  c.floats.push_back(OFFSETGEN_BATCH_CASE2(float, wave2d_o3, offset, f, "fast", 3, true, wave2d_o3));
  c.floats.push_back(OFFSETGEN_BATCH_CASE2(float, wave2d_o3, shell, f, "fast", 3, true, wave2d_o3));
}

}  // namespace offsetgen::batch_test
