// Finds and reads the skeletons of emitted files (templates/*.in), which are rendered with fmt.
#pragma once

#include <string>

namespace offsetgen {

// Search order: $OFFSETGEN_TEMPLATE_DIR, <executable>/../share/offsetgen/templates (installed),
// then the source tree's templates/ (build tree). Throws std::runtime_error naming the paths tried.
std::string load_template(const std::string& name);

// The directory load_template reads from (for --version and diagnostics).
std::string template_directory();

}  // namespace offsetgen
