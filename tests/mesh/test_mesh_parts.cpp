// The plain parts of `offsetgen mesh`: pieces, orientation, file encodings, --cells.
#include "cli/cells_option.h"
#include "cli/mesh_command.h"
#include "mesh/mesh_files.h"
#include "mesh/triangle_mesh.h"
#include "surfaces/surface.h"
#include "validate/block_checks.h"

#include <gtest/gtest.h>

#include <cstring>

namespace offsetgen::mesh {
namespace {

// An axis-aligned cube [o, o + s]^3 as 12 outward triangles, appended to `mesh`.
void add_cube(TriangleMesh& mesh, float o, float s) {
  const uint32_t base = static_cast<uint32_t>(mesh.points.size());
  for (int i = 0; i < 8; ++i)
    mesh.points.push_back({o + s * float(i & 1), o + s * float((i >> 1) & 1), o + s * float((i >> 2) & 1)});
  const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    mesh.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    mesh.triangles.push_back({base + f[0], base + f[2], base + f[3]});
  }
}

TEST(MeshPieces, CubeVolumeIsExactAndPositiveOutward) {
  TriangleMesh m;
  add_cube(m, 0, 2);
  EXPECT_DOUBLE_EQ(signed_volume(m), 8.0);
}

TEST(MeshPieces, InwardMeshIsTurnedOutward) {
  TriangleMesh m;
  add_cube(m, 0, 1);
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  ASSERT_LT(signed_volume(m), 0);
  PieceReport r = keep_large_pieces(m, 0.01);
  EXPECT_DOUBLE_EQ(r.volume, 1.0);
  EXPECT_EQ(r.kept, 1);
}

TEST(MeshPieces, SmallPiecesAreDroppedAndCounted) {
  TriangleMesh m;
  add_cube(m, 0, 1);      // volume 1
  add_cube(m, 5, 0.1f);   // 0.001: below 1%
  add_cube(m, 10, 0.5f);  // 0.125: kept
  PieceReport r = keep_large_pieces(m, 0.01);
  EXPECT_EQ(r.kept, 2);
  EXPECT_EQ(r.dropped, 1);
  EXPECT_NEAR(r.dropped_volume, 0.001, 1e-6);
  EXPECT_EQ(m.triangles.size(), 24u);
  EXPECT_EQ(m.points.size(), 16u);  // unused points are removed
  EXPECT_NEAR(r.volume, 1.125, 1e-6);
}

TEST(MeshPieces, CavitiesAreKeptWhateverTheirSize) {
  TriangleMesh m;
  add_cube(m, 0, 3);
  TriangleMesh inner;
  add_cube(inner, 1, 0.1f);  // a small void inside: faces point into it
  const uint32_t base = static_cast<uint32_t>(m.points.size());
  for (const auto& p : inner.points) m.points.push_back(p);
  for (const auto& t : inner.triangles) m.triangles.push_back({base + t[0], base + t[2], base + t[1]});
  PieceReport r = keep_large_pieces(m, 0.01);
  EXPECT_EQ(r.kept, 1);
  EXPECT_EQ(r.cavities, 1);
  EXPECT_EQ(r.dropped, 0);
  EXPECT_NEAR(r.volume, 27 - 0.001, 1e-5);
}

TEST(MeshFiles, BinaryStlHas50BytesPerFacetAndNoSolidHeader) {
  TriangleMesh m;
  add_cube(m, 0, 1);
  const std::string stl = encode_mesh(m, MeshFormat::Stl, "test cube");
  ASSERT_EQ(stl.size(), 84u + 50u * 12u);
  EXPECT_NE(stl.rfind("solid", 0), 0u);
  uint32_t count = 0;
  std::memcpy(&count, stl.data() + 80, 4);
  EXPECT_EQ(count, 12u);
  float normal[3];  // first facet: the z = 0 face, normal -z
  std::memcpy(normal, stl.data() + 84, 12);
  EXPECT_FLOAT_EQ(normal[2], -1.0f);
  EXPECT_EQ(stl, encode_mesh(m, MeshFormat::Stl, "test cube"));  // deterministic
}

TEST(MeshFiles, BinaryPlyHeaderCountsVerticesAndFaces) {
  TriangleMesh m;
  add_cube(m, 0, 1);
  const std::string ply = encode_mesh(m, MeshFormat::Ply, "test cube");
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_NE(ply.find("element vertex 8\n"), std::string::npos);
  EXPECT_NE(ply.find("element face 12\n"), std::string::npos);
  const size_t body = ply.find("end_header\n") + 11;
  EXPECT_EQ(ply.size() - body, 8u * 12u + 12u * 13u);
}

TEST(MeshFiles, FormatFollowsTheExtensionAndUnknownOnesAreRefused) {
  EXPECT_EQ(format_for_path("a/part.STL"), MeshFormat::Stl);
  EXPECT_EQ(format_for_path("part.ply"), MeshFormat::Ply);
  EXPECT_THROW(format_for_path("part.obj"), InputError);
  EXPECT_THROW(format_for_path("part"), InputError);
}

TEST(MeshCells, OneTwoOrThreeCountsAreAccepted) {
  EXPECT_EQ(parse_cells("3"), (std::array<int, 3>{3, 3, 3}));
  EXPECT_EQ(parse_cells("4x2"), (std::array<int, 3>{4, 2, 2}));
  EXPECT_EQ(parse_cells("2x3x4"), (std::array<int, 3>{2, 3, 4}));
  for (const char* bad : {"0", "-1", "2x", "x2", "2x3x4x5", "a", "2.5", ""})
    EXPECT_THROW(parse_cells(bad), InputError) << bad;
}

// One size is a cube cell, three a box cell; anything else, or a side that is not a positive length,
// is refused.
TEST(MeshCells, OneOrThreeCellSizesAreAcceptedAndEqualSidesAreACube) {
  EXPECT_EQ(parse_cell_size("10"), (std::array<double, 3>{10, 10, 10}));
  EXPECT_EQ(parse_cell_size("10,10,15"), (std::array<double, 3>{10, 10, 15}));
  EXPECT_EQ(parse_cell_size("0.5,2,1e1"), (std::array<double, 3>{0.5, 2, 10}));
  EXPECT_TRUE(cube_cell(parse_cell_size("10,10,10")));
  EXPECT_FALSE(cube_cell(parse_cell_size("10,10,15")));
  for (const char* bad : {"0", "-5", "10,0,15", "10,-1,15", "10,15", "10,10,15,15", "10,,15", "10,10,15,", ",10", "ten",
                          "10,x,15", "inf", "nan", "1e999", ""})
    EXPECT_THROW(parse_cell_size(bad), InputError) << bad;
}

}  // namespace
}  // namespace offsetgen::mesh
