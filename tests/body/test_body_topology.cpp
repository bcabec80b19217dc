// Topology of a body (open, non-manifold and misoriented edges, shells) and its repair.
#include "body/body_mesh.h"
#include "body/body_topology.h"
#include "support/point.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace offsetgen::body {
namespace {

using Triangle = std::array<uint32_t, 3>;

// The cube [o, o + s]^3 (point index = x + 2y + 4z, from `base`) as 12 outward triangles.
void add_cube(BodyMesh& mesh, Point o = {0, 0, 0}, double s = 1) {
  const uint32_t base = static_cast<uint32_t>(mesh.points.size());
  for (uint32_t i = 0; i < 8; ++i)
    mesh.points.push_back({o[0] + s * (i & 1), o[1] + s * ((i >> 1) & 1), o[2] + s * ((i >> 2) & 1)});
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({base + q[0], base + q[1], base + q[2]});
    mesh.triangles.push_back({base + q[0], base + q[2], base + q[3]});
  }
}

BodyMesh cube() {
  BodyMesh mesh;
  add_cube(mesh);
  return mesh;
}

// Triangles given by their corners, welded by exact position (as the readers do).
BodyMesh welded(const std::vector<std::array<Point, 3>>& triangles) {
  BodyMesh mesh;
  std::map<Point, uint32_t> index;
  for (const auto& t : triangles) {
    Triangle out;
    for (size_t k = 0; k < 3; ++k) {
      const auto [it, added] = index.emplace(t[k], static_cast<uint32_t>(mesh.points.size()));
      if (added) mesh.points.push_back(t[k]);
      out[k] = it->second;
    }
    mesh.triangles.push_back(out);
  }
  return mesh;
}

std::vector<std::array<Point, 3>> corners(const BodyMesh& mesh) {
  std::vector<std::array<Point, 3>> out;
  for (const auto& t : mesh.triangles) out.push_back({mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]});
  return out;
}

// A UV sphere: poles and rings - 1 rings of `segments` points, outward.
BodyMesh sphere(int rings, int segments, double r) {
  BodyMesh mesh;
  mesh.points.push_back({0, 0, r});
  mesh.points.push_back({0, 0, -r});
  for (int j = 1; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double theta = M_PI * j / rings, phi = 2 * M_PI * i / segments;
      mesh.points.push_back(
          {r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta)});
    }
  const auto at = [&](int j, int i) { return static_cast<uint32_t>(2 + (j - 1) * segments + (i % segments)); };
  for (int i = 0; i < segments; ++i) {
    mesh.triangles.push_back({0, at(1, i), at(1, i + 1)});
    for (int j = 1; j + 1 < rings; ++j) {
      mesh.triangles.push_back({at(j, i), at(j + 1, i), at(j + 1, i + 1)});
      mesh.triangles.push_back({at(j, i), at(j + 1, i + 1), at(j, i + 1)});
    }
    mesh.triangles.push_back({1, at(rings - 1, i + 1), at(rings - 1, i)});
  }
  return mesh;
}

// A torus as an nu x nv grid of quads, two triangles each, outward.
BodyMesh torus(int nu, int nv) {
  BodyMesh mesh;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      mesh.points.push_back(
          {(10 + 3 * std::cos(v)) * std::cos(u), (10 + 3 * std::cos(v)) * std::sin(u), 3 * std::sin(v)});
    }
  const auto at = [&](int i, int j) { return static_cast<uint32_t>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

void flip(Triangle& t) { std::swap(t[1], t[2]); }

double area(const BodyMesh& mesh, const Triangle& t, double* normal_z = nullptr) {
  const Point& a = mesh.points[t[0]];
  const Point& b = mesh.points[t[1]];
  const Point& c = mesh.points[t[2]];
  const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  if (normal_z) *normal_z = n[2];
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
}

// ---- the mesh ----

TEST(BodyMesh, CubeVolumeAndBoundingBox) {
  BodyMesh mesh;
  add_cube(mesh, {1, 2, 3}, 2);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 8.0);
  const auto box = bounding_box(mesh);
  EXPECT_EQ(box[0], (Point{1, 2, 3}));
  EXPECT_EQ(box[1], (Point{3, 4, 5}));
  for (auto& t : mesh.triangles) flip(t);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), -8.0);
  EXPECT_EQ(bounding_box(BodyMesh{})[1], (Point{0, 0, 0}));
}

