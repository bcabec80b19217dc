// `offsetgen slice --body`: a part filled with the lattice inside a skin, read back by the tests' own
// CLI reader and checked against the geometry by code that is not the slicer's: every vertex lies on
// the part's boundary, which is the wall (|w| / |grad w| within 1e-6 mm, the emitted functions evaluated
// there), the body's surface (distance 0 to its facets, brute force over all of them) or the core's
// surface (distance = the skin); loops are closed and dir matches the signed area; and bad bodies exit 2
// with no file.
#include "body/body_files.h"
#include "cli_reader.h"
#include "offsetgen_test_support.h"
#include "slice_test_support.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;
using test_support::read_file;
using test_support::run_offsetgen;
using test_support::scratch_dir;
using namespace test;  // the CLI reader

const std::string kSphere = "/usr/share/PrusaSlicer/shapes/sphere.stl";  // 31 mm, from Debian's prusa-slicer
constexpr double kSkin = 1.5, kCell = 6, kLayer = 1.0;

using V3 = std::array<double, 3>;
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The distance from p to the triangle abc: the nearest point of its plane if that lies inside,
// else the nearest point of its three edges.
double triangle_distance(const V3& p, const V3& a, const V3& b, const V3& c) {
  const V3 ab = sub(b, a), ac = sub(c, a);
  const V3 n = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
  const double nn = dot(n, n);
  if (nn > 0) {
    const double t = dot(sub(p, a), n) / nn;
    const V3 q = {p[0] - t * n[0], p[1] - t * n[1], p[2] - t * n[2]};
    // Barycentric signs: q inside when it is on the inner side of all three edges.
    auto side = [&](const V3& u, const V3& v) {
      const V3 e = sub(v, u), f = sub(q, u);
      const V3 x = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
      return dot(x, n) >= 0;
    };
    if (side(a, b) && side(b, c) && side(c, a)) return std::abs(t) * std::sqrt(nn);
  }
  auto segment = [&](const V3& u, const V3& v) {
    const V3 e = sub(v, u);
    const double l2 = dot(e, e);
    const double s = l2 > 0 ? std::clamp(dot(sub(p, u), e) / l2, 0.0, 1.0) : 0.0;
    const V3 q = {u[0] + s * e[0] - p[0], u[1] + s * e[1] - p[1], u[2] + s * e[2] - p[2]};
    return std::sqrt(dot(q, q));
  };
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

double body_distance(const body::BodyMesh& mesh, const V3& p) {
  double best = HUGE_VAL;
  for (const auto& t : mesh.triangles)
    best = std::min(best, triangle_distance(p, mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]));
  return best;
}

TEST(SliceBody, FilledSphereCliVerticesLieOnTheWallTheBodyOrTheCoreWithin1e6Mm) {
  if (!fs::exists(kSphere)) GTEST_SKIP() << kSphere << " is missing (tools/install_deps.sh installs prusa-slicer)";
  const std::string dir = scratch_dir("slice-body-sphere");
  const auto r = run_offsetgen({"slice", "--surface", "gyroid", "--density", "0.25", "--body", kSphere, "--skin",
                                fmt::format("{}", kSkin), "--cell-size", fmt::format("{}", kCell), "--layer-height",
                                fmt::format("{}", kLayer), "--cli-ascii", "-o", dir + "/sphere.cli"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("body:       " + kSphere), std::string::npos) << r.output;

  const body::BodyMesh mesh = body::read_body_file(kSphere);
  const auto box = body::bounding_box(mesh);
  const CliFile f = read_cli(read_file(dir + "/sphere.cli"));
  EXPECT_EQ(f.header_layers, static_cast<long>(f.layers.size()));
  ASSERT_EQ(f.layers.size(), static_cast<size_t>(std::ceil((box[1][2] - box[0][2]) / kLayer - 0.5)));

  wall::WallField field(gyroid_request("0.25"));
  field.compile();
  size_t on_wall = 0, on_body = 0, on_core = 0, checked = 0, misses = 0;
  for (size_t k = 0; k < f.layers.size(); ++k) {
    const CliLayer& layer = f.layers[k];
    EXPECT_NEAR(layer.z, kLayer * double(k + 1), 1e-6);
    const double z = box[0][2] + layer.z - 0.5 * kLayer;  // the cut, in the body's millimetres
    std::vector<std::array<double, 2>> points;            // from the lattice's origin, the body's box minimum
    std::vector<std::array<double, 2>> lattice;
    for (const Polyline& p : layer.polylines) {
      EXPECT_EQ(p.points.front(), p.points.back()) << "an open polyline in layer " << k;
      EXPECT_EQ(p.dir, signed_area(p.points) > 0 ? 1 : 0);
      for (size_t i = 0; i + 1 < p.points.size(); ++i) {
        points.push_back(p.points[i]);
        lattice.push_back({p.points[i][0] - box[0][0], p.points[i][1] - box[0][1]});
      }
    }
    const std::vector<double> w = wall_distances(field, lattice, z - box[0][2], kCell);
    for (size_t i = 0; i < points.size(); ++i) {
      const double d = body_distance(mesh, {points[i][0], points[i][1], z});
      const bool wall = w[i] < 1e-6, surface = d < 1e-6, core = std::abs(d - kSkin) < 1e-6;
      on_wall += wall;
      on_body += surface;
      on_core += core;
      ++checked;
      if (!(wall || surface || core) && ++misses <= 10)
        ADD_FAILURE() << "layer " << k << ": (" << points[i][0] << ", " << points[i][1] << ") is " << w[i]
                      << " mm off the wall and " << d << " mm from the body";
    }
  }
  EXPECT_EQ(misses, 0u) << "of " << checked << " vertices";
  EXPECT_GT(on_wall, 1000u);
  EXPECT_GT(on_body, 100u);
  EXPECT_GT(on_core, 100u);
}

TEST(SliceBody, BadBodiesExit2AndWriteNothing) {
  if (!fs::exists(kSphere)) GTEST_SKIP() << kSphere << " is missing (tools/install_deps.sh installs prusa-slicer)";
  const std::string dir = scratch_dir("slice-body-bad");
  fs::create_directories(dir);
  {
    std::ofstream open_body(dir + "/open.stl");
    open_body << "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 10 0 0\nvertex 0 10 0\nendloop\n"
                 "endfacet\nendsolid a\n";
  }
  const std::vector<std::string> base = {"slice", "--surface", "gyroid", "--density", "0.25", "--cell-size", "6"};
  struct Case {
    std::vector<std::string> extra;
    std::string output, says;
  };
  const std::vector<Case> cases = {
      {{"--body", dir + "/missing.stl"}, "a.cli", "missing.stl"},
      {{"--body", dir + "/open.stl"}, "b.cli", "not a closed surface"},
      {{"--body", kSphere, "--skin", "16"}, "c.cli", "leaves no core"},
      {{"--body", kSphere, "--scale", "5"}, "d.sl1", "larger than the SL1 screen"},
      {{"--body", kSphere, "--cells", "2"}, "e.cli", "excludes"},
      {{"--body", kSphere, "--skin", "-1"}, "f.cli", "--skin -1"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = base;
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    args.insert(args.end(), {"-o", dir + "/" + c.output});
    const auto r = run_offsetgen(args);
    EXPECT_EQ(r.exit_code, 2) << c.says << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/" + c.output)) << c.output;
  }
}

}  // namespace
}  // namespace offsetgen::slice
