// Runs WGSL snippets on Dawn (the npm package `webgpu`, pinned in package.json) through Dawn's
// OpenGL ES backend, which runs on Mesa llvmpipe with EGL_PLATFORM=surfaceless: no GPU, no display.
// (Dawn's Vulkan backend refuses Debian 12's lavapipe, Mesa 22.3.)
//
//   node run_wgsl.mjs validate <a.wgsl> [<b.wgsl> ...]
//       Creates one shader module from the files pasted one after the other and prints Dawn's
//       compilation messages as <file>:<line>:<column>: <type>: <message> (<file>#<k> for the k-th
//       of several copies of one file). Exit 0 without errors, 1 with errors.
//   node run_wgsl.mjs run <snippet.wgsl> <prefix> <dims> <points.f32> <results.f32>
//       Calls <prefix>_field(p), _offset(p, h), _shell(p, 2|h|) and _normal(p, h) in a compute
//       shader on every point (x, y, z, h as 4 little-endian float32) and writes 8 float32 per
//       point: field, offset, shell, 0, normal x, y, z, 0.
//
// Exit status 2: bad usage, or Dawn could not start (the message says what to install).
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));

function fail(message) {
  process.stderr.write(`run_wgsl: ${message}\n`);
  process.exit(2);
}

async function device() {
  let webgpu;
  try {
    webgpu = await import(join(here, 'node_modules', 'webgpu', 'index.js'));
  } catch (e) {
    fail(`cannot load Dawn's Node bindings (${e.message}); install them with: npm ci --prefix tests/wgsl ` +
         '(tools/install_deps.sh does it; needs nodejs and npm)');
  }
  Object.assign(globalThis, webgpu.globals);
  process.env.EGL_PLATFORM ??= 'surfaceless';
  const gpu = webgpu.create(['backend=opengles']);
  const adapter = await gpu.requestAdapter({ featureLevel: 'compatibility' });
  if (!adapter)
    fail('Dawn found no OpenGL ES adapter; it needs Mesa llvmpipe through EGL (Debian: libegl1 libgles2 ' +
         'libgl1-mesa-dri) and EGL_PLATFORM=surfaceless');
  const dev = await adapter.requestDevice();
  dev.addEventListener('uncapturederror', (event) => fail(`Dawn error: ${event.error.message}`));
  return { adapter, dev };
}

// Dawn's messages with their line numbers mapped back to the pasted files.
function describeMessages(messages, files, texts) {
  const starts = [];
  let line = 1;
  for (const text of texts) {
    starts.push(line);
    line += text.split('\n').length - 1;
  }
  return messages.map((m) => {
    let k = starts.length - 1;
    while (k > 0 && m.lineNum < starts[k]) --k;
    // A file pasted more than once is named by its copy: a.wgsl#2 is the second.
    const name = files.filter((f) => f === files[k]).length > 1 ? `${files[k]}#${k + 1}` : files[k];
    return `${name}:${m.lineNum - starts[k] + 1}:${m.linePos}: ${m.type}: ${m.message}`;
  });
}

async function compile(dev, code) {
  dev.pushErrorScope('validation');
  const module = dev.createShaderModule({ code });
  const info = await module.getCompilationInfo();
  await dev.popErrorScope();  // the messages are in `info`
  return { module, messages: info.messages };
}

async function validate(files) {
  const { dev } = await device();
  const texts = files.map((f) => readFileSync(f, 'utf8'));
  // Each file ends with a newline, so the files join line by line.
  const { messages } = await compile(dev, texts.join(''));
  for (const line of describeMessages(messages, files, texts)) console.log(line);
  process.exit(messages.some((m) => m.type === 'error') ? 1 : 0);
}

function computeShader(prefix, dims) {
  const p = dims === 3 ? 'q.xyz' : 'q.xy';
  const n = dims === 3 ? 'n' : 'vec3<f32>(n, 0.0)';
  return `
@group(0) @binding(0) var<storage, read> offsetgen_points: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> offsetgen_results: array<vec4<f32>>;

@compute @workgroup_size(64)
fn offsetgen_main(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= arrayLength(&offsetgen_points)) {
    return;
  }
  let q = offsetgen_points[i];
  let n = ${prefix}_normal(${p}, q.w);
  offsetgen_results[2u * i] =
      vec4<f32>(${prefix}_field(${p}), ${prefix}_offset(${p}, q.w), ${prefix}_shell(${p}, 2.0 * abs(q.w)), 0.0);
  offsetgen_results[2u * i + 1u] = vec4<f32>(${n}, 0.0);
}
`;
}

async function run(snippetPath, prefix, dims, pointsPath, resultsPath) {
  const { adapter, dev } = await device();
  const snippet = readFileSync(snippetPath, 'utf8');
  const { module, messages } = await compile(dev, snippet + computeShader(prefix, dims));
  const errors = messages.filter((m) => m.type === 'error');
  if (errors.length) {
    for (const line of describeMessages(errors, [snippetPath, '<compute shader>'], [snippet, '']))
      console.log(line);
    process.exit(1);
  }
  const input = readFileSync(pointsPath);
  const count = input.length / 16;
  if (!Number.isInteger(count) || count === 0) fail(`${pointsPath}: expected a non-empty list of 4 float32 per point`);

  const points = dev.createBuffer({ size: input.length, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST });
  dev.queue.writeBuffer(points, 0, input);
  const size = count * 32;
  const results = dev.createBuffer({ size, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
  const readback = dev.createBuffer({ size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
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
  encoder.copyBufferToBuffer(results, 0, readback, 0, size);
  dev.queue.submit([encoder.finish()]);
  await readback.mapAsync(GPUMapMode.READ);
  writeFileSync(resultsPath, Buffer.from(readback.getMappedRange().slice(0)));
  readback.unmap();
  const info = adapter.info;
  console.log(`run_wgsl: ${count} points on Dawn's OpenGL ES backend: ${info.device}; ${info.description}`);
  process.exit(0);
}

const [mode, ...args] = process.argv.slice(2);
if (mode === 'validate' && args.length >= 1) {
  await validate(args);
} else if (mode === 'run' && args.length === 5) {
  const dims = Number(args[2]);
  if (dims !== 2 && dims !== 3) fail(`dims must be 2 or 3, not ${args[2]}`);
  await run(args[0], args[1], dims, args[3], args[4]);
} else {
  fail('usage: node run_wgsl.mjs validate <a.wgsl> [<b.wgsl> ...] | run <snippet.wgsl> <prefix> <dims> ' +
       '<points.f32> <results.f32>');
}
