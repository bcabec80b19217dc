// libFuzzer target: the metadata reader of `offsetgen check` (the `/* offsetgen-metadata {...} */`
// block of a header or GLSL snippet). A damaged or foreign file must come back as InputError naming
// the problem; any other exception, crash, leak or undefined behaviour is a finding.
#include "run/metadata.h"
#include "surfaces/surface.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    offsetgen::run::parse_metadata(text);
  } catch (const offsetgen::InputError&) {
    // the expected answer to a damaged block
  }
  return 0;
}
