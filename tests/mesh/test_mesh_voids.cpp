// Enclosed voids (issue 43) in small grids drawn here: the flood fill finds closed cavities and not
// the outside or a cavity open to it, pockets under a volume are filled, and drain holes are capsules.
#include "mesh/drain_plan.h"
#include "mesh/part_edits.h"
#include "mesh/void_regions.h"
#include "surfaces/input_error.h"
#include "wall/drain_holes.h"

#include <gtest/gtest.h>

namespace offsetgen::mesh::testing {
namespace {

// A 24^3 grid, void everywhere but a solid shell [4, 20)^3 around two cavities: [6, 10)^3 (64 voxels)
// and [12, 18)^3 (216); a tunnel from the second to the border opens it when `open`.
VoxelBits two_cavities(bool open) {
  VoxelBits bits(VoxelBox{{{0, 0, 0}, {24, 24, 24}}}, true);
  for (int x = 4; x < 20; ++x)
    for (int y = 4; y < 20; ++y)
      for (int z = 4; z < 20; ++z) {
        const bool first = x >= 6 && x < 10 && y >= 6 && y < 10 && z >= 6 && z < 10;
        const bool second = x >= 12 && x < 18 && y >= 12 && y < 18 && z >= 12 && z < 18;
        const bool tunnel = open && x == 14 && y == 14 && z >= 18;
        bits.set(bits.index(x, y, z), first || second || tunnel);
      }
  return bits;
}

TEST(MeshVoids, FindsTheClosedCavitiesNotTheOutside) {
  VoxelBits bits = two_cavities(false);
  const VoidReport r = find_enclosed_voids(bits, 0.5);
  ASSERT_EQ(r.regions.size(), 2u);
  EXPECT_EQ(r.regions[0].voxels, 64u);
  EXPECT_EQ(r.regions[1].voxels, 216u);
  EXPECT_DOUBLE_EQ(r.total, 280 * 0.125);
  EXPECT_DOUBLE_EQ(r.largest, 216 * 0.125);
  EXPECT_EQ(r.large, 2u);  // 8 and 27 mm^3
  EXPECT_EQ(r.regions[1].extreme[2][0][2], 12);
  EXPECT_EQ(r.regions[1].extreme[2][1][2], 17);
}

TEST(MeshVoids, ACavityOpenToTheOutsideIsNotEnclosed) {
  VoxelBits bits = two_cavities(true);
  const VoidReport r = find_enclosed_voids(bits, 0.5);
  ASSERT_EQ(r.regions.size(), 1u);
  EXPECT_EQ(r.regions[0].voxels, 64u);
}

TEST(MeshVoids, PocketsUnderTheVolumeAreFilled) {
  const VoxelBits bits = two_cavities(false);
  VoxelBits flooded = bits;
  const VoidReport r = find_enclosed_voids(flooded, 0.5);
  double filled = 0;
  const VoxelBits fill = pockets_to_fill(bits, r, 10.0, filled);
  EXPECT_DOUBLE_EQ(filled, 64 * 0.125);
  EXPECT_TRUE(fill.get(fill.index(7, 7, 7)));
  EXPECT_FALSE(fill.get(fill.index(14, 14, 14)));
  EXPECT_FALSE(fill.get(fill.index(1, 1, 1)));
}

TEST(MeshVoids, AHoleIsACapsuleCutIntoThePart) {
  const std::vector<wall::DrainHole> holes = {{{0, 0, 0}, {0, 0, 10}, 2}};
  EXPECT_DOUBLE_EQ(wall::hole_distance(holes, {0, 0, 5}), -2);
  EXPECT_DOUBLE_EQ(wall::hole_distance(holes, {3, 0, 5}), 1);
  EXPECT_DOUBLE_EQ(wall::hole_distance(holes, {0, 0, -3}), 1);  // the rounded end
  EXPECT_DOUBLE_EQ(wall::drained_part_value(-3, wall::hole_distance(holes, {1, 0, 5})), 1);
  EXPECT_DOUBLE_EQ(wall::drained_part_value(-3, wall::hole_distance(holes, {9, 0, 5})), -3);
  EXPECT_TRUE(wall::holes_near_box(holes, {3, 3, 3}, {5, 5, 5}, 2));
  EXPECT_FALSE(wall::holes_near_box(holes, {6, 6, 6}, {8, 8, 8}, 2));
}

TEST(MeshVoids, EditsMakeAPocketSolidAndCutAHole) {
  VoxelBits fill(VoxelBox{{{0, 0, 0}, {8, 8, 8}}}, false);
  fill.set(fill.index(2, 2, 2), true);
  PartEdits edits;
  edits.filled = &fill;
  std::vector<float> values(kBlockVoxels, 1.0f);
  ASSERT_TRUE(apply_part_edits(edits, {0, 0, 0}, 3.0f, values));
  EXPECT_EQ(values[size_t(block_offset(2, 2, 2))], kFilledValue);
  EXPECT_EQ(values[size_t(block_offset(3, 2, 2))], 1.0f);
  edits.filled = nullptr;
  edits.holes = {{{4, 4, -10}, {4, 4, 20}, 2}};
  std::vector<float> solid(kBlockVoxels, -3.0f);
  ASSERT_TRUE(apply_part_edits(edits, {0, 0, 0}, 3.0f, solid));
  EXPECT_FLOAT_EQ(solid[size_t(block_offset(4, 4, 4))], 2.0f);
  EXPECT_FLOAT_EQ(solid[size_t(block_offset(0, 0, 0))], -3.0f);
  EXPECT_FALSE(apply_part_edits(edits, {40, 40, 40}, 3.0f, solid));
}

TEST(MeshVoids, UpAxisNames) {
  EXPECT_EQ(parse_up_axis("Z"), 2);
  EXPECT_EQ(parse_up_axis("x"), 0);
  EXPECT_THROW(parse_up_axis("W"), InputError);
}

}  // namespace
}  // namespace offsetgen::mesh::testing
