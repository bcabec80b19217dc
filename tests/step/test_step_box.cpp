// Box patches (step/box_patch.h) on walls whose answers are known, without OpenCASCADE: the pieces
// and caps a flat wall gives, and on a curved wall that every edge bounds exactly two faces, once in
// each direction (the shell is closed and consistently oriented by construction).
#include "step/box_patch.h"
#include "surfaces/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace offsetgen::step {
namespace {

LevelFunction level(double (*f)(double, double, double, double), double h) {
  return [f, h](size_t n, const double* x, const double* y, const double* z, double* out) {
    for (size_t i = 0; i < n; ++i) out[i] = f(x[i], y[i], z[i], h);
  };
}

double flat(double, double, double z, double h) { return z - 0.5 - h; }
double schwarz(double x, double y, double z, double h) {
  return std::cos(2 * M_PI * x) + std::cos(2 * M_PI * y) + std::cos(2 * M_PI * z) - h;
}

// Each edge of every loop, counted per direction: a closed, consistently oriented shell uses every
// curve once forward and once backward, and every segment once each way.
void expect_every_edge_bounds_two_faces_once_each_way(const BoxPartition& p) {
  std::map<std::pair<int, int>, int> used;  // (curve or -1 - segment key, direction) -> count
  std::map<std::pair<int, int>, int> segments;
  auto count = [&](const LoopEdge& e) {
    if (e.curve >= 0)
      ++used[{e.curve, e.forward ? 1 : 0}];
    else
      ++segments[{e.from, e.to}];
  };
  for (const BoxPatch& patch : p.patches)
    for (const LoopEdge& e : patch.loop) count(e);
  for (const BoxCap& cap : p.caps)
    for (const LoopEdge& e : cap.loop) count(e);
  for (size_t c = 0; c < p.curves.size(); ++c) {
    EXPECT_EQ((used[{int(c), 1}]), 1) << "curve " << c;
    EXPECT_EQ((used[{int(c), 0}]), 1) << "curve " << c;
  }
  for (const auto& [key, n] : segments) {
    EXPECT_EQ(n, 1) << "segment " << key.first << " -> " << key.second;
    EXPECT_EQ(segments.count({key.second, key.first}), 1u) << "segment " << key.first << " -> " << key.second;
  }
}

TEST(StepBoxPatches, AFlatWallIsSixteenExactPatchesPerSheetAndEightCapsPerSideFace) {
  const std::array<LevelFunction, 2> sheets{level(flat, 0.05), level(flat, -0.05)};
  const auto inside = [](const Point& p) { return std::abs(p[2] - 0.5) < 0.05; };
  const BoxPartition p = partition_wall(sheets, inside, {1, 1, 1}, 4, 1e-6, 40);
  EXPECT_EQ(p.patches.size(), 32u);
  EXPECT_EQ(p.caps.size(), 32u);  // 4 side faces x 4 boxes x 2 layers; the top and bottom are outside the wall
  for (const BoxPatch& patch : p.patches) {
    EXPECT_EQ(patch.patch.n, 4);  // a plane needs no more
    EXPECT_LT(patch.error, 1e-12);
    // Out of the wall: +z above it, -z below it.
    EXPECT_NEAR(std::abs(patch.normal[2]), 1.0, 1e-12);
    EXPECT_EQ(patch.normal[2] > 0, patch.sheet == 0);
  }
  expect_every_edge_bounds_two_faces_once_each_way(p);
}

TEST(StepBoxPatches, EveryEdgeOfACurvedWallBoundsTwoFacesOnceEachWay) {
  const std::array<LevelFunction, 2> sheets{level(schwarz, 0.3), level(schwarz, -0.3)};
  const auto inside = [](const Point& p) { return std::abs(schwarz(p[0], p[1], p[2], 0)) < 0.3; };
  const BoxPartition p = partition_wall(sheets, inside, {1, 1, 1}, 4, 1e-5, 40);
  EXPECT_GT(p.patches.size(), 64u);
  EXPECT_GT(p.caps.size(), 0u);
  EXPECT_LE(p.fit_error, 1e-5);
  expect_every_edge_bounds_two_faces_once_each_way(p);
}

TEST(StepBoxPatches, ASheetThroughTheBoxesGridIsRefused) {
  const std::array<LevelFunction, 2> sheets{level(flat, 0.0), level(flat, -0.1)};
  const auto inside = [](const Point& p) { return p[2] < 0.5 && p[2] > 0.4; };
  EXPECT_THROW(partition_wall(sheets, inside, {1, 1, 1}, 4, 1e-6, 40), InputError);
}

}  // namespace
}  // namespace offsetgen::step
