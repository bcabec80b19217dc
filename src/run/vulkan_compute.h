// Runs a SPIR-V compute shader on Mesa's lavapipe (Vulkan on the CPU, Debian mesa-vulkan-drivers)
// over a buffer of float4 inputs and returns its float4 outputs: the HLSL tests' runner. The
// shader's entry point is "main", 64 invocations per work group, binding 0 of set 0 the input
// buffer (one float4 per point), binding 1 the output buffer (`outputs_per_point` float4 per point).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace offsetgen::vulkan {

using Float4 = std::array<float, 4>;

struct ComputeRun {
  std::vector<float> outputs;  // inputs.size() * outputs_per_point * 4 floats, point-major
  std::string device;          // the physical device's name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
};

// Throws std::runtime_error naming the failing Vulkan call, or naming mesa-vulkan-drivers when no
// CPU (lavapipe) device exists. `spirv` is the module's words.
ComputeRun run_on_lavapipe(const std::vector<std::uint32_t>& spirv, const std::vector<Float4>& inputs,
                           int outputs_per_point);

// The words of a .spv file; throws std::runtime_error when it cannot be read.
std::vector<std::uint32_t> read_spirv(const std::string& path);

}  // namespace offsetgen::vulkan
