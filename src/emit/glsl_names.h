// The names GLSL (ES 3.00 through 4.60, Vulkan) and WebGL reserve, as they bear on what an emitted
// snippet declares. One place for the GLSL target's rules (a backend registry can own this file).
#pragma once

#include <optional>
#include <string>

namespace offsetgen::glsl_names {

// Why a snippet must not declare `identifier` (a function, or a macro), or nullopt when it may.
std::optional<std::string> reserved(const std::string& identifier);

}  // namespace offsetgen::glsl_names