// ---- analysis ----

TEST(BodyTopology, ClosedCubeIsClosedWithOneShell) {
  const TopologyReport r = analyse_topology(cube());
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.points, 8u);
  EXPECT_EQ(r.shells, 1u);
  EXPECT_EQ(r.open_edges + r.nonmanifold_edges + r.misoriented_edges + r.degenerate_triangles + r.duplicate_triangles,
            0u);
  EXPECT_FALSE(r.first_open_edge || r.first_nonmanifold_edge || r.first_misoriented_edge);
}

TEST(BodyTopology, CubeWithOneFacetRemovedHasThreeOpenEdgesTheFirstOfTheSmallestPair) {
  BodyMesh mesh = cube();
  mesh.triangles.erase(mesh.triangles.begin());  // (0, 2, 3): edges 0-2, 2-3, 0-3
  const TopologyReport r = analyse_topology(mesh);
  EXPECT_FALSE(r.closed());
  EXPECT_EQ(r.open_edges, 3u);
  ASSERT_TRUE(r.first_open_edge);
  EXPECT_EQ(*r.first_open_edge, (Point{0, 0.5, 0}));  // edge (0, 2)
  EXPECT_EQ(r.describe(),
            "3 open edges (the first at (0, 0.5, 0) mm), 0 non-manifold edges, 0 misoriented edges, 0 degenerate and "
            "0 duplicate triangles; 11 triangles in 1 shell");
}

TEST(BodyTopology, OneFlippedFacetMakesThreeMisorientedEdges) {
  BodyMesh mesh = cube();
  flip(mesh.triangles[0]);
  const TopologyReport r = analyse_topology(mesh);
  EXPECT_EQ(r.misoriented_edges, 3u);
  EXPECT_EQ(r.open_edges, 0u);
  EXPECT_FALSE(r.closed());
  ASSERT_TRUE(r.first_misoriented_edge);
  EXPECT_EQ(*r.first_misoriented_edge, (Point{0, 0.5, 0}));
}

TEST(BodyTopology, ADuplicateFacetIsCountedAndItsEdgesAreNonManifold) {
  BodyMesh mesh = cube();
  mesh.triangles.push_back({3, 0, 2});  // triangle 0 again, rotated
  const TopologyReport r = analyse_topology(mesh);
  EXPECT_EQ(r.duplicate_triangles, 1u);
  EXPECT_EQ(r.nonmanifold_edges, 3u);
  ASSERT_TRUE(r.first_nonmanifold_edge);
  EXPECT_EQ(*r.first_nonmanifold_edge, (Point{0, 0.5, 0}));
}

TEST(BodyTopology, ThreeTrianglesOnOneEdgeMakeItNonManifold) {
  BodyMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const TopologyReport r = analyse_topology(mesh);
  EXPECT_EQ(r.nonmanifold_edges, 1u);
  EXPECT_EQ(*r.first_nonmanifold_edge, (Point{0.5, 0, 0}));
  EXPECT_EQ(r.open_edges, 6u);
  EXPECT_EQ(r.shells, 1u);
}

TEST(BodyTopology, RepeatedIndexAndZeroAreaTrianglesAreDegenerate) {
  BodyMesh mesh = cube();
  mesh.triangles.push_back({0, 0, 1});
  mesh.points.push_back({2, 0, 0});  // on the line of points 0 and 1
  mesh.triangles.push_back({0, 1, static_cast<uint32_t>(mesh.points.size() - 1)});
  const TopologyReport r = analyse_topology(mesh);
  EXPECT_EQ(r.degenerate_triangles, 2u);
  EXPECT_EQ(r.shells, 1u);  // the zero-area one shares the edge 0-1; the other has no edges
}

TEST(BodyTopology, TwoSeparateCubesAreTwoShells) {
  BodyMesh mesh = cube();
  add_cube(mesh, {5, 0, 0}, 1);
  const TopologyReport r = analyse_topology(mesh);
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.shells, 2u);
}

// ---- repair ----

TEST(BodyTopology, RepairOfAClosedCubeChangesNothing) {
  BodyMesh mesh = cube();
  const BodyMesh before = mesh;
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.describe(), "nothing to repair");
  EXPECT_EQ(mesh.points, before.points);
  EXPECT_EQ(mesh.triangles, before.triangles);
}

