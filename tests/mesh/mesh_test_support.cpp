#include "mesh_test_support.h"

#include "mesh/mesh_files.h"

#include "pipeline/generate.h"
#include "run/metadata.h"
#include "run/process.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace offsetgen::mesh::testing {
namespace fs = std::filesystem;

std::vector<std::array<std::array<float, 3>, 3>> read_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 84) throw std::runtime_error(path + ": too short for binary STL");
  uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  if (bytes.size() != 84 + 50 * size_t(n)) throw std::runtime_error(path + ": size does not match the facet count");
  std::vector<std::array<std::array<float, 3>, 3>> facets(n);
  for (size_t i = 0; i < n; ++i) std::memcpy(facets[i].data(), bytes.data() + 84 + 50 * i + 12, 36);
  return facets;
}

double stl_volume(const std::vector<std::array<std::array<float, 3>, 3>>& facets) {
  double v = 0;
  for (const auto& f : facets) {
    const auto &a = f[0], &b = f[1], &c = f[2];
    v += (a[0] * (double(b[1]) * c[2] - double(b[2]) * c[1]) + a[1] * (double(b[2]) * c[0] - double(b[0]) * c[2]) +
          a[2] * (double(b[0]) * c[1] - double(b[1]) * c[0])) /
         6.0;
  }
  return v;
}

std::map<std::string, double> admesh_report(const std::string& stl, std::string* raw) {
  run::ProcessResult r = run::run_process({"admesh", stl});
  if (!r.started || r.exit_code != 0) throw std::runtime_error("admesh failed: " + r.output);
  if (raw) *raw = r.output;
  std::map<std::string, double> out;
  // admesh prints the initial check ("Number of facets", "Total disconnected facets") and then the
  // results after its fixes, with the same labels; the first occurrence is the file as written.
  const std::vector<std::pair<std::string, std::string>> labels = {
      {"facets", "Number of facets"},         {"disconnected facets", "Total disconnected facets"},
      {"parts", "Number of parts"},           {"degenerate facets", "Degenerate facets"},
      {"edges fixed", "Edges fixed"},         {"facets removed", "Facets removed"},
      {"facets added", "Facets added"},       {"facets reversed", "Facets reversed"},
      {"backwards edges", "Backwards edges"}, {"normals fixed", "Normals fixed"}};
  for (const auto& [key, label] : labels) {
    std::regex re(label + R"(\s*:\s*(-?[0-9.]+))");
    std::smatch m;
    if (std::regex_search(r.output, m, re)) out[key] = std::stod(m[1]);
  }
  return out;
}

ExactWalls::ExactWalls(const std::string& surface, int order, double thickness) : t_(thickness) {
  GenerationRequest request;
  request.surface = surface;
  request.order = order;
  Generation g = generate(request);
  const std::string dir = scratch_dir("exact-" + surface);
  const std::string path = dir + "/" + g.prefix + ".h";
  std::ofstream(path) << g.c_header();
  run::FileMetadata meta = run::read_metadata(path);
  run::CompileOptions options;
  options.optimization = "-O2";
  options.cxx = false;
  compiled_ = std::make_unique<run::CompileResult>(run::compile_and_load(path, meta, run::find_toolchain(), options));
  if (!compiled_->ok) throw std::runtime_error("cannot compile " + path);
}

double ExactWalls::phi(const double p[3], double h) const { return compiled_->library->functions().offset(p, h); }

double ExactWalls::w(const double p[3]) const { return std::max(phi(p, 0.5 * t_), -phi(p, -0.5 * t_)); }

void expect_clean_part(const Case& c) {
  const std::string dir = scratch_dir("admesh-" + c.name);
  const std::string stl = dir + "/part.stl";
  std::vector<std::string> args = {"mesh", "--cells", "3", "--cell-size", "10", "-o", stl};
  args.insert(args.end(), c.args.begin(), c.args.end());
  CliRun r = run_offsetgen(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "a progress bar, though stderr is not a terminal";
  std::string raw;
  auto report = admesh_report(stl, &raw);
  EXPECT_GT(report["facets"], 1000) << raw;
  EXPECT_EQ(report["disconnected facets"], 0) << raw;
  EXPECT_EQ(report["facets added"], 0) << "holes\n" << raw;
  EXPECT_EQ(report["backwards edges"], 0) << raw;
  EXPECT_EQ(report["facets reversed"], 0) << raw;
  EXPECT_EQ(report["parts"], 1) << raw;
  EXPECT_GT(stl_volume(read_stl(stl)), 0) << "facets face inward";
}

constexpr double kPi = 3.14159265358979323846;

// An icosphere of radius r about c: the icosahedron, each triangle split in 4 `levels` times.
TriangleMesh sphere(double r, const std::array<double, 3>& c, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<uint32_t, 3>> t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
    auto mid = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      p.push_back({(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2});
      return middle[key] = static_cast<uint32_t>(p.size() - 1);
    };
    std::vector<std::array<uint32_t, 3>> next;
    for (const auto& f : t) {
      const uint32_t a = mid(f[0], f[1]), b = mid(f[1], f[2]), d = mid(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, d}, {f[1], b, a}, {f[2], d, b}, {a, b, d}});
    }
    t = next;
  }
  TriangleMesh m;
  for (const auto& q : p) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    m.points.push_back({static_cast<float>(c[0] + r * q[0] / n), static_cast<float>(c[1] + r * q[1] / n),
                        static_cast<float>(c[2] + r * q[2] / n)});
  }
  m.triangles = t;
  return m;
}

// A torus about the z axis through c: major radius big, minor radius small, n x m quads.
TriangleMesh torus(double big, double small, const std::array<double, 3>& c, int n, int m) {
  TriangleMesh out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      out.points.push_back({static_cast<float>(c[0] + (big + small * std::cos(v)) * std::cos(u)),
                            static_cast<float>(c[1] + (big + small * std::cos(v)) * std::sin(u)),
                            static_cast<float>(c[2] + small * std::sin(v))});
    }
  auto at = [&](int i, int j) { return static_cast<uint32_t>(((i + n) % n) * m + (j + m) % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      out.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      out.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return out;
}

void write_stl(const TriangleMesh& m, const std::string& path) {
  std::ofstream(path, std::ios::binary) << encode_mesh(m, MeshFormat::Stl, "test body");
}

// "key: ... <number> ..." -> the first number after `label` in the summary.
double summary_number(const std::string& summary, const std::string& label) {
  const size_t at = summary.find(label);
  if (at == std::string::npos) throw std::runtime_error("no '" + label + "' in:\n" + summary);
  return std::stod(summary.substr(at + label.size()));
}

// admesh counts every closed surface as a part: the outer one and each cavity the skin closes
// (cavities < 0: not checked).
void expect_admesh_clean(const std::string& stl, double cavities) {
  std::string raw;
  auto report = admesh_report(stl, &raw);
  EXPECT_EQ(report["facets added"], 0) << raw;
  EXPECT_EQ(report["backwards edges"], 0) << raw;
  EXPECT_EQ(report["disconnected facets"], 0) << raw;
  if (cavities >= 0) {
    EXPECT_EQ(report["parts"], 1 + cavities) << raw;
  }
}

}  // namespace offsetgen::mesh::testing
