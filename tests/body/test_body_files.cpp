// Reading a body: every format, its error messages, welding, and real files.
#include "body/body_files.h"
#include "body/body_topology.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#ifdef OFFSETGEN_HAVE_LIB3MF
#include <Model/COM/NMR_DLLInterfaces.h>
#endif

namespace offsetgen::body {
namespace {

namespace fs = std::filesystem;

// The unit cube's corners (index = x + 2y + 4z) and its faces as counter-clockwise quads from outside.
const double kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

// The cube's 12 triangles as corner triples.
std::vector<std::array<int, 3>> cube_triangles() {
  std::vector<std::array<int, 3>> out;
  for (const auto& q : kQuads) {
    out.push_back({q[0], q[1], q[2]});
    out.push_back({q[0], q[2], q[3]});
  }
  return out;
}

std::string ascii_stl_cube(const std::string& solid = "solid cube", const std::string& end = "endsolid cube") {
  std::string s = solid + "\n";
  for (const auto& t : cube_triangles()) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (int v : t) s += fmt::format("      vertex {} {} {}\n", kCorners[v][0], kCorners[v][1], kCorners[v][2]);
    s += "    endloop\n  endfacet\n";
  }
  return s + end + "\n";
}

template <typename T>
void put(std::string& out, T value, bool big_endian = false) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string binary_stl_cube(std::string header = "binary cube") {
  header.resize(80, ' ');
  std::string s = header;
  const auto tris = cube_triangles();
  put<uint32_t>(s, static_cast<uint32_t>(tris.size()));
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) put<float>(s, 0.0f);
    for (int v : t)
      for (int k = 0; k < 3; ++k) put<float>(s, static_cast<float>(kCorners[v][k]));
    put<uint16_t>(s, 0);
  }
  return s;
}

// An ASCII PLY of the cube as quads, with properties and an element that are to be skipped.
std::string ascii_ply_cube() {
  std::string s =
      "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 8\nproperty float x\nproperty float nx\n"
      "property float y\nproperty float z\nproperty uchar red\nelement face 6\nproperty uchar flags\n"
      "property list uchar int vertex_indices\nproperty list uchar float texcoord\nelement edge 1\n"
      "property int vertex1\nproperty int vertex2\nend_header\n";
  for (const auto& c : kCorners) s += fmt::format("{} 0.5 {} {} 255\n", c[0], c[1], c[2]);
  for (const auto& q : kQuads) s += fmt::format("7 4 {} {} {} {} 2 0.5 0.5\n", q[0], q[1], q[2], q[3]);
  return s + "0 1\n";
}

std::string binary_ply_cube(bool big_endian) {
  std::string s = fmt::format(
      "ply\nformat {} 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
      "property short extra\nelement face 12\nproperty list int uint vertex_index\nend_header\n",
      big_endian ? "binary_big_endian" : "binary_little_endian");
  for (const auto& c : kCorners) {
    for (double x : c) put<double>(s, x, big_endian);
    put<int16_t>(s, -3, big_endian);
  }
  for (const auto& t : cube_triangles()) {
    put<int32_t>(s, 3, big_endian);
    for (int v : t) put<uint32_t>(s, static_cast<uint32_t>(v), big_endian);
  }
  return s;
}

// An OBJ of the cube using every face form, negative indices, quads and lines to be ignored.
std::string obj_cube() {
  std::string s = "# cube\nmtllib cube.mtl\no cube\n";
  for (const auto& c : kCorners) s += fmt::format("v {} {} {}\n", c[0], c[1], c[2]);
  s += "vt 0 0\nvn 0 0 1\ng sides\nusemtl red\ns off\n";
  s += "f 1 3 4 2\n";                     // v
  s += "f 5/1 6/1 8/1 7/1\n";             // v/vt
  s += "f 1//1 2//1 6//1 5//1\n";         // v//vn
  s += "f 3/1/1 7/1/1 8/1/1 4/1/1\n";     // v/vt/vn
  s += "f -8 -4 -2 -6\n";                 // negative: 1 5 7 3
  s += "f 2 4 8 # a comment\nf 2 8 6\n";  // triangles
  return s;
}

