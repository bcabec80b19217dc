// An independent check of `offsetgen mesh`'s void report (issue 43), written apart from the mesher:
// voxelises a written binary STL (voxel centres inside by ray parity along z, one column at a time),
// flood-fills the void from the grid's border (the outside), and labels what void is left: the enclosed
// regions, 6-connected. Prints one line:
//   stl_voids: N enclosed regions, V mm^3 trapped (largest L mm^3); K of 1 mm^3 or more (W mm^3)
// then each region of 1 mm^3 or more and at least the eight largest, largest first. Usage: stl_voids PART.stl
// [VOXEL_MM, default 0.08]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace {

using Tri = std::array<std::array<double, 3>, 3>;

std::vector<Tri> read_binary_stl(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "stl_voids: cannot read %s\n", path);
    std::exit(2);
  }
  char header[80];
  uint32_t count = 0;
  in.read(header, 80);
  in.read(reinterpret_cast<char*>(&count), 4);
  std::vector<Tri> tris(count);
  for (uint32_t t = 0; t < count; ++t) {
    float f[12];
    uint16_t attr = 0;
    in.read(reinterpret_cast<char*>(f), sizeof f);
    in.read(reinterpret_cast<char*>(&attr), 2);
    for (int v = 0; v < 3; ++v)
      for (int a = 0; a < 3; ++a) tris[t][size_t(v)][size_t(a)] = f[3 + 3 * v + a];
  }
  if (!in) {
    std::fprintf(stderr, "stl_voids: %s is not a binary STL\n", path);
    std::exit(2);
  }
  return tris;
}

struct Grid {
  std::array<double, 3> lo{};
  double h = 0.08;
  std::array<int64_t, 3> n{};
  std::vector<uint8_t> solid;  // 1 inside the part; index (x * ny + y) * nz + z
  int64_t at(int64_t x, int64_t y, int64_t z) const { return (x * n[1] + y) * n[2] + z; }
};

