// Batch test case: expo_o2.h compiled with the "fast" flags (see CMakeLists.txt).
#include "expo_o2.h"
#include "expo_o2_ld.h"

#include "batch_cases.h"

namespace offsetgen::batch_test {

void add_expo_o2(Cases& c) {
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, expo_o2, offset, , "fast", 2, false, ld_expo_o2));
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, expo_o2, shell, , "fast", 2, false, ld_expo_o2));
}

}  // namespace offsetgen::batch_test
