// Runs a GLSL snippet as a user's WebGL2 page does: a GLSL ES 3.00 fragment shader in headless
// Chromium, WebGL2 on ANGLE over SwiftShader (--use-angle=swiftshader), the software GPU whose
// builtin sin/cos are off by 1.9e-4 (issue 14). The page reads the points from an RGBA32F texture
// with texelFetch, writes floatBitsToUint of each result into an RGBA32UI target, and reads it back
// bit for bit with readPixels; --dump-dom carries the bits out as base64.
#pragma once

#include <string>
#include <vector>

#include "run/glsl_executor.h"

namespace offsetgen::glsl_test {

struct WebGl2Job {
  std::string snippet;         // pasted after the host's precision statement
  std::string host_precision;  // "mediump" or "highp": the host's `precision ... float;`
  std::string call_expr;       // in terms of `p` (highp vec4), e.g. "gyroid_o4_offset(p.xyz, p.w)"
  int components = 1;          // 1..4
};

// The chromium executable the tests run (configure-time find_program), or "" when none was found.
std::string chromium_executable();

// One page, one Chromium run (about 15 s, mostly Chromium's start), every job over every point: result[j] has
// inputs.size() * jobs[j].components floats, point-major. Throws std::runtime_error with the page's message (shader
// info log, no WebGL2) or Chromium's output when no result comes back. `work_dir` holds the page.
std::vector<std::vector<float>> run_webgl2(const std::vector<WebGl2Job>& jobs, const std::vector<glsl::Sample>& inputs,
                                           const std::string& work_dir);

}  // namespace offsetgen::glsl_test
