#include "shell_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace offsetgen::render {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Fails early, with the functions the snippet does define, instead of a driver error later.
void require_function(const std::vector<glsl::GlslFunction>& fns, const std::string& name,
                      std::size_t n_params) {
  for (const auto& f : fns) {
    if (f.name != name) continue;
    if (f.params.size() != n_params || f.params[0].type != "vec3") {
      throw std::runtime_error(name + " must take (vec3" + (n_params == 2 ? ", float)" : ")") +
                               ": render_shell draws 3D surfaces only");
    }
    return;
  }
  std::string have;
  for (const auto& f : fns) have += " " + f.name;
  throw std::runtime_error("the snippet defines no " + name + " (check --prefix); it defines:" +
                           (have.empty() ? std::string(" nothing") : have));
}

// Full-screen triangle from gl_VertexID: no vertex buffers needed.
std::string vertex_source(gl::Api api) {
  return gl::version_line(api) +
         "void main() {\n"
         "  vec2 v = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - "
         "1.0);\n"
         "  gl_Position = vec4(v, 0.0, 1.0);\n"
         "}\n";
}

// Host code after the snippet. Host names start with "rs_" / "u_" to stay clear of snippet names.
std::string epilogue(const Options& o) {
  const std::string& P = o.prefix;
  std::string s = R"(
// ---- render_shell host (everything above this line is the snippet, verbatim) ----
uniform vec2 u_resolution;
uniform vec3 u_box;
uniform float u_thickness;
uniform float u_step;
uniform vec3 u_eye;
uniform vec3 u_target;
uniform int u_samples;
out vec4 o_color;

const vec3 rs_background = vec3(1.0);
const vec3 rs_color_pos = vec3(0.90, 0.58, 0.28);  // wall face on the F > 0 side
const vec3 rs_color_neg = vec3(0.32, 0.56, 0.86);  // wall face on the F < 0 side
const vec3 rs_color_cut = vec3(0.80, 0.80, 0.76);  // wall cut open by the box faces

)";
  if (o.graded) {
    s += "float rs_shell(vec3 p) { return " + P + "_graded(p); }\n";
    // t(p) is baked into _graded, so the offset side is unknown: use grad Phi, which points out
    // of the wall (Phi < 0 inside) on both of its faces.
    s += "vec3 rs_normal(vec3 p, float side) {\n"
         "  const float e = 1.0e-3;\n"
         "  vec3 g = vec3(rs_shell(p + vec3(e, 0.0, 0.0)) - rs_shell(p - vec3(e, 0.0, 0.0)),\n"
         "                rs_shell(p + vec3(0.0, e, 0.0)) - rs_shell(p - vec3(0.0, e, 0.0)),\n"
         "                rs_shell(p + vec3(0.0, 0.0, e)) - rs_shell(p - vec3(0.0, 0.0, e)));\n"
         "  return g * inversesqrt(max(dot(g, g), 1.0e-30));\n"
         "}\n";
  } else {
    s += "float rs_shell(vec3 p) { return " + P + "_shell(p, u_thickness); }\n";
    // Face on the F > 0 side is offset(p, +t/2) = 0 with the wall where it is negative, so the
    // outward normal is +grad; on the F < 0 side the wall has offset(p, -t/2) > 0: use -grad.
    s += "vec3 rs_normal(vec3 p, float side) {\n"
         "  return side * " +
         P +
         "_normal(p, side * 0.5 * u_thickness);\n"
         "}\n";
  }
  s += "float rs_side(vec3 p) { return " + P + "_field(p) >= 0.0 ? 1.0 : -1.0; }\n";
  s += R"(
// Slab test against the box [0, u_box]; returns entry/exit distances and the entry face normal.
bool rs_box(vec3 ro, vec3 rd, out float t0, out float t1, out vec3 n0) {
  vec3 d = mix(rd, vec3(1.0e-8), lessThan(abs(rd), vec3(1.0e-8)));
  vec3 ta = (vec3(0.0) - ro) / d;
  vec3 tb = (u_box - ro) / d;
  vec3 tmin = min(ta, tb);
  vec3 tmax = max(ta, tb);
  t0 = max(max(tmin.x, tmin.y), tmin.z);
  t1 = min(min(tmax.x, tmax.y), tmax.z);
  if (tmin.x >= tmin.y && tmin.x >= tmin.z) n0 = vec3(-sign(d.x), 0.0, 0.0);
  else if (tmin.y >= tmin.z) n0 = vec3(0.0, -sign(d.y), 0.0);
  else n0 = vec3(0.0, 0.0, -sign(d.z));
  return t1 > max(t0, 0.0);
}

