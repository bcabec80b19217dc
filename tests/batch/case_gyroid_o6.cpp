// Batch test case: gyroid_o6.h compiled with the "fast" flags (see CMakeLists.txt).
#include "gyroid_o6.h"
#include "gyroid_o6_ld.h"

#include "batch_cases.h"

namespace offsetgen::batch_test {

void add_gyroid_o6(Cases& c) {
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, gyroid_o6, offset, , "fast", 6, true, ld_gyroid_o6));
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, gyroid_o6, shell, , "fast", 6, true, ld_gyroid_o6));
}

}  // namespace offsetgen::batch_test