void expect_unit_cube(const BodyMesh& mesh) {
  EXPECT_EQ(mesh.points.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(signed_volume(mesh), 1.0);
  const auto box = bounding_box(mesh);
  EXPECT_EQ(box[0], (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(box[1], (std::array<double, 3>{1, 1, 1}));
  const TopologyReport report = analyse_topology(mesh);
  EXPECT_TRUE(report.closed()) << report.describe();
  EXPECT_EQ(report.shells, 1u);
}

// The message of the InputError that parse_body throws ("" when it does not).
std::string error_of(const std::string& bytes, BodyFormat format, const std::string& name = "part") {
  try {
    parse_body(bytes, format, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(OFFSETGEN_BODY_TEST_TMP);
  fs::create_directories(dir);
  return dir / name;
}

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// ---- formats and names ----

TEST(BodyFiles, FormatFollowsTheExtensionInAnyCase) {
  EXPECT_EQ(body_format_for_path("a/part.stl"), BodyFormat::Stl);
  EXPECT_EQ(body_format_for_path("PART.STL"), BodyFormat::Stl);
  EXPECT_EQ(body_format_for_path("part.Ply"), BodyFormat::Ply);
  EXPECT_EQ(body_format_for_path("part.OBJ"), BodyFormat::Obj);
  EXPECT_EQ(body_format_for_path("part.3MF"), BodyFormat::ThreeMf);
}

TEST(BodyFiles, UnknownExtensionIsAnInputErrorNamingItAndTheAcceptedOnes) {
  try {
    body_format_for_path("part.step");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'.step'"), std::string::npos) << message;
    for (const char* ext : {".stl", ".ply", ".obj", ".3mf"}) EXPECT_NE(message.find(ext), std::string::npos) << message;
  }
  EXPECT_THROW(body_format_for_path("part"), InputError);
}

// ---- STL ----

TEST(BodyFiles, AsciiStlCubeIsReadWithSharedCornersWelded) {
  expect_unit_cube(parse_body(ascii_stl_cube(), BodyFormat::Stl, "c"));
}

TEST(BodyFiles, AsciiStlKeywordsInUpperCaseAndSeveralSolidsAreOneBody) {
  std::string upper = ascii_stl_cube("SOLID CUBE", "ENDSOLID");
  for (const char* word : {"facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet"}) {
    std::string lower = word, capital = word;
    std::transform(capital.begin(), capital.end(), capital.begin(),
                   [](char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); });
    for (size_t at = upper.find(" " + lower); at != std::string::npos; at = upper.find(" " + lower, at + 1))
      upper.replace(at + 1, lower.size(), capital);
  }
  const BodyMesh one = parse_body(upper, BodyFormat::Stl, "c");
  expect_unit_cube(one);
  // Two solids, the second the same cube moved by 2 in x: two shells in one body.
  std::string moved = ascii_stl_cube("solid second", "endsolid second");
  for (size_t at = moved.find("vertex 0 "); at != std::string::npos; at = moved.find("vertex 0 ", at))
    moved.replace(at, 9, "vertex 2 ");
  for (size_t at = moved.find("vertex 1 "); at != std::string::npos; at = moved.find("vertex 1 ", at))
    moved.replace(at, 9, "vertex 3 ");
  const BodyMesh two = parse_body(ascii_stl_cube() + moved, BodyFormat::Stl, "c");
  EXPECT_EQ(two.triangles.size(), 24u);
  EXPECT_EQ(two.points.size(), 16u);
  EXPECT_EQ(analyse_topology(two).shells, 2u);
  EXPECT_DOUBLE_EQ(signed_volume(two), 2.0);
}

TEST(BodyFiles, BinaryStlCubeIsReadWithSharedCornersWelded) {
  expect_unit_cube(parse_body(binary_stl_cube(), BodyFormat::Stl, "c"));
}

TEST(BodyFiles, BinaryStlWhoseHeaderStartsWithSolidIsReadAsBinary) {
  const std::string bytes = binary_stl_cube("solid cube exported by a CAD program that writes binary");
  ASSERT_EQ(bytes.compare(0, 5, "solid"), 0);
  expect_unit_cube(parse_body(bytes, BodyFormat::Stl, "c"));
}

TEST(BodyFiles, BinaryStlWithSolidHeaderAndWrongSizeIsReportedAsBinary) {
  std::string bytes = binary_stl_cube("solid but binary");
  bytes.resize(bytes.size() - 7);
  const std::string message = error_of(bytes, BodyFormat::Stl, "c.stl");
  EXPECT_NE(message.find("c.stl: byte 677: truncated binary STL: its count of 12 facets needs 684 bytes"),
            std::string::npos)
      << message;
}

TEST(BodyFiles, TruncatedBinaryStlIsAnInputErrorNamingTheSizes) {
  std::string bytes = binary_stl_cube();
  bytes.resize(bytes.size() - 50);
  const std::string message = error_of(bytes, BodyFormat::Stl, "c.stl");
  EXPECT_EQ(message, "c.stl: byte 634: truncated binary STL: its count of 12 facets needs 684 bytes, the file has 634");
  EXPECT_EQ(error_of("short", BodyFormat::Stl, "c.stl"),
            "c.stl: byte 5: truncated binary STL: 5 bytes, less than its 80-byte header and facet count");
}

TEST(BodyFiles, BinaryStlWithExtraBytesIsAnInputError) {
  const std::string message = error_of(binary_stl_cube() + "xyz", BodyFormat::Stl, "c.stl");
  EXPECT_EQ(message,
            "c.stl: byte 684: 3 bytes after the last of the 12 facets of this binary STL (damaged, or not an STL)");
}

TEST(BodyFiles, BinaryStlWithAnAbsurdCountIsAnInputErrorNotAnAllocation) {
  std::string bytes(80, 'x');
  put<uint32_t>(bytes, 0xFFFFFFFFu);
  bytes += std::string(50, '\0');
  const std::string message = error_of(bytes, BodyFormat::Stl, "c.stl");
  EXPECT_NE(message.find("its count of 4294967295 facets needs 214748364834 bytes, the file has 134"),
            std::string::npos)
      << message;
}

TEST(BodyFiles, BinaryStlWithZeroFacetsHasNoTriangles) {
  std::string bytes(80, 'x');
  put<uint32_t>(bytes, 0);
  EXPECT_EQ(error_of(bytes, BodyFormat::Stl, "c.stl"), "c.stl: no triangles");
  EXPECT_EQ(error_of("solid empty\nendsolid empty\n", BodyFormat::Stl, "c.stl"), "c.stl: no triangles");
}

TEST(BodyFiles, AsciiStlErrorsNameTheLine) {
  EXPECT_EQ(
      error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 zero 0\n", BodyFormat::Stl, "part.stl"),
      "part.stl: line 5: expected 'vertex x y z', found 'zero'");
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n",
                     BodyFormat::Stl, "part.stl"),
            "part.stl: line 6: a facet with 2 vertices (it needs 3)");
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                     "endfacet\n",
                     BodyFormat::Stl, "part.stl"),
            "part.stl: line 9: unexpected end of file: expected 'endsolid'");
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loops\n", BodyFormat::Stl, "part.stl"),
            "part.stl: line 3: expected 'outer loop'");
  EXPECT_EQ(error_of("solid x\n  face\n", BodyFormat::Stl, "part.stl"),
            "part.stl: line 2: expected 'facet' or 'endsolid', found 'face'");
}

