// The names C and C++ reserve, as they bear on what an emitted header declares at file scope: the
// header compiles as C99 and as C++17, so both languages' rules apply. One place for the C target's
// rules (a backend registry can own this file).
#pragma once

#include <optional>
#include <string>

namespace offsetgen::c_names {

// Why a header must not declare `identifier` (a function at file scope, or a macro), or nullopt
// when it may.
std::optional<std::string> reserved(const std::string& identifier);

}  // namespace offsetgen::c_names
