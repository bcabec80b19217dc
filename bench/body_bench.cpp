// Bodies (src/body/) at a million triangles: reading a binary STL (parse and weld), the topology
// analysis of a broken mesh, its repair, and the analysis of the closed result. The same torus as the
// slow body tests (tests/body/: SlowBodyFiles and SlowBodyTopology assert only that each takes seconds,
// not minutes); this prints the times, the median of --runs runs (default 5).
//   bench_body [--runs N]
#include "body/body_files.h"
#include "body/body_mesh.h"
#include "body/body_topology.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using offsetgen::body::BodyMesh;
constexpr int kU = 1000, kV = 500;  // 2 kU kV = 1,000,000 triangles

std::array<float, 3> torus_point(int i, int j) {
  const double u = 2 * M_PI * (i % kU) / kU, v = 2 * M_PI * (j % kV) / kV;
  return {static_cast<float>((10 + 3 * std::cos(v)) * std::cos(u)),
          static_cast<float>((10 + 3 * std::cos(v)) * std::sin(u)), static_cast<float>(3 * std::sin(v))};
}

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// The torus as binary STL: 1,000,000 facets.
std::string torus_stl() {
  std::string bytes(80, ' ');
  put<uint32_t>(bytes, 2u * kU * kV);
  const auto facet = [&](const std::array<float, 3>& a, const std::array<float, 3>& b, const std::array<float, 3>& c) {
    for (int k = 0; k < 3; ++k) put<float>(bytes, 0.0f);
    for (const auto& p : {a, b, c})
      for (float x : p) put<float>(bytes, x);
    put<uint16_t>(bytes, 0);
  };
  for (int i = 0; i < kU; ++i)
    for (int j = 0; j < kV; ++j) {
      facet(torus_point(i, j), torus_point(i + 1, j), torus_point(i + 1, j + 1));
      facet(torus_point(i, j), torus_point(i + 1, j + 1), torus_point(i, j + 1));
    }
  return bytes;
}

// The welded torus with the slow topology test's defects: every 1001st facet flipped, two removed.
BodyMesh broken(const BodyMesh& torus) {
  BodyMesh mesh = torus;
  for (size_t i = 7; i < mesh.triangles.size(); i += 1001) std::swap(mesh.triangles[i][1], mesh.triangles[i][2]);
  mesh.triangles.erase(mesh.triangles.begin() + 123456);
  mesh.triangles.erase(mesh.triangles.begin() + 654321);
  return mesh;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else {
      fmt::print(stderr, "usage: bench_body [--runs N]\n");
      return 2;
    }
  }
  const std::string stl = torus_stl();
  std::vector<double> parse, analyse_broken, repair, analyse_closed;
  std::string repaired;
  size_t triangles = 0;
  for (int r = 0; r < runs; ++r) {
    auto start = std::chrono::steady_clock::now();
    const BodyMesh torus = offsetgen::body::parse_body(stl, offsetgen::body::BodyFormat::Stl, "torus.stl");
    parse.push_back(seconds_since(start));
    triangles = torus.triangles.size();
    BodyMesh mesh = broken(torus);
    start = std::chrono::steady_clock::now();
    offsetgen::body::analyse_topology(mesh);
    analyse_broken.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    repaired = offsetgen::body::repair_body(mesh).describe();
    repair.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    offsetgen::body::analyse_topology(mesh);
    analyse_closed.push_back(seconds_since(start));
  }
  fmt::print("body of {} triangles (a torus), median of {} runs:\n", triangles, runs);
  fmt::print("  parse and weld the binary STL  {:.3f} s\n", median(parse));
  fmt::print("  analyse (broken)               {:.3f} s\n", median(analyse_broken));
  fmt::print("  repair                         {:.3f} s ({})\n", median(repair), repaired);
  fmt::print("  analyse (closed)               {:.3f} s\n", median(analyse_closed));
  return 0;
}
