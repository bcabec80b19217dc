// --name: the identifiers a prefix produces, checked against the reserved names of every requested
// language (each backend lists its rules: Backend::reserved, emit/backend.h).
#pragma once

#include "emit/backend.h"

#include <string>
#include <vector>

namespace offsetgen {

// Throws InputError naming the first emitted identifier a requested language reserves, and why.
void require_usable_prefix(const std::string& prefix, const std::vector<const Backend*>& languages);

}  // namespace offsetgen
