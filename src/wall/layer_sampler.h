// One horizontal layer of the wall (z fixed), sampled on a square grid of pixels in blocks of 8 x 8 on a
// few threads: the wall's level w (max(phi(p, t/2), -phi(p, -t/2)), or a network's phi(p, h), in
// pixels, negative inside) near its surface, and which blocks are solid or empty throughout. F rules
// out the blocks far from the surface (field_bound.h), so a layer costs its contours, not its area.
// This is what a slicer marches and refines into contours (`offsetgen slice`); mesh samples 3D blocks
// the same way (mesh/narrow_band.h).
#pragma once

#include "wall/wall_field.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace offsetgen::wall {

inline constexpr int kLayerBlock = 8;
inline constexpr int kLayerBlockPixels = kLayerBlock * kLayerBlock;

// Pixel (i, j) is centred at origin + ((i + 1/2) pixel, (j + 1/2) pixel), at height z; cell units.
struct LayerGrid {
  double z = 0;
  std::array<double, 2> origin{0, 0};
  double pixel = 1.0 / 64;
  std::array<int, 2> size{64, 64};  // pixels on each axis
};

// A block near the surface: its 8 x 8 values x-major ((i * 8) + j), in pixels, clamped to +-background;
// pixels beyond the grid hold +background.
struct LayerBlock {
  std::array<int, 2> origin{};  // its first pixel
  std::vector<float> values;    // kLayerBlockPixels
};

struct SampledLayer {
  std::vector<LayerBlock> blocks;         // near the surface, in block order
  std::vector<std::array<int, 2>> solid;  // blocks inside the solid throughout (a network's strut)
  float background = 3.0f;                // pixels: values beyond it are clamped
  size_t samples = 0, skipped = 0;        // pixels evaluated, and ruled out by F
};

// `reach`: how far from F = 0 the solid's surface gets (WallExtent::reach); use_field_bound as for
// mesh (periodic surfaces, or a single cell). `wanted`, when given, says which blocks (by their first
// pixel) need the wall at all (a body's core); the others are skipped, neither near nor solid.
using BlockFilter = std::function<bool(const std::array<int, 2>& origin)>;
SampledLayer sample_layer(const WallField& field, const LayerGrid& grid, double reach, bool use_field_bound,
                          int threads, const std::function<void(double)>& progress, const BlockFilter& wanted = {});

}  // namespace offsetgen::wall