TEST(BodyTopology, RepairFillsAHoleAndTheResultIsClosed) {
  BodyMesh mesh = cube();
  mesh.triangles.erase(mesh.triangles.begin());
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.holes_filled, 1u);
  EXPECT_EQ(r.hole_triangles, 1u);
  EXPECT_EQ(r.describe(), "filled 1 hole with 1 triangle");
  EXPECT_TRUE(analyse_topology(mesh).closed());
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST(BodyTopology, RepairFillsAMissingFaceOfTwoTriangles) {
  BodyMesh mesh = cube();
  mesh.triangles.erase(mesh.triangles.begin(), mesh.triangles.begin() + 2);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.holes_filled, 1u);
  EXPECT_EQ(r.hole_triangles, 2u);
  EXPECT_TRUE(analyse_topology(mesh).closed());
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST(BodyTopology, RepairFillsTheRoundHoleOfASphereWithoutItsCap) {
  BodyMesh mesh = sphere(24, 48, 10);
  const double full = signed_volume(mesh);
  // The 48 triangles at the north pole: a hole whose rim is a circle of 48 edges.
  mesh.triangles.erase(
      std::remove_if(mesh.triangles.begin(), mesh.triangles.end(), [](const Triangle& t) { return t[0] == 0; }),
      mesh.triangles.end());
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.holes_filled, 1u);
  EXPECT_EQ(r.hole_triangles, 46u);
  const TopologyReport after = analyse_topology(mesh);
  EXPECT_TRUE(after.closed()) << after.describe();
  EXPECT_EQ(after.degenerate_triangles, 0u);
  EXPECT_EQ(mesh.points.size(), 2u + 23 * 48 - 1);  // the pole is no longer used
  EXPECT_LT(signed_volume(mesh), full);
  EXPECT_GT(signed_volume(mesh), 0.99 * full);
}

TEST(BodyTopology, RepairFillsANonConvexHoleWithoutOverlaps) {
  // An L-shaped prism (three unit squares) of height 1 without its top.
  const double l[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  BodyMesh mesh;
  for (double z : {0.0, 1.0})
    for (const auto& p : l) mesh.points.push_back({p[0], p[1], z});
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 5, 4}};  // the bottom, facing down
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    mesh.triangles.push_back({i, j, j + 6});
    mesh.triangles.push_back({i, j + 6, i + 6});
  }
  ASSERT_EQ(analyse_topology(mesh).open_edges, 6u);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.hole_triangles, 4u);
  EXPECT_TRUE(analyse_topology(mesh).closed());
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 3.0);
  // Every triangle of the top faces up and their areas add up to the L's: nothing overlaps.
  double top = 0;
  for (const Triangle& t : mesh.triangles) {
    if (mesh.points[t[0]][2] != 1 || mesh.points[t[1]][2] != 1 || mesh.points[t[2]][2] != 1) continue;
    double normal_z = 0;
    top += area(mesh, t, &normal_z);
    EXPECT_GT(normal_z, 0);
  }
  EXPECT_DOUBLE_EQ(top, 3.0);
}

TEST(BodyTopology, RepairFlipsMisorientedTrianglesToAgreeWithTheirNeighbours) {
  BodyMesh mesh = cube();
  flip(mesh.triangles[0]);
  flip(mesh.triangles[5]);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.flipped, 2u);
  EXPECT_EQ(r.describe(), "flipped 2 to agree with their neighbours");
  EXPECT_TRUE(analyse_topology(mesh).closed());
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST(BodyTopology, RepairTurnsAnInsideOutMeshOutward) {
  BodyMesh mesh = cube();
  for (auto& t : mesh.triangles) flip(t);
  const RepairReport r = repair_body(mesh);
  EXPECT_TRUE(r.oriented_outward_flipped_all);
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_EQ(r.describe(), "turned the whole mesh outward (it faced inward)");
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST(BodyTopology, RepairMakesACavityFaceInward) {
  BodyMesh mesh;
  add_cube(mesh, {0, 0, 0}, 3);
  add_cube(mesh, {1, 1, 1}, 1);  // a void inside, wrongly facing outward
  RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.shells_flipped, 1u);
  EXPECT_FALSE(r.oriented_outward_flipped_all);
  EXPECT_EQ(r.describe(), "turned 1 shell to face away from the material");
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 26.0);
  // Right as it is now: nothing more to do. Both inside out: both turned.
  EXPECT_EQ(repair_body(mesh).describe(), "nothing to repair");
  for (auto& t : mesh.triangles) flip(t);
  r = repair_body(mesh);
  EXPECT_TRUE(r.oriented_outward_flipped_all);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 26.0);
}