vec3 rs_shade(vec3 n, vec3 rd, vec3 base) {
  vec3 key = normalize(vec3(0.45, 0.25, 0.85));
  float diffuse = max(dot(n, key), 0.0);
  float head = max(dot(n, -rd), 0.0);  // a light at the eye keeps back-lit walls readable
  float spec = pow(max(dot(reflect(-key, n), -rd), 0.0), 40.0);
  return min(base * (0.20 + 0.55 * diffuse + 0.30 * head) + vec3(0.22 * spec), vec3(1.0));
}

// March until the first sample inside the wall (rs_shell < 0), then bisect the sign change.
vec3 rs_trace(vec3 ro, vec3 rd) {
  float t0, t1;
  vec3 n0;
  if (!rs_box(ro, rd, t0, t1, n0)) return rs_background;
  float t = max(t0, 0.0);
  if (rs_shell(ro + t * rd) < 0.0) return rs_shade(n0, rd, rs_color_cut);
  int steps = min(int(ceil((t1 - t) / u_step)), 8192);
  for (int i = 0; i < steps; ++i) {
    float tn = min(t + u_step, t1);
    if (rs_shell(ro + tn * rd) < 0.0) {
      float a = t, b = tn;
      for (int k = 0; k < 20; ++k) {
        float m = 0.5 * (a + b);
        if (rs_shell(ro + m * rd) < 0.0) b = m; else a = m;
      }
      vec3 p = ro + b * rd;
      float side = rs_side(p);
      vec3 n = rs_normal(p, side);
      if (dot(n, rd) > 0.0) n = -n;  // bisection may land a hair on the other side
      return rs_shade(n, rd, side > 0.0 ? rs_color_pos : rs_color_neg);
    }
    t = tn;
  }
  return rs_background;
}

void main() {
  vec3 fwd = normalize(u_target - u_eye);
  vec3 right = normalize(cross(fwd, vec3(0.0, 0.0, 1.0)));
  vec3 up = cross(right, fwd);
  const float focal = 1.4;  // uv spans [-0.5, 0.5]: 2 atan(0.5 / 1.4) = 39 degrees vertical
  vec3 sum = vec3(0.0);
  for (int sy = 0; sy < u_samples; ++sy) {
    for (int sx = 0; sx < u_samples; ++sx) {
      vec2 sub = (vec2(float(sx), float(sy)) + 0.5) / float(u_samples) - 0.5;
      vec2 uv = (gl_FragCoord.xy + sub - 0.5 * u_resolution) / u_resolution.y;
      vec3 rd = normalize(focal * fwd + uv.x * right + uv.y * up);
      sum += rs_trace(u_eye, rd);
    }
  }
  o_color = vec4(sum / float(u_samples * u_samples), 1.0);
}
)";
  return s;
}

void validate(const Options& o) {
  if (o.prefix.empty()) throw std::runtime_error("no prefix given");
  if (!(o.thickness > 0.0) && !o.graded) throw std::runtime_error("thickness must be > 0");
  if (o.cells < 1 || o.cells > 16) throw std::runtime_error("cells must be in 1..16");
  const bool box_set = o.box[0] > 0 || o.box[1] > 0 || o.box[2] > 0;
  for (int c : o.box) {
    if (box_set && (c < 1 || c > 16)) throw std::runtime_error("box cells must be in 1..16");
  }
  const double v2 = o.view[0] * o.view[0] + o.view[1] * o.view[1] + o.view[2] * o.view[2];
  if (!(v2 > 1e-12) || o.view[0] * o.view[0] + o.view[1] * o.view[1] < 1e-6 * v2) {
    throw std::runtime_error("view direction must be nonzero and not vertical");
  }
  if (o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192) {
    throw std::runtime_error("size must be within 1x1 .. 8192x8192");
  }
  if (o.samples < 1 || o.samples > 8) throw std::runtime_error("samples must be in 1..8");
  const auto fns = glsl::scan_functions(o.snippet);
  require_function(fns, o.prefix + "_field", 1);
  if (o.graded) {
    require_function(fns, o.prefix + "_graded", 1);
  } else {
    require_function(fns, o.prefix + "_shell", 2);
    require_function(fns, o.prefix + "_normal", 2);
  }
}

