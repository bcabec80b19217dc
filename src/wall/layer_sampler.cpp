#include "wall/layer_sampler.h"

#include "wall/field_bound.h"
#include "wall/parallel_blocks.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace offsetgen::wall {
namespace {

constexpr double kNear = 2.0;  // pixels: blocks with a value closer to the surface are kept

struct BlockResult {
  LayerBlock block;
  size_t samples = 0, skipped = 0;
  bool near = false, solid = false;
};

class LayerBlockSampler {
 public:
  LayerBlockSampler(const WallField& field, const LayerGrid& grid, double reach, bool use_field_bound, float background)
      : field_(field),
        worker_(field),
        grid_(grid),
        background_(background),
        bound_(field, use_field_bound ? field.field_lipschitz() : 0, reach, kNear * grid.pixel) {}

  void sample(const std::array<int, 2>& origin, BlockResult& out) {
    out = BlockResult{};
    out.block.origin = origin;
    const double p = grid_.pixel;
    const double centre[3] = {grid_.origin[0] + (origin[0] + 0.5 * kLayerBlock) * p,
                              grid_.origin[1] + (origin[1] + 0.5 * kLayerBlock) * p, grid_.z};
    const double radius = 0.5 * std::sqrt(2.0) * (kLayerBlock - 1) * p;
    const FieldBound::Far far = bound_.far_from_walls(centre, radius);
    if (far != FieldBound::Far::No) {
      out.skipped = kLayerBlockPixels;
      out.solid = far == FieldBound::Far::Inside;
      return;
    }
    x_.clear();
    y_.clear();
    z_.clear();
    for (int i = 0; i < kLayerBlock; ++i)
      for (int j = 0; j < kLayerBlock; ++j) {
        x_.push_back(grid_.origin[0] + (origin[0] + i + 0.5) * p);
        y_.push_back(grid_.origin[1] + (origin[1] + j + 0.5) * p);
        z_.push_back(grid_.z);
      }
    w_.resize(x_.size());
    field_.walls(x_.size(), x_.data(), y_.data(), z_.data(), w_.data(), worker_);
    out.samples = x_.size();
    out.block.values.assign(kLayerBlockPixels, background_);
    bool all_inside = true;
    for (int i = 0; i < kLayerBlock; ++i)
      for (int j = 0; j < kLayerBlock; ++j) {
        const auto k = static_cast<size_t>(i * kLayerBlock + j);
        if (origin[0] + i >= grid_.size[0] || origin[1] + j >= grid_.size[1]) continue;  // beyond the grid
        const double value = w_[k] / p;
        out.block.values[k] = static_cast<float>(std::clamp(value, -double(background_), double(background_)));
        out.near = out.near || std::abs(value) < kNear;
        all_inside = all_inside && value <= -kNear;
      }
    out.solid = !out.near && all_inside;
  }

 private:
  const WallField& field_;
  WallField::Worker worker_;
  const LayerGrid& grid_;
  float background_;
  FieldBound bound_;
  std::vector<double> x_, y_, z_, w_;
};

}  // namespace

SampledLayer sample_layer(const WallField& field, const LayerGrid& grid, double reach, bool use_field_bound,
                          int threads, const std::function<void(double)>& progress, const BlockFilter& wanted) {
  SampledLayer layer;
  std::vector<std::array<int, 2>> origins;
  for (int i = 0; i < grid.size[0]; i += kLayerBlock)
    for (int j = 0; j < grid.size[1]; j += kLayerBlock) {
      if (!wanted || wanted({i, j}))
        origins.push_back({i, j});
      else
        layer.skipped += kLayerBlockPixels;
    }
  std::vector<BlockResult> results(origins.size());
  for_each_block(
      origins.size(), threads, progress,
      [&] { return std::make_unique<LayerBlockSampler>(field, grid, reach, use_field_bound, layer.background); },
      [&](std::unique_ptr<LayerBlockSampler>& sampler, size_t b) { sampler->sample(origins[b], results[b]); });
  for (auto& r : results) {
    layer.samples += r.samples;
    layer.skipped += r.skipped;
    if (r.near) layer.blocks.push_back(std::move(r.block));
    if (r.solid) layer.solid.push_back(r.block.origin);
  }
  return layer;
}

}  // namespace offsetgen::wall