TEST(BodyFiles, NonFiniteCoordinatesAreInputErrors) {
  std::string ascii = ascii_stl_cube();
  ascii.replace(ascii.find("vertex 1 1 1"), 12, "vertex 1 nan 1");
  EXPECT_NE(error_of(ascii, BodyFormat::Stl).find("coordinate 'nan' is not finite"), std::string::npos);

  std::string binary = binary_stl_cube();
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(binary.data() + 84 + 50 + 12 + 4, &inf, 4);  // facet 1, vertex 0, y
  EXPECT_EQ(error_of(binary, BodyFormat::Stl, "c.stl"), "c.stl: byte 150: facet 1: a coordinate is not finite (inf)");

  std::string ply = ascii_ply_cube();
  ply.replace(ply.find("\n1 0.5 1 1 255\n"), 15, "\n1 0.5 1 inf 255\n");
  EXPECT_NE(error_of(ply, BodyFormat::Ply).find("vertex 7: coordinate z is not finite"), std::string::npos);

  std::string obj = obj_cube();
  obj.replace(obj.find("v 1 1 1"), 7, "v 1 1 -inf");
  EXPECT_NE(error_of(obj, BodyFormat::Obj).find("line 11: coordinate '-inf' is not finite"), std::string::npos)
      << error_of(obj, BodyFormat::Obj);
}

