// `offsetgen mesh --cell-size X,Y,Z`: a block of box cells ("distorted cells", the lattice u = x/X,
// v = y/Y, w = z/Z), meshed as the composed field G(x) = F(x/X, y/Y, z/Z) offset in millimetres along
// the physical normal (docs/maps.md), not the cell's wall stretched with the cell.
#include "mesh_test_support.h"

#include "wall/wall_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace offsetgen::mesh::testing {
namespace {

constexpr double kVoxel = 0.2, kThickness = 1;  // mm
const std::array<double, 3> kCell{10, 10, 15};  // one cell, mm

// phi(p, h) of the composed field's walls, p and h in mm.
class ComposedWalls {
 public:
  ComposedWalls() : field_(request()) { field_.compile(); }
  double phi(const std::array<double, 3>& p, double h) const {
    double out = 0;
    field_.offsets(1, &p[0], &p[1], &p[2], &h, &out);
    return out;
  }

 private:
  static wall::WallRequest request() {
    wall::WallRequest r;
    r.generation.surface = "gyroid";
    r.generation.map = "x/10; y/10; z/15";
    r.generation.domain = Surface::Box{{0, 0, 0}, {kCell[0], kCell[1], kCell[2]}};
    r.thickness = "1";
    return r;
  }
  wall::WallField field_;
};

// Whether the line through p along phi's gradient crosses phi = 0 within `reach` of p.
bool crosses_within(const ComposedWalls& walls, const std::array<double, 3>& p, double h, double reach) {
  std::array<double, 3> g{};
  double length = 0;
  for (size_t a = 0; a < 3; ++a) {
    std::array<double, 3> hi = p, lo = p;
    hi[a] += 1e-6;
    lo[a] -= 1e-6;
    g[a] = (walls.phi(hi, h) - walls.phi(lo, h)) / 2e-6;
    length += g[a] * g[a];
  }
  length = std::sqrt(length);
  if (!(length > 0)) return false;
  std::array<double, 3> lo = p, hi = p;
  for (size_t a = 0; a < 3; ++a) {
    lo[a] -= reach * g[a] / length;
    hi[a] += reach * g[a] / length;
  }
  return (walls.phi(lo, h) <= 0) != (walls.phi(hi, h) <= 0);
}

TEST(MeshBoxCells, ABlockOfBoxCellsIsSoundAndItsWallsAreMillimetresThickAlongThePhysicalNormal) {
  const std::string stl = scratch_dir("box_cells") + "/box.stl";
  // The mesher's own soundness judge runs before anything is kept: exit 0 says it passed.
  const CliRun r = run_offsetgen({"mesh", "--surface", "gyroid", "--thickness", "1", "--cells", "1", "--cell-size",
                                  "10,10,15", "--voxel", "0.2", "-o", stl});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_admesh_clean(stl, 0);

  const auto facets = read_stl(stl);
  std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  std::vector<std::array<double, 3>> inner;  // vertices off the block's faces: on a wall
  for (const auto& f : facets)
    for (const auto& v : f) {
      const std::array<double, 3> p{v[0], v[1], v[2]};
      bool on_face = false;
      for (size_t a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
        on_face = on_face || p[a] < kVoxel || p[a] > kCell[a] - kVoxel;
      }
      if (!on_face) inner.push_back(p);
    }
  for (size_t a = 0; a < 3; ++a) {
    EXPECT_NEAR(lo[a], 0, 1e-3) << "axis " << a;
    EXPECT_NEAR(hi[a], kCell[a], 1e-3) << "axis " << a;
  }
  std::sort(inner.begin(), inner.end());
  inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
  ASSERT_GT(inner.size(), 1000u);
  // Every vertex within half a voxel of a wall at +-0.5 mm of the composed field along its normal. The
  // cell's own wall stretched with the cell (0.1 cell: 1 to 1.5 mm thick) would miss by up to 0.25 mm.
  const ComposedWalls walls;
  size_t far = 0;
  for (const auto& p : inner)
    if (!crosses_within(walls, p, 0.5 * kThickness, 0.5 * kVoxel) &&
        !crosses_within(walls, p, -0.5 * kThickness, 0.5 * kVoxel))
      ++far;
  EXPECT_EQ(far, 0u) << "of " << inner.size() << " vertices";
}

}  // namespace
}  // namespace offsetgen::mesh::testing
