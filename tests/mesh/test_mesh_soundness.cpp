// The part is judged as written before it is kept (issue 39): the audit's counts on meshes with known
// defects, the same counts whether a mesh arrives whole or in tiles, and planted faults in the sampler
// (OFFSETGEN_TEST_FAULT, docs/testing.md) refused with exit 3, the old output left as it was.
#include "mesh/mesh_audit.h"
#include "mesh/triangle_mesh.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace offsetgen::mesh::testing {
namespace {

namespace fs = std::filesystem;

// The unit cube, 12 triangles facing outward.
TriangleMesh cube() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.points.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

AuditReport audit_whole(const TriangleMesh& m) {
  MeshAudit audit;
  audit.add(m);
  return audit.finish();
}

TEST(MeshAudit, AClosedCubeHasNoFault) {
  const AuditReport r = audit_whole(cube());
  EXPECT_TRUE(r.closed()) << r.describe();
}

TEST(MeshAudit, AMissingFacetLeavesThreeOpenEdges) {
  TriangleMesh m = cube();
  m.triangles.pop_back();
  const AuditReport r = audit_whole(m);
  EXPECT_EQ(r.open_edges, 3u);
  EXPECT_FALSE(r.closed());
}

TEST(MeshAudit, AFacetTwiceMakesThreeNonManifoldEdges) {
  TriangleMesh m = cube();
  m.triangles.push_back({3, 7, 5});
  EXPECT_EQ(audit_whole(m).nonmanifold_edges, 3u);
}

TEST(MeshAudit, AFacetTurnedOverMisorientsItsThreeEdges) {
  TriangleMesh m = cube();
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  EXPECT_EQ(audit_whole(m).misoriented_edges, 3u);
}

// Two corners that differ in the mesh's indices but not in the file: one point, as a reader welds.
TEST(MeshAudit, CornersAtTheSamePositionMakeADegenerateFacet) {
  TriangleMesh m = cube();
  m.points.push_back(m.points[3]);
  m.triangles[1] = {1, 2, 8};  // the same triangle, its third corner a copy of point 3
  EXPECT_TRUE(audit_whole(m).closed());
  m.triangles.push_back({1, 3, 8});
  EXPECT_EQ(audit_whole(m).degenerate_facets, 1u);
}

// The cube's facets in two tiles split at x = 0.5, every point on the seam: the held seam edges pair
// up across the tiles, and a facet missing from the second tile is still found.
TEST(MeshAudit, TilesJudgedApartCountAsTheWholeMesh) {
  const TriangleMesh m = cube();
  TriangleMesh low, high;
  low.points = high.points = m.points;
  for (const auto& t : m.triangles)
    (m.points[t[0]][0] + m.points[t[1]][0] + m.points[t[2]][0] < 1.5f ? low : high).triangles.push_back(t);
  const std::vector<uint8_t> seam(m.points.size(), 1), none(m.points.size(), 0);
  MeshAudit audit;
  audit.add(low, seam, none);
  audit.add(high, seam, none);
  EXPECT_TRUE(audit.finish().closed());

  high.triangles.pop_back();
  MeshAudit broken;
  broken.add(low, seam, none);
  broken.add(high, seam, none);
  EXPECT_EQ(broken.finish().open_edges, 3u);

  // Edges toward a tile another run meshes (--tile-range) are not judged.
  MeshAudit share;
  share.add(low, seam, seam);
  const AuditReport r = share.finish();
  EXPECT_TRUE(r.closed()) << r.describe();
  EXPECT_GT(r.unmatched_seam_edges, 0u);
}

// A run with a planted fault: exit 3 naming what was found, and `old` left as it was.
void expect_refused(const char* fault, const std::string& expected_words, const std::vector<std::string>& args,
                    const std::string& dir) {
  const std::string out = dir + "/part.stl";
  std::ofstream(out, std::ios::binary) << "the old part";
  ::setenv("OFFSETGEN_TEST_FAULT", fault, 1);
  std::vector<std::string> all = args;
  all.insert(all.end(), {"-o", out});
  const CliRun r = run_offsetgen(all);
  ::unsetenv("OFFSETGEN_TEST_FAULT");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("the part is not sound"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(expected_words), std::string::npos) << r.output;
  EXPECT_EQ(read_bytes(out), "the old part");
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".part.stl.tmp"), std::string::npos) << entry.path();
}

const std::vector<std::string> kSpherePart(const std::string& body) {
  return {"mesh",   "--surface", "gyroid",      "--density", "0.3",     "--body", body,
          "--skin", "1.5",       "--cell-size", "6",         "--voxel", "0.1"};
}

// Blocks solid throughout (inside a 15-voxel skin) dropped as the sampler once dropped them: holes
// in the skin's inside, so open edges.
TEST(MeshSoundness, BlocksDroppedFromTheSkinAreRefusedWithExit3AndTheOldFileKept) {
  const std::string dir = scratch_dir("sound-dropped");
  write_stl(sphere(10, {12, 12, 12}, 4), dir + "/sphere.stl");
  expect_refused("drop-solid-blocks", "open edges", kSpherePart(dir + "/sphere.stl"), dir);
}

TEST(MeshSoundness, ASkinReadTooShallowIsRefusedWithExit3AndTheOldFileKept) {
  const std::string dir = scratch_dir("sound-shallow");
  write_stl(sphere(10, {12, 12, 12}, 4), dir + "/sphere.stl");
  expect_refused("shallow-skin", "the thinnest skin measured", kSpherePart(dir + "/sphere.stl"), dir);
}

// The same part without a fault: written, admesh clean, the check's line in the summary.
TEST(MeshSoundness, ASkinManyVoxelsThickIsClosedAndAtLeastTheRequestedThickness) {
  const std::string dir = scratch_dir("sound-thick");
  write_stl(sphere(10, {12, 12, 12}, 4), dir + "/sphere.stl");
  std::vector<std::string> args = kSpherePart(dir + "/sphere.stl");
  args.insert(args.end(), {"-o", dir + "/part.stl"});
  const CliRun r = run_offsetgen(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("checked:    0 open edges, 0 non-manifold edges, 0 misoriented edges, 0 degenerate facets"),
            std::string::npos)
      << r.output;
  EXPECT_GE(summary_number(r.output, "measured: thinnest "), 1.5 - 0.1);
  expect_admesh_clean(dir + "/part.stl", -1);
}

}  // namespace
}  // namespace offsetgen::mesh::testing