TEST(BodyTopology, RepairKeepsASolidInsideACavityFacingOutward) {
  BodyMesh mesh;
  add_cube(mesh, {0, 0, 0}, 5);
  BodyMesh cavity;
  add_cube(cavity, {1, 1, 1}, 3);
  for (auto& t : cavity.triangles) flip(t);
  const uint32_t base = static_cast<uint32_t>(mesh.points.size());
  mesh.points.insert(mesh.points.end(), cavity.points.begin(), cavity.points.end());
  for (auto t : cavity.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  add_cube(mesh, {2, 2, 2}, 1);  // an island in the cavity: outward
  const double expected = 125 - 27 + 1;
  EXPECT_DOUBLE_EQ(signed_volume(mesh), expected);
  EXPECT_EQ(repair_body(mesh).describe(), "nothing to repair");
  for (auto& t : mesh.triangles) flip(t);
  repair_body(mesh);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), expected);
}

TEST(BodyTopology, RepairRemovesDegenerateAndDuplicateTriangles) {
  BodyMesh mesh = cube();
  mesh.triangles.push_back({0, 0, 1});
  mesh.triangles.push_back({7, 7, 7});
  mesh.triangles.push_back(mesh.triangles[3]);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.removed_degenerate, 2u);
  EXPECT_EQ(r.removed_duplicate, 1u);
  EXPECT_EQ(r.describe(), "removed 2 degenerate and 1 duplicate triangles");
  EXPECT_EQ(mesh.triangles, cube().triangles);
}

TEST(BodyTopology, RepairRemovesTheSharedWallOfTwoTouchingCubes) {
  BodyMesh a = cube(), b;
  add_cube(b, {1, 0, 0}, 1);
  auto triangles = corners(a);
  for (const auto& t : corners(b)) triangles.push_back(t);
  BodyMesh mesh = welded(triangles);
  const TopologyReport before = analyse_topology(mesh);
  EXPECT_EQ(before.duplicate_triangles, 2u);
  EXPECT_GT(before.nonmanifold_edges, 0u);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.removed_duplicate, 4u);  // both copies of both triangles of the wall
  const TopologyReport after = analyse_topology(mesh);
  EXPECT_TRUE(after.closed()) << after.describe();
  EXPECT_EQ(after.shells, 1u);
  EXPECT_EQ(mesh.points.size(), 12u);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 2.0);
}

TEST(BodyTopology, RepairSplitsTheTriangleAcrossAZeroAreaSliver) {
  // The cube's top (4, 5, 7) split at m, the middle of the diagonal 4-7, and the sliver (4, m, 7) that
  // an exporter leaves at such a T-junction: closed, but with a zero-area triangle.
  BodyMesh mesh = cube();
  mesh.points.push_back({0.5, 0.5, 1});
  const uint32_t m = 8;
  auto& tris = mesh.triangles;
  const auto top = std::find(tris.begin(), tris.end(), Triangle{4, 5, 7});
  ASSERT_NE(top, tris.end());
  *top = {4, 5, m};
  tris.push_back({m, 5, 7});
  tris.push_back({4, m, 7});
  const TopologyReport before = analyse_topology(mesh);
  EXPECT_TRUE(before.closed()) << before.describe();
  EXPECT_EQ(before.degenerate_triangles, 1u);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.removed_degenerate, 1u);
  EXPECT_EQ(r.holes_filled, 0u);
  const TopologyReport after = analyse_topology(mesh);
  EXPECT_TRUE(after.closed()) << after.describe();
  EXPECT_EQ(after.degenerate_triangles, 0u);
  EXPECT_EQ(after.triangles, 14u);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
}

