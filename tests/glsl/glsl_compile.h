// Offline compile check of a GLSL snippet with glslangValidator, in the four host dialects users
// paste it into. Each host calls every function the snippet defines, so each one is type-checked
// and linked as used code, not as dead code.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "glsl_source.h"

namespace offsetgen::glsl {

enum class Target {
  Es300,   // "#version 300 es" fragment shader, "precision highp float;"
  Gl330,   // "#version 330 core"
  Gl450,   // "#version 450 core"
  Vulkan,  // "#version 450", layout(location = 0) out, compiled to SPIR-V (-V)
};

const char* target_name(Target t);
inline void PrintTo(Target t, std::ostream* os) { *os << target_name(t); }  // for GoogleTest
std::vector<Target> all_targets();

struct CompileResult {
  Target target{};
  bool ok = false;
  // On failure: glslang's log followed by the offending lines, mapped back to the snippet
  // ("snippet line 12: ..."), or the reason the check could not run (e.g. no glslangValidator).
  std::string message;
  HostedSource source;  // the host shader that was compiled
};

// The host shader for `target` around `snippet`; throws std::runtime_error when a function's
// parameter type has no generated argument (structs, arrays, samplers).
HostedSource host_shader(const std::string& snippet, Target target);

// Compiles and links with `glslangValidator -l` (plus -V for Vulkan). Never throws: a missing
// validator or an unsupported snippet comes back as ok == false with the reason in `message`.
CompileResult compile_check(const std::string& snippet, Target target);
std::vector<CompileResult> compile_check_all(const std::string& snippet);

// Compiles and links a complete fragment shader (host code included) with
// `glslangValidator -l`; `target` only selects -V for Vulkan. Never throws.
CompileResult compile_fragment_shader(const HostedSource& source, Target target);

// Absolute path of glslangValidator on PATH, or "" when absent.
std::string find_glslang_validator();

}  // namespace offsetgen::glsl
