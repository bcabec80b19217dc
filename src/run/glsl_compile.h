// Item 6 of `offsetgen check`: an emitted GLSL snippet compiled with glslangValidator in the four
// host dialects it is meant for. Each host shader calls every function the metadata promises, so
// they are type-checked as used code.
#pragma once

#include "run/metadata.h"

#include <string>
#include <vector>

namespace offsetgen::run {

enum class GlslTarget { Es300, Gl330, Gl450, Vulkan };

struct GlslCompileResult {
  GlslTarget target{};
  std::string name;  // "GLSL ES 3.00 (fragment)"
  std::vector<std::string> command;
  bool ok = false;
  std::string output;  // glslangValidator's log, verbatim, then "snippet line N: ..." notes
};

std::string glsl_target_name(GlslTarget target);

// The host fragment shader for `target` around `snippet`; `snippet_first_line` receives the line
// of the host on which the snippet starts.
std::string glsl_host_shader(const std::string& snippet, const FileMetadata& meta, GlslTarget target,
                             int* snippet_first_line = nullptr);

// Throws InputError when glslangValidator is not on PATH (Debian: glslang-tools).
// `display_name` names the snippet in the line notes ("[gyroid_o4.glsl line 55]").
std::vector<GlslCompileResult> compile_glsl(const std::string& snippet, const FileMetadata& meta,
                                            const std::string& display_name);

}  // namespace offsetgen::run