TEST(BodyFiles, NegativeZeroAndZeroAreOnePoint) {
  const std::string stl =
      "solid z\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 1\nouter loop\nvertex -0 -0.0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid\n";
  const BodyMesh mesh = parse_body(stl, BodyFormat::Stl, "z");
  EXPECT_EQ(mesh.points.size(), 4u);
  EXPECT_EQ(mesh.triangles[0][0], mesh.triangles[1][0]);
}

TEST(BodyFiles, PointsCloseButNotEqualAreNotWelded) {
  const std::string stl =
      "solid z\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 1\nouter loop\nvertex 1e-9 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid\n";
  EXPECT_EQ(parse_body(stl, BodyFormat::Stl, "z").points.size(), 5u);
}

// ---- PLY ----

TEST(BodyFiles, AsciiPlyQuadsAreSplitAndOtherPropertiesAndElementsSkipped) {
  expect_unit_cube(parse_body(ascii_ply_cube(), BodyFormat::Ply, "c"));
}

TEST(BodyFiles, BinaryLittleEndianPlyIsRead) {
  expect_unit_cube(parse_body(binary_ply_cube(false), BodyFormat::Ply, "c"));
}

TEST(BodyFiles, BinaryBigEndianPlyIsRead) { expect_unit_cube(parse_body(binary_ply_cube(true), BodyFormat::Ply, "c")); }

TEST(BodyFiles, PlyHeaderWithCrLfLineEndsIsRead) {
  std::string ply = binary_ply_cube(false);
  const size_t end = ply.find("end_header\n") + 11;
  std::string header = ply.substr(0, end), crlf;
  for (char c : header) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_unit_cube(parse_body(crlf + ply.substr(end), BodyFormat::Ply, "c"));
}

TEST(BodyFiles, PlyVerticesNoFaceUsesAreDropped) {
  std::string ply = ascii_ply_cube();
  ply.replace(ply.find("element vertex 8"), 16, "element vertex 9");
  ply.insert(ply.find("7 4 0 2 3 1"), "5 0.5 5 5 0\n");
  const BodyMesh mesh = parse_body(ply, BodyFormat::Ply, "c");
  EXPECT_EQ(mesh.points.size(), 8u);
}

TEST(BodyFiles, PlyErrorsNameTheLineByteOrFace) {
  std::string ply = ascii_ply_cube();
  ply.replace(ply.find("7 4 1 3 7 5"), 11, "7 4 1 3 7 8");
  EXPECT_EQ(error_of(ply, BodyFormat::Ply, "c.ply"),
            "c.ply: line 31: face 5: vertex index 8 out of range (the file has 8 vertices)");

  std::string binary = binary_ply_cube(false);
  binary.resize(binary.size() - 3);
  const std::string message = error_of(binary, BodyFormat::Ply, "c.ply");
  EXPECT_NE(message.find("c.ply: byte "), std::string::npos) << message;
  EXPECT_NE(message.find("unexpected end of file in the PLY data"), std::string::npos) << message;

  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
                     BodyFormat::Ply, "c.ply"),
            "c.ply: line 3: the vertex element has no property 'z'");
  EXPECT_EQ(error_of("plyx\n", BodyFormat::Ply, "c.ply"), "c.ply: line 1: not a PLY file (it must start with 'ply')");
  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 1\n", BodyFormat::Ply, "c.ply"),
            "c.ply: line 3: the header has no 'end_header'");
  EXPECT_EQ(
      error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", BodyFormat::Ply, "c.ply"),
      "c.ply: line 4: unknown property type 'quad'");

  std::string small = ascii_ply_cube();
  small.replace(small.find("7 4 0 2 3 1"), 11, "7 2 0 2");
  EXPECT_EQ(error_of(small, BodyFormat::Ply, "c.ply"), "c.ply: line 26: face 0: 2 vertices (a face needs 3)");
}