// Columns along z through voxel centres, shifted by a few hundred-thousandths of a voxel so that no
// column passes through a mesh vertex or edge (the mesh's vertices lie on the mesher's grid).
Grid voxelise(const std::vector<Tri>& tris, double h) {
  Grid g;
  g.h = h;
  std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Tri& t : tris)
    for (const auto& p : t)
      for (size_t a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
  for (size_t a = 0; a < 3; ++a) {
    g.lo[a] = lo[a] - 2 * h;
    g.n[a] = int64_t(std::ceil((hi[a] - lo[a]) / h)) + 4;
  }
  const double shift[2] = {h * 1.7320508e-5, h * 2.2360679e-5};
  auto cx = [&](int64_t i) { return g.lo[0] + (double(i) + 0.5) * h + shift[0]; };
  auto cy = [&](int64_t j) { return g.lo[1] + (double(j) + 0.5) * h + shift[1]; };
  const int64_t columns = g.n[0] * g.n[1];
  std::vector<uint32_t> start(size_t(columns) + 1, 0);
  std::vector<float> hits;
  // Two passes: count the crossings per column, then store them.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<uint32_t> fill;
    if (pass == 1) {
      for (int64_t c = 0; c < columns; ++c) start[size_t(c + 1)] += start[size_t(c)];
      hits.resize(start[size_t(columns)]);
      fill.assign(start.begin(), start.end() - 1);
    }
    for (const Tri& t : tris) {
      const double x0 = std::min({t[0][0], t[1][0], t[2][0]}), x1 = std::max({t[0][0], t[1][0], t[2][0]});
      const double y0 = std::min({t[0][1], t[1][1], t[2][1]}), y1 = std::max({t[0][1], t[1][1], t[2][1]});
      const auto i0 = std::max<int64_t>(0, int64_t(std::floor((x0 - g.lo[0]) / h - 0.5)));
      const auto i1 = std::min<int64_t>(g.n[0] - 1, int64_t(std::ceil((x1 - g.lo[0]) / h - 0.5)));
      const auto j0 = std::max<int64_t>(0, int64_t(std::floor((y0 - g.lo[1]) / h - 0.5)));
      const auto j1 = std::min<int64_t>(g.n[1] - 1, int64_t(std::ceil((y1 - g.lo[1]) / h - 0.5)));
      for (int64_t i = i0; i <= i1; ++i)
        for (int64_t j = j0; j <= j1; ++j) {
          const double px = cx(i), py = cy(j);
          // Edge functions of the projection; the column crosses where all three share a sign.
          double w[3];
          for (int e = 0; e < 3; ++e) {
            const auto& a = t[size_t(e)];
            const auto& b = t[size_t((e + 1) % 3)];
            w[e] = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
          }
          const bool in = (w[0] > 0 && w[1] > 0 && w[2] > 0) || (w[0] < 0 && w[1] < 0 && w[2] < 0);
          if (!in) continue;
          const size_t c = size_t(i * g.n[1] + j);
          if (pass == 0) {
            ++start[c + 1];
            continue;
          }
          const double sum = w[0] + w[1] + w[2];
          // w[e] weighs the vertex opposite edge e.
          const double z = (w[1] * t[0][2] + w[2] * t[1][2] + w[0] * t[2][2]) / sum;
          hits[fill[c]++] = float(z);
        }
    }
  }
  g.solid.assign(size_t(g.n[0] * g.n[1] * g.n[2]), 0);
  for (int64_t c = 0; c < columns; ++c) {
    auto* first = hits.data() + start[size_t(c)];
    auto* last = hits.data() + start[size_t(c + 1)];
    std::sort(first, last);
    const int64_t i = c / g.n[1], j = c % g.n[1];
    for (auto* p = first; p + 1 < last; p += 2) {
      const auto k0 = std::max<int64_t>(0, int64_t(std::ceil((double(p[0]) - g.lo[2]) / h - 0.5)));
      const auto k1 = std::min<int64_t>(g.n[2] - 1, int64_t(std::floor((double(p[1]) - g.lo[2]) / h - 0.5)));
      for (int64_t k = k0; k <= k1; ++k) g.solid[size_t(g.at(i, j, k))] = 1;
    }
  }
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: stl_voids PART.stl [VOXEL_MM]\n");
    return 2;
  }
  const double h = argc == 3 ? std::atof(argv[2]) : 0.08;
  Grid g = voxelise(read_binary_stl(argv[1]), h);
  // state: 0 void unvisited, 1 solid, 2 visited void.
  std::vector<uint8_t>& state = g.solid;
  std::vector<int64_t> stack;
  std::array<double, 6> bbox{};
  auto flood = [&](int64_t seed) {
    int64_t voxels = 0;
    bbox = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    state[size_t(seed)] = 2;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int64_t v = stack.back();
      stack.pop_back();
      ++voxels;
      const int64_t z = v % g.n[2], y = v / g.n[2] % g.n[1], x = v / (g.n[1] * g.n[2]);
      const double c[3] = {g.lo[0] + (double(x) + 0.5) * h, g.lo[1] + (double(y) + 0.5) * h,
                           g.lo[2] + (double(z) + 0.5) * h};
      for (size_t a = 0; a < 3; ++a) {
        bbox[a] = std::min(bbox[a], c[a]);
        bbox[a + 3] = std::max(bbox[a + 3], c[a]);
      }
      const int64_t nb[6][3] = {{x - 1, y, z}, {x + 1, y, z}, {x, y - 1, z},
                                {x, y + 1, z}, {x, y, z - 1}, {x, y, z + 1}};
      for (const auto& q : nb) {
        if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= g.n[0] || q[1] >= g.n[1] || q[2] >= g.n[2]) continue;
        const int64_t u = g.at(q[0], q[1], q[2]);
        if (state[size_t(u)] != 0) continue;
        state[size_t(u)] = 2;
        stack.push_back(u);
      }
    }
    return voxels;
  };
  flood(g.at(0, 0, 0));  // the border is void: the grid has two voxels of margin
  struct Region {
    double volume;
    std::array<double, 6> box;
  };
  std::vector<Region> regions;
  const double voxel3 = h * h * h;
  for (int64_t v = 0; v < int64_t(state.size()); ++v)
    if (state[size_t(v)] == 0) {
      const double volume = double(flood(v)) * voxel3;
      regions.push_back({volume, bbox});
    }
  std::stable_sort(regions.begin(), regions.end(),
                   [](const Region& a, const Region& b) { return a.volume > b.volume; });
  std::vector<double> volumes;
  for (const Region& r : regions) volumes.push_back(r.volume);
  double total = 0, large_volume = 0;
  size_t large = 0;
  for (double v : volumes) {
    total += v;
    if (v >= 1.0) {
      ++large;
      large_volume += v;
    }
  }
  std::printf(
      "stl_voids: %zu enclosed regions, %.1f mm^3 trapped (largest %.1f mm^3); %zu of 1 mm^3 or more (%.1f mm^3)\n",
      volumes.size(), total, volumes.empty() ? 0.0 : volumes.front(), large, large_volume);
  for (size_t i = 0; i < std::max<size_t>(large, std::min<size_t>(volumes.size(), 8)); ++i)
    std::printf("  region %zu: %.2f mm^3, box (%.2f, %.2f, %.2f) to (%.2f, %.2f, %.2f) mm\n", i + 1, volumes[i],
                regions[i].box[0], regions[i].box[1], regions[i].box[2], regions[i].box[3], regions[i].box[4],
                regions[i].box[5]);
  return 0;
}