TEST(BodyTopology, RepairLeavesALooseSheetOpenRatherThanClosingItFlat) {
  BodyMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.holes_filled, 0u);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_FALSE(analyse_topology(mesh).closed());

  // A cube and, apart from it, one stray triangle: the cube is fine, the triangle stays open.
  BodyMesh with_stray = cube();
  with_stray.points.push_back({5, 0, 0});
  with_stray.points.push_back({6, 0, 0});
  with_stray.points.push_back({5, 1, 0});
  with_stray.triangles.push_back({8, 9, 10});
  repair_body(with_stray);
  EXPECT_EQ(analyse_topology(with_stray).open_edges, 3u);
}

TEST(BodyTopology, RepairLeavesAHoleWhoseRimTouchesItselfOpen) {
  BodyMesh mesh = cube();
  // (0, 2, 3) and (1, 3, 7) share only the point 3: the rim passes through it twice.
  mesh.triangles.erase(std::remove_if(mesh.triangles.begin(), mesh.triangles.end(),
                                      [](const Triangle& t) {
                                        return t == Triangle{0, 2, 3} || t == Triangle{1, 3, 7};
                                      }),
                       mesh.triangles.end());
  ASSERT_EQ(mesh.triangles.size(), 10u);
  const RepairReport r = repair_body(mesh);
  EXPECT_EQ(r.holes_filled, 0u);
  EXPECT_EQ(analyse_topology(mesh).open_edges, 6u);
}

TEST(BodyTopology, RepairDescribeListsWhatItDid) {
  RepairReport r;
  EXPECT_EQ(r.describe(), "nothing to repair");
  r.removed_degenerate = 2;
  r.removed_duplicate = 1;
  r.flipped = 5;
  r.holes_filled = 1;
  r.hole_triangles = 4;
  EXPECT_EQ(r.describe(),
            "removed 2 degenerate and 1 duplicate triangles, flipped 5 to agree with their neighbours, filled 1 hole "
            "with 4 triangles");
}

TEST(BodyTopology, RepairOfABrokenSphereIsDeterministicAndCloses) {
  BodyMesh mesh = sphere(30, 60, 5);
  // Holes, flipped triangles, a duplicate and a degenerate one.
  for (size_t i = 100; i < mesh.triangles.size(); i += 97) flip(mesh.triangles[i]);
  mesh.triangles.erase(mesh.triangles.begin() + 500);
  mesh.triangles.erase(mesh.triangles.begin() + 1500, mesh.triangles.begin() + 1502);
  mesh.triangles.push_back(mesh.triangles[42]);
  mesh.triangles.push_back({5, 6, 5});
  BodyMesh again = mesh;
  const RepairReport r = repair_body(mesh);
  const RepairReport r2 = repair_body(again);
  EXPECT_EQ(mesh.triangles, again.triangles);
  EXPECT_EQ(r.describe(), r2.describe());
  const TopologyReport after = analyse_topology(mesh);
  EXPECT_TRUE(after.closed()) << after.describe() << "; " << r.describe();
  EXPECT_EQ(r.holes_filled, 2u);
  EXPECT_GT(signed_volume(mesh), 0);
}

// A torus of a million triangles, with defects: analysed and repaired in well under the time it takes
// to make a level set of it.
TEST(SlowBodyTopology, AMillionTrianglesAreAnalysedAndRepairedInSeconds) {
  BodyMesh mesh = torus(1000, 500);
  ASSERT_EQ(mesh.triangles.size(), 1000000u);
  for (size_t i = 7; i < mesh.triangles.size(); i += 1001) flip(mesh.triangles[i]);
  mesh.triangles.erase(mesh.triangles.begin() + 123456);
  mesh.triangles.erase(mesh.triangles.begin() + 654321);
  const auto seconds_since = [](std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  auto start = std::chrono::steady_clock::now();
  const TopologyReport before = analyse_topology(mesh);
  const double analyse_seconds = seconds_since(start);
  EXPECT_EQ(before.open_edges, 6u);
  start = std::chrono::steady_clock::now();
  const RepairReport r = repair_body(mesh);
  const double repair_seconds = seconds_since(start);
  const TopologyReport after = analyse_topology(mesh);
  EXPECT_TRUE(after.closed()) << after.describe();
  EXPECT_EQ(r.holes_filled, 2u);
  EXPECT_LT(analyse_seconds, 3.0);
  EXPECT_LT(repair_seconds, 10.0);
}

}  // namespace
}  // namespace offsetgen::body
