#include "batch_cases.h"

#include "run/metadata.h"

namespace offsetgen::batch_test {

const Cases& all_cases() {
  static const Cases cases = [] {
    Cases c;
    add_gyroid_o4(c);
    add_gyroid_o4_omp(c);
    add_gyroid_o4_generic(c);
    add_gyroid_o6(c);
    add_neovius_o3(c);
    add_schwarzp_o2(c);
    add_wave2d_o3(c);
    add_expo_o2(c);
    return c;
  }();
  return cases;
}

HeaderFacts header_facts(const std::string& header) {
  const run::FileMetadata meta = run::read_metadata(std::string(OFFSETGEN_BATCH_HEADER_DIR) + "/" + header + ".h");
  return {meta.gradient_bound, meta.scale};
}

}  // namespace offsetgen::batch_test