TEST(BodyFiles, PlyWithAnAbsurdElementCountIsAnInputErrorNotAnAllocation) {
  std::string ply = binary_ply_cube(false);
  ply.replace(ply.find("element vertex 8"), 16, "element vertex 4000000000");
  EXPECT_EQ(error_of(ply, BodyFormat::Ply, "c.ply"),
            "c.ply: line 3: 4000000000 vertex elements, more than the rest of the file can hold");
  ply.replace(ply.find("element vertex 4000000000"), 25, "element vertex 4000000000000");
  EXPECT_EQ(error_of(ply, BodyFormat::Ply, "c.ply"),
            "c.ply: line 3: 4000000000000 vertices, more than 32-bit indices reach");
  std::string ascii = ascii_ply_cube();
  ascii.replace(ascii.find("element face 6"), 14, "element face 999999999999");
  EXPECT_NE(error_of(ascii, BodyFormat::Ply, "c.ply").find("999999999999 face elements"), std::string::npos);
}

TEST(BodyFiles, PlyWithoutAFaceElementHasNoTriangles) {
  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float "
                     "z\nend_header\n0 0 0\n",
                     BodyFormat::Ply, "c.ply"),
            "c.ply: header: no triangles (no 'face' element)");
  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float "
                     "z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
                     BodyFormat::Ply, "c.ply"),
            "c.ply: no triangles");
}

// ---- OBJ ----

TEST(BodyFiles, ObjFaceFormsNegativeIndicesAndPolygonsAreRead) {
  expect_unit_cube(parse_body(obj_cube(), BodyFormat::Obj, "c"));
}

TEST(BodyFiles, ObjFacesMayNameVerticesDefinedLater) {
  expect_unit_cube(parse_body("f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n" +
                                  obj_cube().substr(0, obj_cube().find("vt")),
                              BodyFormat::Obj, "c"));
}

TEST(BodyFiles, ObjErrorsNameTheLine) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(vertices + "f 1 2 4\n", BodyFormat::Obj, "c.obj"),
            "c.obj: line 4: face vertex 4 out of range (the file has 3 vertices)");
  EXPECT_EQ(error_of(vertices + "f 1 2 -4\n", BodyFormat::Obj, "c.obj"),
            "c.obj: line 4: face vertex -4 out of range (3 vertices before this line)");
  EXPECT_EQ(error_of(vertices + "f 1 2 -9223372036854775808\n", BodyFormat::Obj, "c.obj"),
            "c.obj: line 4: face vertex -9223372036854775808 out of range (3 vertices before this line)");
  EXPECT_EQ(error_of(vertices + "f 0 1 2\n", BodyFormat::Obj, "c.obj"),
            "c.obj: line 4: expected a face vertex 'v', 'v/vt', 'v//vn' or 'v/vt/vn', found '0'");
  EXPECT_EQ(error_of(vertices + "f 1 2\n", BodyFormat::Obj, "c.obj"),
            "c.obj: line 4: a face with 2 vertices (it needs 3)");
  EXPECT_EQ(error_of("v 0 0\n", BodyFormat::Obj, "c.obj"), "c.obj: line 1: expected 'v x y z', found ''");
  EXPECT_EQ(error_of(vertices, BodyFormat::Obj, "c.obj"), "c.obj: no triangles");
}

// ---- 3MF ----

#ifdef OFFSETGEN_HAVE_LIB3MF

struct Lib3mf {
  NMR::PLib3MFBase* p = nullptr;
  ~Lib3mf() {
    if (p) NMR::lib3mf_release(p);
  }
};

NMR::MODELTRANSFORM affine(const std::array<std::array<float, 4>, 3>& m) {
  NMR::MODELTRANSFORM t;
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 4; ++j) t.m_fFields[i][j] = m[i][j];
  return t;
}

