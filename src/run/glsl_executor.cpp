#include "run/glsl_executor.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <stdexcept>

#include "run/glsl_source.h"
#include "run/headless_gl.h"
#include "support/stopwatch.h"

namespace offsetgen::glsl {
namespace {

constexpr GLuint kLocalSize = 64;          // compute work-group size
constexpr GLuint kMaxGroups = 65535;       // GL's guaranteed minimum per dispatch dimension
constexpr GLsizei kTexWidth = 1024;        // fragment path: points per texture row
constexpr GLsizei kMaxRowsPerDraw = 1024;  // fragment path: at most 1M points per draw

const char* swizzle(int components) {
  static const char* k[] = {"x", "xy", "xyz", "xyzw"};
  if (components < 1 || components > 4) throw std::runtime_error("components must be 1..4");
  return k[components - 1];
}

// Result assignment shared by both hosts; the parentheses keep the expression one unit.
std::string store_result(const std::string& call_expr, int components) {
  return "  highp vec4 r = vec4(0.0);\n  r." + std::string(swizzle(components)) + " = (" + call_expr + ");\n";
}

HostedSource compute_source(const std::string& snippet, const std::string& call_expr, int components) {
  const std::string prologue = gl::version_line(gl::Api::Desktop43) + "layout(local_size_x = 64) in;\n";
  const std::string epilogue =
      "\nlayout(std430, binding = 0) readonly buffer OgIn { vec4 og_in[]; };\n"
      "layout(std430, binding = 1) writeonly buffer OgOut { vec4 og_out[]; };\n"
      "uniform uint og_count;\n"
      "uniform uint og_base;\n"
      "void main() {\n"
      "  uint i = og_base + gl_GlobalInvocationID.x;\n"
      "  if (i >= og_count) return;\n"
      "  highp vec4 p = og_in[i];\n" +
      store_result(call_expr, components) +
      "  og_out[i] = r;\n"
      "}\n";
  return assemble(prologue, snippet, epilogue);
}

// mediump on purpose: a snippet that forgot a highp would be computed in fp16 by some drivers.
HostedSource fragment_source(const std::string& snippet, const std::string& call_expr, int components) {
  const std::string prologue = gl::version_line(gl::Api::Es30) + "precision mediump float;\n";
  const std::string epilogue =
      "\nuniform highp sampler2D og_in;\n"
      "layout(location = 0) out highp uvec4 og_out;\n"
      "void main() {\n"
      "  highp vec4 p = texelFetch(og_in, ivec2(gl_FragCoord.xy), 0);\n" +
      store_result(call_expr, components) +
      "  og_out = floatBitsToUint(r);\n"
      "}\n";
  return assemble(prologue, snippet, epilogue);
}

HostedSource fullscreen_vertex_source() {
  return assemble(gl::version_line(gl::Api::Es30) +
                      "void main() {\n"
                      "  vec2 v = vec2(float((gl_VertexID & 1) << 2) - 1.0, "
                      "float((gl_VertexID & 2) << 1) - 1.0);\n"
                      "  gl_Position = vec4(v, 0.0, 1.0);\n"
                      "}\n",
                  "", "");
}

// Compiling costs more than running 1e5 points on llvmpipe; tests evaluate the same expression
// on several point sets, so programs live until the process ends.
GLuint cached_program(const gl::Functions& gl, gl::Api api, const std::vector<gl::Stage>& stages, double& compile_s) {
  static std::map<std::pair<int, std::string>, GLuint> cache;
  const auto key = std::make_pair(static_cast<int>(api), stages.back().source.text);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  const auto t0 = Clock::now();
  const GLuint program = gl::build_program(gl, stages);
  compile_s = seconds_since(t0);
  cache.emplace(key, program);
  return program;
}

std::vector<float> run_compute_path(const std::string& snippet, const std::string& call_expr,
                                    const std::vector<Sample>& inputs, int components, RunStats& st) {
  const gl::Functions& gl = gl::make_current(gl::Api::Desktop43);
  const GLuint program = cached_program(
      gl, gl::Api::Desktop43, {{GL_COMPUTE_SHADER, compute_source(snippet, call_expr, components)}}, st.compile_s);
  const auto t0 = Clock::now();
  const auto n = static_cast<GLuint>(inputs.size());
  const auto bytes = static_cast<GLsizeiptr>(inputs.size() * sizeof(Sample));
  GLuint buffers[2] = {0, 0};
  gl.GenBuffers(2, buffers);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[0]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, bytes, inputs.data(), GL_STATIC_DRAW);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[1]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, GL_STREAM_READ);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
  gl.UseProgram(program);
  gl.Uniform1ui(gl.GetUniformLocation(program, "og_count"), n);
  const GLint base_loc = gl.GetUniformLocation(program, "og_base");
  for (GLuint base = 0; base < n; base += kMaxGroups * kLocalSize) {
    gl.Uniform1ui(base_loc, base);
    const GLuint groups = std::min(kMaxGroups, (n - base + kLocalSize - 1) / kLocalSize);
    gl.DispatchCompute(groups, 1, 1);
  }
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> out(inputs.size() * static_cast<std::size_t>(components));
  const auto* mapped =
      static_cast<const float*>(gl.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, bytes, GL_MAP_READ_BIT));
  if (mapped == nullptr) throw std::runtime_error("glMapBufferRange of the result buffer failed");
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    std::memcpy(&out[i * static_cast<std::size_t>(components)], mapped + 4 * i,
                sizeof(float) * static_cast<std::size_t>(components));
  }
  gl.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  gl.DeleteBuffers(2, buffers);
  gl::check_error(gl, "compute path");
  st.run_s = seconds_since(t0);
  return out;
}

