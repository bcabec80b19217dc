// Batch test case: gyroid_o4.h compiled with the "omp" flags (see CMakeLists.txt).
#include "gyroid_o4.h"
#include "gyroid_o4_ld.h"

#include "batch_cases.h"

namespace offsetgen::batch_test {

void add_gyroid_o4_omp(Cases& c) {
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, gyroid_o4, offset, , "omp", 4, true, ld_gyroid_o4));
  c.doubles.push_back(OFFSETGEN_BATCH_CASE3(double, gyroid_o4, shell, , "omp", 4, true, ld_gyroid_o4));
  c.floats.push_back(OFFSETGEN_BATCH_CASE3(float, gyroid_o4, offset, f, "omp", 4, true, gyroid_o4));
  c.floats.push_back(OFFSETGEN_BATCH_CASE3(float, gyroid_o4, shell, f, "omp", 4, true, gyroid_o4));
}

}  // namespace offsetgen::batch_test