// A 3MF in centimetres: the unit cube as a mesh object placed at x + 10 by its build item, and a
// components object holding it mirrored in x (a transform of determinant -1) placed at x - 10.
std::string three_mf_cubes() {
  std::vector<NMR::MODELMESHVERTEX> vertices(8);
  for (size_t i = 0; i < 8; ++i)
    for (size_t k = 0; k < 3; ++k) vertices[i].m_fPosition[k] = static_cast<float>(kCorners[i][k]);
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  for (const auto& t : cube_triangles())
    triangles.push_back({{static_cast<DWORD>(t[0]), static_cast<DWORD>(t[1]), static_cast<DWORD>(t[2])}});
  Lib3mf model, mesh, components, component, item1, item2, writer;
  EXPECT_EQ(NMR::lib3mf_createmodel(reinterpret_cast<NMR::PLib3MFModel**>(&model.p)), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_setunit(model.p, NMR::MODELUNIT_CENTIMETER), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_addmeshobject(model.p, reinterpret_cast<NMR::PLib3MFModelMeshObject**>(&mesh.p)),
            LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_meshobject_setgeometry(mesh.p, vertices.data(), 8, triangles.data(), 12), LIB3MF_OK);
  NMR::MODELTRANSFORM shift = affine({{{1, 0, 0, 10}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
  EXPECT_EQ(
      NMR::lib3mf_model_addbuilditem(model.p, mesh.p, &shift, reinterpret_cast<NMR::PLib3MFModelBuildItem**>(&item1.p)),
      LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_addcomponentsobject(model.p,
                                                  reinterpret_cast<NMR::PLib3MFModelComponentsObject**>(&components.p)),
            LIB3MF_OK);
  NMR::MODELTRANSFORM mirror = affine({{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
  EXPECT_EQ(NMR::lib3mf_componentsobject_addcomponent(components.p, mesh.p, &mirror,
                                                      reinterpret_cast<NMR::PLib3MFModelComponent**>(&component.p)),
            LIB3MF_OK);
  NMR::MODELTRANSFORM back = affine({{{1, 0, 0, -10}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
  EXPECT_EQ(NMR::lib3mf_model_addbuilditem(model.p, components.p, &back,
                                           reinterpret_cast<NMR::PLib3MFModelBuildItem**>(&item2.p)),
            LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_querywriter(model.p, "3mf", reinterpret_cast<NMR::PLib3MFModelWriter**>(&writer.p)),
            LIB3MF_OK);
  ULONG64 size = 0;
  EXPECT_EQ(NMR::lib3mf_writer_getstreamsize(writer.p, &size), LIB3MF_OK);
  std::string bytes(static_cast<size_t>(size), '\0');
  EXPECT_EQ(NMR::lib3mf_writer_writetobuffer(writer.p, reinterpret_cast<BYTE*>(bytes.data()), size), LIB3MF_OK);
  return bytes;
}

TEST(BodyFiles, ThreeMfBuildItemsAndComponentsAreReadWithTransformsInMillimetres) {
  ASSERT_TRUE(can_read_3mf());
  const BodyMesh mesh = parse_body(three_mf_cubes(), BodyFormat::ThreeMf, "c.3mf");
  EXPECT_EQ(mesh.triangles.size(), 24u);
  EXPECT_EQ(mesh.points.size(), 16u);
  const auto box = bounding_box(mesh);
  // Cubes [10, 11] and [-11, -10] cm in x, [0, 1] cm in y and z: in mm.
  EXPECT_EQ(box[0], (std::array<double, 3>{-110, 0, 0}));
  EXPECT_EQ(box[1], (std::array<double, 3>{110, 10, 10}));
  const TopologyReport report = analyse_topology(mesh);
  EXPECT_TRUE(report.closed()) << report.describe();
  EXPECT_EQ(report.shells, 2u);
  // The mirrored cube's triangles were reversed: both face outward.
  EXPECT_NEAR(signed_volume(mesh), 2000.0, 1e-9);
}

// A zip of stored (uncompressed) entries: enough to write a 3MF by hand, as the spec words it, rather
// than through the lib3mf that reads it.
std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& entries) {
  const auto crc32 = [](const std::string& data) {
    uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char c : data) {
      crc ^= c;
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
  };
  std::string out, directory;
  for (const auto& [name, data] : entries) {
    const uint32_t offset = static_cast<uint32_t>(out.size()), crc = crc32(data);
    const uint32_t size = static_cast<uint32_t>(data.size());
    const uint16_t name_size = static_cast<uint16_t>(name.size());
    put<uint32_t>(out, 0x04034b50u);
    for (uint16_t v : {uint16_t(20), uint16_t(0), uint16_t(0), uint16_t(0), uint16_t(0x21)}) put<uint16_t>(out, v);
    for (uint32_t v : {crc, size, size}) put<uint32_t>(out, v);
    put<uint16_t>(out, name_size);
    put<uint16_t>(out, 0);
    out += name + data;
    put<uint32_t>(directory, 0x02014b50u);
    for (uint16_t v : {uint16_t(20), uint16_t(20), uint16_t(0), uint16_t(0), uint16_t(0), uint16_t(0x21)})
      put<uint16_t>(directory, v);
    for (uint32_t v : {crc, size, size}) put<uint32_t>(directory, v);
    for (uint16_t v : {name_size, uint16_t(0), uint16_t(0), uint16_t(0), uint16_t(0)}) put<uint16_t>(directory, v);
    put<uint32_t>(directory, 0);
    put<uint32_t>(directory, offset);
    directory += name;
  }
  const uint32_t directory_offset = static_cast<uint32_t>(out.size());
  out += directory;
  put<uint32_t>(out, 0x06054b50u);
  const uint16_t count = static_cast<uint16_t>(entries.size());
  for (uint16_t v : {uint16_t(0), uint16_t(0), count, count}) put<uint16_t>(out, v);
  put<uint32_t>(out, static_cast<uint32_t>(directory.size()));
  put<uint32_t>(out, directory_offset);
  put<uint16_t>(out, 0);
  return out;
}

// A 3MF package of one tetrahedron with the given unit and build item transform.
std::string hand_made_3mf(const std::string& unit, const std::string& transform) {
  const std::string model =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"" + unit +
      "\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n"
      "<resources><object id=\"1\" type=\"model\"><mesh><vertices>"
      "<vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"1\" y=\"0\" z=\"0\"/><vertex x=\"0\" y=\"1\" z=\"0\"/>"
      "<vertex x=\"0\" y=\"0\" z=\"1\"/></vertices><triangles><triangle v1=\"0\" v2=\"2\" v3=\"1\"/>"
      "<triangle v1=\"0\" v2=\"1\" v3=\"3\"/><triangle v1=\"0\" v2=\"3\" v3=\"2\"/>"
      "<triangle v1=\"1\" v2=\"2\" v3=\"3\"/></triangles></mesh></object></resources>\n"
      "<build><item objectid=\"1\"" +
      (transform.empty() ? "" : " transform=\"" + transform + "\"") + "/></build>\n</model>\n";
  const std::string rels =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships "
      "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship "
      "Target=\"/3D/3dmodel.model\" "
      "Id=\"rel0\" Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>\n";
  const std::string types =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types "
      "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default Extension=\"rels\" "
      "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/><Default Extension=\"model\" "
      "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>\n";
  return stored_zip({{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
}

TEST(BodyFiles, ThreeMfTransformIsAppliedAsTheSpecDefinesIt) {
  // Rows m00 m01 m02 / m10 m11 m12 / m20 m21 m22 / m30 m31 m32 act on row vectors: (x, y, z) goes to
  // (-y + 10, x + 20, 2z + 30), a quarter turn, a stretch of z and a shift.
  const BodyMesh mesh =
      parse_body(hand_made_3mf("millimeter", "0 1 0 -1 0 0 0 0 2 10 20 30"), BodyFormat::ThreeMf, "t.3mf");
  std::vector<std::array<double, 3>> points = mesh.points;
  std::sort(points.begin(), points.end());
  EXPECT_EQ(points, (std::vector<std::array<double, 3>>{{9, 20, 30}, {10, 20, 30}, {10, 20, 32}, {10, 21, 30}}));
  EXPECT_NEAR(signed_volume(mesh), 2.0 / 6, 1e-12);

  const BodyMesh inches = parse_body(hand_made_3mf("inch", ""), BodyFormat::ThreeMf, "t.3mf");
  EXPECT_EQ(bounding_box(inches)[1], (std::array<double, 3>{25.4, 25.4, 25.4}));
}

TEST(BodyFiles, DamagedThreeMfIsAnInputError) {
  std::string bytes = three_mf_cubes();
  EXPECT_NE(error_of(bytes.substr(0, bytes.size() / 2), BodyFormat::ThreeMf, "c.3mf").find("c.3mf: not a readable 3MF"),
            std::string::npos);
  EXPECT_NE(error_of("not a zip at all", BodyFormat::ThreeMf, "c.3mf").find("c.3mf: not a readable 3MF"),
            std::string::npos);
}

#else

TEST(BodyFiles, ThreeMfWithoutLib3mfIsAnInputErrorSayingSo) {
  EXPECT_FALSE(can_read_3mf());
  EXPECT_NE(error_of("PK", BodyFormat::ThreeMf, "c.3mf").find("needs lib3mf"), std::string::npos);
}

#endif

// ---- files ----

TEST(BodyFiles, ReadBodyFileTakesTheFormatFromTheExtension) {
  const fs::path stl = scratch("cube.STL"), ply = scratch("cube.ply"), obj = scratch("cube.obj");
  write_file(stl, binary_stl_cube());
  write_file(ply, binary_ply_cube(true));
  write_file(obj, obj_cube());
  for (const fs::path& path : {stl, ply, obj}) expect_unit_cube(read_body_file(path.string()));
}

TEST(BodyFiles, MissingOrUnreadableFileIsAnInputErrorNamingIt) {
  const std::string missing = scratch("no_such_part.stl").string();
  try {
    read_body_file(missing);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read body '" + missing + "': No such file or directory");
  }
  const fs::path dir = scratch("a_directory.stl");
  fs::create_directories(dir);
  EXPECT_THROW(read_body_file(dir.string()), InputError);
}

TEST(BodyFiles, ErrorsFromAFileNameThePath) {
  const fs::path path = scratch("bad.obj");
  write_file(path, "v 0 0 0\nf 1 2 3\n");
  try {
    read_body_file(path.string());
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": line 2: face vertex 2 out of range (the file has 1 vertices)");
  }
}

// PrusaSlicer's shape gallery: real binary STLs from a CAD pipeline, all closed solids.
TEST(BodyFiles, PrusaSlicerShapesReadAsClosedSolids) {
  const fs::path dir = "/usr/share/PrusaSlicer/shapes";
  if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " absent (apt-get install prusa-slicer)";
  size_t count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".stl") continue;
    ++count;
    const BodyMesh mesh = read_body_file(entry.path().string());
    const TopologyReport report = analyse_topology(mesh);
    EXPECT_TRUE(report.closed()) << entry.path() << ": " << report.describe();
    EXPECT_GT(signed_volume(mesh), 0) << entry.path();
  }
  EXPECT_GT(count, 5u);
}

// A million triangles (a 500 x 1000 grid on a torus) in binary STL: read and welded in seconds.
TEST(SlowBodyFiles, AMillionTriangleBinaryStlIsReadInSeconds) {
  const int nu = 1000, nv = 500;
  const auto at = [&](int i, int j) {
    const double u = 2 * M_PI * (i % nu) / nu, v = 2 * M_PI * (j % nv) / nv;
    return std::array<float, 3>{static_cast<float>((10 + 3 * std::cos(v)) * std::cos(u)),
                                static_cast<float>((10 + 3 * std::cos(v)) * std::sin(u)),
                                static_cast<float>(3 * std::sin(v))};
  };
  std::string bytes(80, ' ');
  put<uint32_t>(bytes, 2u * nu * nv);
  bytes.reserve(84 + 50ull * 2 * nu * nv);
  const auto facet = [&](std::array<float, 3> a, std::array<float, 3> b, std::array<float, 3> c) {
    for (int k = 0; k < 3; ++k) put<float>(bytes, 0.0f);
    for (const auto& p : {a, b, c})
      for (float x : p) put<float>(bytes, x);
    put<uint16_t>(bytes, 0);
  };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      facet(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      facet(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  const auto start = std::chrono::steady_clock::now();
  const BodyMesh mesh = parse_body(bytes, BodyFormat::Stl, "torus.stl");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(mesh.triangles.size(), size_t(2) * nu * nv);
  EXPECT_EQ(mesh.points.size(), size_t(nu) * nv);
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace offsetgen::body
