// Runs a GLSL snippet on Mesa llvmpipe (headless EGL, no GPU needed) over many points and returns
// the exact float results; `offsetgen check` judges a snippet's values with it, and the GLSL tests
// (tests/glsl) use it too. Two independent paths:
//   - Compute: desktop OpenGL 4.3 compute shader, inputs/outputs in shader storage buffers;
//   - Fragment: GLSL ES 3.00 fragment shader whose host says "precision mediump float;" on
//     purpose (the snippet's own highp must protect it), inputs from an RGBA32F texture via
//     texelFetch, results written as floatBitsToUint into an RGBA32UI target and read back
//     bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace offsetgen::glsl {

using Sample = std::array<float, 4>;

enum class Path { Compute, Fragment };
const char* path_name(Path p);
inline void PrintTo(Path p, std::ostream* os) { *os << path_name(p); }  // for GoogleTest
std::vector<Path> all_paths();

struct RunStats {
  double compile_s = 0.0;  // compile + link; 0 when the program came from the cache
  double run_s = 0.0;      // upload + execute + read back; Mesa JIT-compiles the shader on its
                           // first dispatch/draw, so a first run also pays for code generation
  std::size_t points = 0;
};

// Evaluates `call_expr` once per input point. In the expression `p` is the point (highp vec4),
// e.g. "gyroid_o4_offset(p.xyz, p.w)". The expression's type must be float (components == 1)
// or vec2/vec3/vec4 (components == 2/3/4). Returns inputs.size() * components floats, point-major.
// Throws gl::Unavailable (no EGL/driver; the message names the packages), gl::ShaderError
// (compile error, annotated with snippet lines) or std::runtime_error.
std::vector<float> run(Path path, const std::string& snippet, const std::string& call_expr,
                       const std::vector<Sample>& inputs, int components = 1, RunStats* stats = nullptr);

}  // namespace offsetgen::glsl
