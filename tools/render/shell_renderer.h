// Ray-marched pictures of the shell Phi(x, t) < 0 given by a generated GLSL snippet, rendered
// headless (llvmpipe) into an RGBA image. The snippet is pasted byte for byte into the shader.
#pragma once

#include <string>

#include "png_io.h"
#include "run/glsl_source.h"
#include "run/headless_gl.h"

namespace offsetgen::render {

struct Options {
  std::string snippet;                  // the .glsl file's contents, pasted verbatim
  std::string prefix;                   // e.g. "gyroid_o4": functions are <prefix>_shell, _field, ...
  double thickness = 0.1;               // total wall thickness t (cell length 1)
  bool graded = false;                  // use <prefix>_graded(p) instead of <prefix>_shell(p, t)
  int cells = 1;                        // renders the box [0, cells]^3 ...
  int box[3] = {0, 0, 0};               // ... or [0, box[0]] x [0, box[1]] x [0, box[2]] when all are > 0
  double view[3] = {0.70, 0.46, 0.55};  // direction from the box centre towards the eye
  int width = 512;
  int height = 512;
  int samples = 1;              // samples x samples supersampling per pixel
  double step = 0.0;            // march step; 0 = 0.4 * thickness (walls thinner than a step can be missed)
  gl::Api api = gl::Api::Es30;  // GLSL ES 3.00 or GL 4.3 core fragment shader
};

// The exact background colour (8-bit), so tests and users can tell wall pixels from background.
constexpr unsigned char kBackground[3] = {255, 255, 255};

struct Timing {
  double compile_s = 0.0;  // shader compile + link
  double render_s = 0.0;   // draw + read back
};

// Cells along x, y, z: `box` when set, else `cells` each way.
void box_cells(const Options& options, int out[3]);

// Fragment shader source (snippet at its recorded position) for `options`.
glsl::HostedSource fragment_source(const Options& options);

// Renders; throws gl::Unavailable, gl::ShaderError (annotated with snippet lines) or
// std::runtime_error (bad options).
png::Image render(const Options& options, Timing* timing = nullptr);

}  // namespace offsetgen::render
