// Batch test case: schwarzp_o2.h compiled with the "fast" flags (see CMakeLists.txt).
#include "schwarzp_o2.h"
#include "schwarzp_o2_ld.h"

#include "batch_cases.h"

namespace offsetgen::batch_test {

void add_schwarzp_o2(Cases& c) {
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, schwarzp_o2, offset, , "fast", 2, true, ld_schwarzp_o2));
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, schwarzp_o2, shell, , "fast", 2, true, ld_schwarzp_o2));
}

}  // namespace offsetgen::batch_test
