// Batch test case: neovius_o3.h compiled with the "fast" flags (see CMakeLists.txt).
#include "neovius_o3.h"
#include "neovius_o3_ld.h"

#include "batch_cases.h"

namespace offsetgen::batch_test {

void add_neovius_o3(Cases& c) {
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, neovius_o3, offset, , "fast", 3, true, ld_neovius_o3));
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, neovius_o3, shell, , "fast", 3, true, ld_neovius_o3));
  c.floats.push_back(OFFSETGEN_BATCH_CASE3(float, neovius_o3, offset, f, "fast", 3, true, neovius_o3));
  c.floats.push_back(OFFSETGEN_BATCH_CASE3(float, neovius_o3, shell, f, "fast", 3, true, neovius_o3));
}

}  // namespace offsetgen::batch_test
