// WGSL snippets: Dawn, through its Node bindings (the npm package `webgpu`), validates the snippet and
// runs one compute shader per function with its OpenGL ES backend on Mesa llvmpipe, in float32.
#include "run/process.h"
#include "run/runner.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace offsetgen::run {
namespace {

namespace fs = std::filesystem;

// node --input-type=module -e kDawn <webgpu index.js> <mode> ...:
//   validate <a.wgsl>: prints Dawn's messages as line:column: type: message; exit 1 on errors.
//   run <shader.wgsl> <points.f32> <results.f32>: runs offsetgen_main over the points (4 float32
//   each), writes one vec4<f32> per point.
// Exit 2: Dawn could not start; the message says what to install.
constexpr const char* kDawn = R"(import { readFileSync, writeFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';

function fail(message) { process.stderr.write(`${message}\n`); process.exit(2); }

async function device(entry) {
  let webgpu;
  try { webgpu = await import(pathToFileURL(entry).href); } catch (e) { fail(`cannot load ${entry}: ${e.message}`); }
  Object.assign(globalThis, webgpu.globals);
  process.env.EGL_PLATFORM ??= 'surfaceless';
  const adapter = await webgpu.create(['backend=opengles']).requestAdapter({ featureLevel: 'compatibility' });
  if (!adapter) fail('Dawn found no OpenGL ES adapter (Debian: libegl1 libgles2 libgl1-mesa-dri)');
  const dev = await adapter.requestDevice();
  dev.addEventListener('uncapturederror', (event) => fail(`Dawn error: ${event.error.message}`));
  return { adapter, dev };
}

async function compile(dev, code) {
  dev.pushErrorScope('validation');
  const module = dev.createShaderModule({ code });
  const info = await module.getCompilationInfo();
  await dev.popErrorScope();
  const errors = info.messages.filter((m) => m.type === 'error');
  for (const m of info.messages) console.log(`${m.lineNum}:${m.linePos}: ${m.type}: ${m.message}`);
  return { module, errors };
}

const [entry, mode, ...args] = process.argv.slice(1);
const { adapter, dev } = await device(entry);
const { module, errors } = await compile(dev, readFileSync(args[0], 'utf8'));
if (errors.length) process.exit(1);
if (mode === 'validate') {
  const info = adapter.info;
  console.log(`Dawn's OpenGL ES backend: ${info.device}; ${info.description}`);
  process.exit(0);
}
const input = readFileSync(args[1]);
const count = input.length / 16;
const points = dev.createBuffer({ size: input.length, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST });
dev.queue.writeBuffer(points, 0, input);
const results = dev.createBuffer({ size: input.length, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
const readback = dev.createBuffer({ size: input.length, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
const pipeline = dev.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: 'offsetgen_main' } });
const bindGroup = dev.createBindGroup({
  layout: pipeline.getBindGroupLayout(0),
  entries: [{ binding: 0, resource: { buffer: points } }, { binding: 1, resource: { buffer: results } }],
});
const encoder = dev.createCommandEncoder();
const pass = encoder.beginComputePass();
pass.setPipeline(pipeline);
pass.setBindGroup(0, bindGroup);
pass.dispatchWorkgroups(Math.ceil(count / 64));
pass.end();
encoder.copyBufferToBuffer(results, 0, readback, 0, input.length);
dev.queue.submit([encoder.finish()]);
await readback.mapAsync(GPUMapMode.READ);
writeFileSync(args[2], Buffer.from(readback.getMappedRange().slice(0)));
readback.unmap();
process.exit(0);
)";

// Where Dawn's Node bindings are: $OFFSETGEN_WEBGPU; node_modules/webgpu in the working directory or
// one above it (as node resolves `webgpu` from there); npm's global folders; tests/wgsl of the source
// tree that holds the directory of this executable, where tools/install_deps.sh installs them. Returns the package's
// index.js, or throws ToolMissing saying where it looked.
std::string find_webgpu() {
  const auto entry = [](const fs::path& dir) { return dir / "index.js"; };
  if (const char* env = std::getenv("OFFSETGEN_WEBGPU"); env != nullptr && *env != '\0') {
    if (fs::is_regular_file(entry(env))) return entry(env).string();
    throw ToolMissing(fmt::format(
        "$OFFSETGEN_WEBGPU is {}, which holds no webgpu package (no index.js): set it to a node_modules/webgpu "
        "directory (npm install webgpu@0.6.2), or unset it to let check look for one",
        env));
  }
  std::vector<fs::path> looked;
  std::error_code ec;
  for (fs::path dir = fs::current_path(ec); !ec && !dir.empty(); dir = dir.parent_path()) {
    looked.push_back(dir / "node_modules" / "webgpu");
    if (dir == dir.root_path()) break;
  }
  for (const char* global : {"/usr/local/lib/node_modules/webgpu", "/usr/lib/node_modules/webgpu"})
    looked.emplace_back(global);
  // The source tree around the build directory this offsetgen runs from (build/ or any folder in the
  // tree): no path of the tree is compiled in, so an installed offsetgen names none.
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  for (fs::path dir = ec ? fs::path() : self.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (fs::is_regular_file(dir / "tests" / "wgsl" / "package.json", ec))
      looked.push_back(dir / "tests" / "wgsl" / "node_modules" / "webgpu");
    if (dir == dir.root_path()) break;
  }
  std::string where;
  for (const fs::path& dir : looked) {
    if (fs::is_regular_file(entry(dir))) return entry(dir).string();
    where += (where.empty() ? "" : ", ") + dir.string();
  }
  throw ToolMissing(fmt::format(
      "Dawn's Node bindings (the npm package webgpu) are not installed; looked in {}. Install them with `npm "
      "install -g webgpu@0.6.2` (or tools/install_deps.sh), or set $OFFSETGEN_WEBGPU to a node_modules/webgpu "
      "directory",
      where));
}

ProcessResult run_dawn(const std::string& node, const std::string& webgpu, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {node, "--input-type=module", "-e", kDawn, webgpu};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_process(argv);
}

// One point in, one vec4<f32> out: the function's value, or its normal, padded with zeros.
std::string compute_shader(const std::string& snippet, const FileMetadata& meta, const std::string& function) {
  const std::string call = shader_call(meta, function, "p.xyz", "p.w", "p.xy", "p.z");
  const std::string value =
      function != "normal" ? call + ", 0.0, 0.0, 0.0" : call + (meta.dims == 3 ? ", 0.0" : ", 0.0, 0.0");
  return fmt::format(
      "{}\n@group(0) @binding(0) var<storage, read> offsetgen_points: array<vec4<f32>>;\n"
      "@group(0) @binding(1) var<storage, read_write> offsetgen_results: array<vec4<f32>>;\n\n"
      "@compute @workgroup_size(64)\n"
      "fn offsetgen_main(@builtin(global_invocation_id) id: vec3<u32>) {{\n"
      "  if (id.x >= arrayLength(&offsetgen_points)) {{\n    return;\n  }}\n"
      "  let p = offsetgen_points[id.x];\n"
      "  offsetgen_results[id.x] = vec4<f32>({});\n}}\n",
      snippet, value);
}

// The function's shader over the points, through float32 files.
std::vector<double> run_function(const std::string& node, const std::string& webgpu, const std::string& snippet,
                                 const FileMetadata& meta, const std::string& function,
                                 const std::vector<Sample>& points, int components) {
  ScratchDir dir("offsetgen-wgsl");
  const fs::path shader = dir.path() / "shader.wgsl", in = dir.path() / "in.f32", out = dir.path() / "out.f32";
  std::ofstream(shader) << compute_shader(snippet, meta, function);
  const std::vector<std::array<float, 4>> inputs = narrowed(points);
  std::ofstream(in, std::ios::binary)
      .write(reinterpret_cast<const char*>(inputs.data()), static_cast<std::streamsize>(inputs.size() * 16));
  const ProcessResult r = run_dawn(node, webgpu, {"run", shader.string(), in.string(), out.string()});
  if (!r.started || r.exit_code != 0)
    throw std::runtime_error(fmt::format("Dawn failed on {}:\n{}", function, r.output));
  std::vector<float> results(4 * points.size());
  std::ifstream read(out, std::ios::binary);
  read.read(reinterpret_cast<char*>(results.data()), static_cast<std::streamsize>(results.size() * sizeof(float)));
  if (read.gcount() != static_cast<std::streamsize>(results.size() * sizeof(float)))
    throw std::runtime_error(fmt::format("Dawn returned {} bytes for {}", read.gcount(), function));
  std::vector<double> values;
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < components; ++k) values.push_back(results[4 * i + static_cast<size_t>(k)]);
  return values;
}

