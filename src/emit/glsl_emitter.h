// Emits a paste-safe GLSL snippet (lygia conventions) from the lowered programs.
#pragma once

#include "emit/emitted_api.h"

#include <string>
#include <vector>

namespace offsetgen {

std::string emit_glsl_snippet(const FileFacts& facts, const std::vector<EmittedFunction>& functions);

}  // namespace offsetgen
