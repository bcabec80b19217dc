// --name: the identifiers a prefix produces, checked against the reserved names of every requested
// language (emit/c_names.h, emit/glsl_names.h).
#pragma once

#include <string>

namespace offsetgen {

// Throws InputError naming the first emitted identifier a requested language reserves, and why.
void require_usable_prefix(const std::string& prefix, bool c, bool glsl);

}  // namespace offsetgen