std::string find_node() {
  if (const char* env = std::getenv("OFFSETGEN_NODE"); env != nullptr && *env != '\0') return find_on_path(env);
  return find_on_path("node");
}

class WgslRunner final : public Runner {
 public:
  std::string backend() const override { return "wgsl"; }
  std::string how() const override { return "Dawn (the npm webgpu module, through Node) runs it"; }
  ValueWords words() const override {
    return {"values on Dawn", "the shader on Dawn (OpenGL ES backend on Mesa llvmpipe, float32)",
            "cannot run the shader"};
  }

  Prepared prepare(const std::string& path, const std::string& text, const FileMetadata& meta,
                   const ProgressFn& progress) const override {
    Prepared p;
    p.listing = Listing::Compile;
    p.json_key = "compile";
    const std::string node = find_node();
    if (node.empty())
      throw ToolMissing(
          "no node on PATH ($OFFSETGEN_NODE): a WGSL snippet runs on Dawn through its Node bindings (Debian: "
          "nodejs npm, then npm install -g webgpu@0.6.2)");
    const std::string webgpu = find_webgpu();
    progress("compile", "Dawn: the snippet as a shader module");
    CompileStep step =
        run_step("Dawn shader module", {node, "--input-type=module", "-e", kDawn, webgpu, "validate", path});
    step.command = {node, "<offsetgen's Dawn runner>", webgpu, "validate", path};
    p.toolchain = step.ok ? step.output.substr(step.output.rfind('\n', step.output.size() - 2) + 1) : node;
    while (!p.toolchain.empty() && p.toolchain.back() == '\n') p.toolchain.pop_back();
    p.steps.push_back(step);
    p.outcomes.push_back(compile_outcome(p.steps));
    p.ready = step.ok;
    if (!p.ready) return p;
    Lane lane;
    lane.label = "wgsl";
    lane.graded = meta.thickness.has_value();
    lane.evaluate = [node, webgpu, text, meta](const std::string& function, const std::vector<Sample>& points,
                                               int components) {
      return run_function(node, webgpu, text, meta, function, points, components);
    };
    p.lanes.push_back(lane);
    return p;
  }
};

}  // namespace

const Runner& wgsl_runner() {
  static const WgslRunner instance;
  return instance;
}

}  // namespace offsetgen::run