// One draw of up to kTexWidth x kMaxRowsPerDraw points starting at `first`.
void fragment_chunk(const gl::Functions& gl, GLuint program, const std::vector<Sample>& inputs, std::size_t first,
                    int components, std::vector<float>& out) {
  const std::size_t count = std::min(inputs.size() - first, static_cast<std::size_t>(kTexWidth) * kMaxRowsPerDraw);
  const auto rows = static_cast<GLsizei>((count + kTexWidth - 1) / kTexWidth);
  const std::size_t texels = static_cast<std::size_t>(kTexWidth) * static_cast<std::size_t>(rows);
  std::vector<Sample> padded(texels, Sample{0.0f, 0.0f, 0.0f, 0.0f});
  std::copy_n(inputs.begin() + static_cast<std::ptrdiff_t>(first), count, padded.begin());

  GLuint tex = 0, rbo = 0, fbo = 0, vao = 0;
  gl.GenTextures(1, &tex);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, tex);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // float textures are
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // not filterable in ES
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTexWidth, rows, 0, GL_RGBA, GL_FLOAT, padded.data());
  gl.GenRenderbuffers(1, &rbo);
  gl.BindRenderbuffer(GL_RENDERBUFFER, rbo);
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32UI, kTexWidth, rows);
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbo);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("RGBA32UI framebuffer incomplete");
  }
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.Viewport(0, 0, kTexWidth, rows);
  gl.UseProgram(program);
  gl.Uniform1i(gl.GetUniformLocation(program, "og_in"), 0);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);

  std::vector<std::uint32_t> bits(texels * 4);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl.ReadPixels(0, 0, kTexWidth, rows, GL_RGBA_INTEGER, GL_UNSIGNED_INT, bits.data());
  for (std::size_t i = 0; i < count; ++i) {
    std::memcpy(&out[(first + i) * static_cast<std::size_t>(components)], &bits[4 * i],
                sizeof(float) * static_cast<std::size_t>(components));
  }
  gl.DeleteVertexArrays(1, &vao);
  gl.DeleteFramebuffers(1, &fbo);
  gl.DeleteRenderbuffers(1, &rbo);
  gl.DeleteTextures(1, &tex);
  gl::check_error(gl, "fragment path");
}

std::vector<float> run_fragment_path(const std::string& snippet, const std::string& call_expr,
                                     const std::vector<Sample>& inputs, int components, RunStats& st) {
  const gl::Functions& gl = gl::make_current(gl::Api::Es30);
  const GLuint program = cached_program(gl, gl::Api::Es30,
                                        {{GL_VERTEX_SHADER, fullscreen_vertex_source()},
                                         {GL_FRAGMENT_SHADER, fragment_source(snippet, call_expr, components)}},
                                        st.compile_s);
  const auto t0 = Clock::now();
  std::vector<float> out(inputs.size() * static_cast<std::size_t>(components));
  for (std::size_t first = 0; first < inputs.size(); first += static_cast<std::size_t>(kTexWidth) * kMaxRowsPerDraw) {
    fragment_chunk(gl, program, inputs, first, components, out);
  }
  st.run_s = seconds_since(t0);
  return out;
}

}  // namespace

const char* path_name(Path p) { return p == Path::Compute ? "GL 4.3 compute" : "GLSL ES 3.00 fragment (mediump host)"; }

std::vector<Path> all_paths() { return {Path::Compute, Path::Fragment}; }

std::vector<float> run(Path path, const std::string& snippet, const std::string& call_expr,
                       const std::vector<Sample>& inputs, int components, RunStats* stats) {
  swizzle(components);  // validates before any GL work
  RunStats st;
  st.points = inputs.size();
  std::vector<float> out;
  if (!inputs.empty()) {
    out = path == Path::Compute ? run_compute_path(snippet, call_expr, inputs, components, st)
                                : run_fragment_path(snippet, call_expr, inputs, components, st);
  }
  if (stats) *stats = st;
  return out;
}

}  // namespace offsetgen::glsl