struct Vec3 {
  double x, y, z;
};
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalized(Vec3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

// Eye on the line from the box centre along `view`, as close as it can be while all eight box
// corners project inside the frame (with a small margin): the box fills the picture.
// Must agree with the shader: focal length 1.4, uv = (frag - res/2) / res.y.
void set_camera(const gl::Functions& gl, GLuint program, const Options& o) {
  int cells[3];
  box_cells(o, cells);
  const Vec3 size{static_cast<double>(cells[0]), static_cast<double>(cells[1]),
                  static_cast<double>(cells[2])};
  const Vec3 centre = 0.5 * size;
  const Vec3 d = normalized({o.view[0], o.view[1], o.view[2]});
  const Vec3 fwd = -1.0 * d;
  const Vec3 right = normalized(cross(fwd, {0.0, 0.0, 1.0}));
  const Vec3 up = cross(right, fwd);
  constexpr double kFocal = 1.4, kMargin = 0.94;
  const double half_w = 0.5 * kMargin * static_cast<double>(o.width) / o.height;
  const double half_h = 0.5 * kMargin;
  double dist = 0.0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? size.x : 0.0, (i & 2) ? size.y : 0.0, (i & 4) ? size.z : 0.0};
    const Vec3 q = corner - centre;
    // depth of the corner = dist + q.fwd must reach focal * |q.right| / half_w (and likewise up)
    dist = std::max(dist, kFocal * std::abs(dot(q, right)) / half_w - dot(q, fwd));
    dist = std::max(dist, kFocal * std::abs(dot(q, up)) / half_h - dot(q, fwd));
  }
  const Vec3 eye{centre.x + dist * d.x, centre.y + dist * d.y, centre.z + dist * d.z};
  gl.Uniform3f(gl.GetUniformLocation(program, "u_target"), static_cast<float>(centre.x),
               static_cast<float>(centre.y), static_cast<float>(centre.z));
  gl.Uniform3f(gl.GetUniformLocation(program, "u_eye"), static_cast<float>(eye.x),
               static_cast<float>(eye.y), static_cast<float>(eye.z));
  gl.Uniform3f(gl.GetUniformLocation(program, "u_box"), static_cast<float>(size.x),
               static_cast<float>(size.y), static_cast<float>(size.z));
}

}  // namespace

void box_cells(const Options& o, int out[3]) {
  const bool box_set = o.box[0] > 0 || o.box[1] > 0 || o.box[2] > 0;
  for (int i = 0; i < 3; ++i) out[i] = box_set ? o.box[i] : o.cells;
}

glsl::HostedSource fragment_source(const Options& o) {
  const std::string prologue =
      gl::version_line(o.api) + "precision highp float;\nprecision highp int;\n";
  return glsl::assemble(prologue, o.snippet, epilogue(o));
}

png::Image render(const Options& o, Timing* timing) {
  validate(o);
  const gl::Functions& gl = gl::make_current(o.api);

  auto t_compile = Clock::now();
  const GLuint program =
      gl::build_program(gl, {{GL_VERTEX_SHADER, glsl::assemble(vertex_source(o.api), "", "")},
                             {GL_FRAGMENT_SHADER, fragment_source(o)}});
  const double compile_s = seconds_since(t_compile);

  auto t_render = Clock::now();
  GLuint fbo = 0, rbo = 0, vao = 0;
  gl.GenRenderbuffers(1, &rbo);
  gl.BindRenderbuffer(GL_RENDERBUFFER, rbo);
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, o.width, o.height);
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbo);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("RGBA8 framebuffer incomplete");
  }
  gl.GenVertexArrays(1, &vao);  // core profile refuses draws without a vertex array object
  gl.BindVertexArray(vao);
  gl.Viewport(0, 0, o.width, o.height);
  gl.UseProgram(program);
  gl.Uniform2f(gl.GetUniformLocation(program, "u_resolution"), static_cast<float>(o.width),
               static_cast<float>(o.height));
  gl.Uniform1f(gl.GetUniformLocation(program, "u_thickness"), static_cast<float>(o.thickness));
  const double step = o.step > 0.0 ? o.step : 0.4 * std::max(o.thickness, 0.005);
  gl.Uniform1f(gl.GetUniformLocation(program, "u_step"), static_cast<float>(step));
  gl.Uniform1i(gl.GetUniformLocation(program, "u_samples"), o.samples);
  set_camera(gl, program, o);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);

  png::Image img;
  img.width = o.width;
  img.height = o.height;
  std::vector<std::uint8_t> bottom_up(static_cast<std::size_t>(o.width) * o.height * 4);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, o.width, o.height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  gl::check_error(gl, "render_shell draw/read");
  // GL's first row is the bottom one; PNG's is the top one.
  img.rgba.resize(bottom_up.size());
  const std::size_t row = static_cast<std::size_t>(o.width) * 4;
  for (int y = 0; y < o.height; ++y) {
    std::copy_n(bottom_up.begin() +
                    static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(o.height - 1 - y)),
                row,
                img.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
  }
  gl.DeleteVertexArrays(1, &vao);
  gl.DeleteFramebuffers(1, &fbo);
  gl.DeleteRenderbuffers(1, &rbo);
  gl.DeleteProgram(program);
  if (timing) *timing = {compile_s, seconds_since(t_render)};
  return img;
}

}  // namespace offsetgen::render
