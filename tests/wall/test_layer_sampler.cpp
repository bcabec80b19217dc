// wall/layer_sampler.h: a horizontal layer of a gyroid sheet and of a network, against the wall's own
// functions at every pixel: the blocks kept hold every pixel near the surface with its exact value, the
// blocks left out are away from it (or solid throughout, for the network), and threads do not change
// a value.
#include "wall/layer_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace offsetgen::wall {
namespace {

WallRequest gyroid(bool network, const std::string& thickness) {
  WallRequest r;
  r.generation.surface = "gyroid";
  r.thickness = thickness;
  r.network = network;
  return r;
}

LayerGrid one_cell(double z) {
  LayerGrid g;
  g.z = z;
  g.pixel = 1.0 / 100;
  g.size = {100, 100};  // 13 blocks a side, the last one partly beyond the grid
  return g;
}

// Every pixel's exact level, in pixels.
std::vector<double> exact_levels(const WallField& field, const LayerGrid& g) {
  WallField::Worker worker(field);
  std::vector<double> x, y, z, w;
  for (int i = 0; i < g.size[0]; ++i)
    for (int j = 0; j < g.size[1]; ++j) {
      x.push_back(g.origin[0] + (i + 0.5) * g.pixel);
      y.push_back(g.origin[1] + (j + 0.5) * g.pixel);
      z.push_back(g.z);
    }
  w.resize(x.size());
  field.walls(x.size(), x.data(), y.data(), z.data(), w.data(), worker);
  for (double& v : w) v /= g.pixel;
  return w;
}

void expect_layer_matches(const WallField& field, const LayerGrid& g, double reach) {
  const SampledLayer layer = sample_layer(field, g, reach, true, 2, {});
  const std::vector<double> exact = exact_levels(field, g);
  std::map<std::pair<int, int>, const LayerBlock*> kept;
  for (const auto& b : layer.blocks) kept[{b.origin[0], b.origin[1]}] = &b;
  std::map<std::pair<int, int>, bool> solid;
  for (const auto& o : layer.solid) solid[{o[0], o[1]}] = true;
  size_t near = 0;
  for (int i = 0; i < g.size[0]; ++i)
    for (int j = 0; j < g.size[1]; ++j) {
      const double w = exact[static_cast<size_t>(i * g.size[1] + j)];
      const std::pair<int, int> block{i / kLayerBlock * kLayerBlock, j / kLayerBlock * kLayerBlock};
      const auto it = kept.find(block);
      if (it != kept.end()) {
        const float v = it->second->values[static_cast<size_t>((i % kLayerBlock) * kLayerBlock + j % kLayerBlock)];
        EXPECT_FLOAT_EQ(v, static_cast<float>(std::clamp(w, -3.0, 3.0))) << "pixel " << i << ", " << j;
      } else if (solid.count(block)) {
        EXPECT_LT(w, 0) << "pixel " << i << ", " << j << " of a solid block is outside";
      } else {
        EXPECT_GT(w, 0) << "pixel " << i << ", " << j << " of a block left out is inside";
      }
      if (std::abs(w) < 2) {
        ++near;
        EXPECT_TRUE(it != kept.end()) << "pixel " << i << ", " << j << " near the surface (" << w << ") left out";
      }
    }
  EXPECT_GT(near, 100u);
  EXPECT_GT(layer.skipped, 0u) << "F ruled out no block";
  // The same values on one thread.
  const SampledLayer single = sample_layer(field, g, reach, true, 1, {});
  ASSERT_EQ(single.blocks.size(), layer.blocks.size());
  for (size_t b = 0; b < layer.blocks.size(); ++b) EXPECT_EQ(single.blocks[b].values, layer.blocks[b].values);
}

TEST(LayerSampler, AGyroidSheetsLayerHoldsEveryPixelNearItsSurfaceWithItsExactValue) {
  WallField field(gyroid(false, "0.1"));
  field.compile();
  expect_layer_matches(field, one_cell(0.3), field.extent(field.thickness_range({1, 1, 1})).reach);
}

TEST(LayerSampler, ANetworksLayerMarksItsStrutsSolidAndHoldsItsSurface) {
  WallField field(gyroid(true, "-0.05"));
  field.compile();
  const LayerGrid g = one_cell(0.7);
  expect_layer_matches(field, g, field.extent(field.thickness_range({1, 1, 1})).reach);
  EXPECT_FALSE(sample_layer(field, g, 0.05, true, 2, {}).solid.empty()) << "no block inside the struts";
}

}  // namespace
}  // namespace offsetgen::wall
