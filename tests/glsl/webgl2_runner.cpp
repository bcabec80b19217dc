#include "webgl2_runner.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "offsetgen_test_support.h"

namespace offsetgen::glsl_test {
namespace {

constexpr int kWidth = 256;  // texels per row of the input texture and the result target

const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(const std::vector<std::uint8_t>& bytes) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                        b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t v = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::vector<std::uint8_t> unbase64(const std::string& text) {
  std::vector<std::uint8_t> out;
  std::uint32_t v = 0;
  int bits = 0;
  for (char ch : text) {
    const char* at = std::strchr(kAlphabet, ch);
    if (ch == '=' || ch == '\0' || at == nullptr) break;
    v = (v << 6) | static_cast<std::uint32_t>(at - kAlphabet);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>((v >> bits) & 0xff));
    }
  }
  return out;
}

// The host a user writes around the snippet: GLSL ES 3.00, the job's default float precision.
std::string fragment_source(const WebGl2Job& job) {
  static const char* swizzles[] = {"x", "xy", "xyz", "xyzw"};
  if (job.components < 1 || job.components > 4) throw std::runtime_error("components must be 1..4");
  return "#version 300 es\nprecision " + job.host_precision + " float;\n" + job.snippet +
         "\nuniform highp sampler2D og_in;\n"
         "layout(location = 0) out highp uvec4 og_out;\n"
         "void main() {\n"
         "  highp vec4 p = texelFetch(og_in, ivec2(gl_FragCoord.xy), 0);\n"
         "  highp vec4 r = vec4(0.0);\n"
         "  r." +
         swizzles[job.components - 1] + " = (" + job.call_expr +
         ");\n"
         "  og_out = floatBitsToUint(r);\n"
         "}\n";
}

// The markers are split in the script so that only the page's output matches them in the dump.
const char kPage[] = R"(<!doctype html><html><body><pre id="out">pending</pre><script>
const out = document.getElementById('out');
function fromB64(s) { const b = atob(s), u = new Uint8Array(b.length); for (let i = 0; i < b.length; ++i) u[i] = b.charCodeAt(i); return u; }
function toB64(u) { let s = ''; for (let i = 0; i < u.length; i += 32768) s += String.fromCharCode.apply(null, u.subarray(i, i + 32768)); return btoa(s); }
try {
  const W = @@WIDTH@@, H = @@HEIGHT@@;
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) throw new Error('no WebGL2 context');
  const points = new Float32Array(W * H * 4);
  points.set(new Float32Array(fromB64(@@INPUT@@).buffer));
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, W, H, 0, gl.RGBA, gl.FLOAT, points);
  const rb = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, rb);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA32UI, W, H);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, rb);
  gl.viewport(0, 0, W, H);
  function shader(type, source) {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error('compile: ' + gl.getShaderInfoLog(s));
    return s;
  }
  const vs = shader(gl.VERTEX_SHADER, '#version 300 es\nvoid main() { gl_Position = vec4(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0, 0.0, 1.0); }\n');
  let text = '';
  for (const source of @@SOURCES@@) {
    const program = gl.createProgram();
    gl.attachShader(program, vs);
    gl.attachShader(program, shader(gl.FRAGMENT_SHADER, source));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error('link: ' + gl.getProgramInfoLog(program));
    gl.useProgram(program);
    gl.uniform1i(gl.getUniformLocation(program, 'og_in'), 0);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    const result = new Uint32Array(W * H * 4);
    gl.readPixels(0, 0, W, H, gl.RGBA_INTEGER, gl.UNSIGNED_INT, result);
    text += 'OG' + 'JOB ' + toB64(new Uint8Array(result.buffer)) + '\n';
  }
  out.textContent = text + 'OG' + 'DONE';
} catch (e) {
  out.textContent = 'OG' + 'ERROR ' + e.message;
}
</script></body></html>
)";

void replace(std::string& text, const std::string& what, const std::string& with) {
  const auto at = text.find(what);
  if (at == std::string::npos) throw std::logic_error("page template lacks " + what);
  text.replace(at, what.size(), with);
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string chromium_executable() { return OFFSETGEN_CHROMIUM; }

std::vector<std::vector<float>> run_webgl2(const std::vector<WebGl2Job>& jobs, const std::vector<glsl::Sample>& inputs,
                                           const std::string& work_dir) {
  if (chromium_executable().empty())
    throw std::runtime_error("chromium not found at configure time (Debian: chromium; run tools/install_deps.sh)");
  const int height = static_cast<int>((inputs.size() + kWidth - 1) / kWidth);
  std::vector<std::uint8_t> bytes(inputs.size() * sizeof(glsl::Sample));
  if (!inputs.empty()) std::memcpy(bytes.data(), inputs.data(), bytes.size());
  nlohmann::json sources = nlohmann::json::array();
  for (const auto& job : jobs) sources.push_back(fragment_source(job));

  std::string page = kPage;
  // Each placeholder's first occurrence is the template's, and base64 holds no '@'.
  replace(page, "@@WIDTH@@", std::to_string(kWidth));
  replace(page, "@@HEIGHT@@", std::to_string(height));
  replace(page, "@@INPUT@@", "'" + base64(bytes) + "'");
  std::string listed = sources.dump();
  for (auto at = listed.find("</"); at != std::string::npos; at = listed.find("</", at))
    listed.replace(at, 2, "<\\/");  // a </script> in a comment must not end the page's script
  replace(page, "@@SOURCES@@", listed);
  const std::string path = work_dir + "/page.html";
  test_support::write_file(path, page);

  const auto result = test_support::run_shell(
      shell_quote(chromium_executable()) +
      " --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --no-first-run"
      " --user-data-dir=" +
      shell_quote(work_dir + "/profile") + " --dump-dom " + shell_quote("file://" + path) + " 2>" +
      shell_quote(work_dir + "/chromium.log"));
  const std::string& dump = result.output;
  if (auto at = dump.find("OGERROR "); at != std::string::npos)
    throw std::runtime_error("WebGL2 page: " + dump.substr(at, dump.find("</pre>", at) - at));
  std::vector<std::vector<float>> results;
  for (std::size_t at = dump.find("OGJOB "); at != std::string::npos; at = dump.find("OGJOB ", at + 1)) {
    const std::size_t begin = at + 6;
    const std::vector<std::uint8_t> raw = unbase64(dump.substr(begin, dump.find('\n', begin) - begin));
    const WebGl2Job& job = jobs.at(results.size());
    if (raw.size() < inputs.size() * 16) throw std::runtime_error("WebGL2 page: short result");
    std::vector<float> values(inputs.size() * static_cast<std::size_t>(job.components));
    for (std::size_t i = 0; i < inputs.size(); ++i)
      std::memcpy(&values[i * static_cast<std::size_t>(job.components)], &raw[16 * i],
                  sizeof(float) * static_cast<std::size_t>(job.components));
    results.push_back(std::move(values));
  }
  if (results.size() != jobs.size() || dump.find("OGDONE") == std::string::npos)
    throw std::runtime_error("Chromium gave no result (exit status " + std::to_string(result.exit_code) + "; see " +
                             work_dir + "/chromium.log): " + dump.substr(0, 2000));
  return results;
}

}  // namespace offsetgen::glsl_test
