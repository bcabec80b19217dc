#include "mesh/void_regions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace offsetgen::mesh {
namespace {

// Breadth first over the open voxels from `seeds` (already closed), closing each voxel as it is
// reached, so the open bits are the flood's marks too; calls visit(index) once per voxel. Two
// frontiers, so the memory held is the front, not the region.
template <typename Visit>
void flood(VoxelBits& open, std::vector<uint64_t> front, const Visit& visit) {
  const auto& n = open.size();
  const uint64_t step[3] = {n[1] * n[2], n[2], 1};
  std::vector<uint64_t> next;
  while (!front.empty()) {
    next.clear();
    for (const uint64_t i : front) {
      visit(i);
      const uint64_t c[3] = {i / step[0], i / step[1] % n[1], i % n[2]};
      for (size_t a = 0; a < 3; ++a) {
        if (c[a] > 0 && open.get(i - step[a])) {
          open.set(i - step[a], false);
          next.push_back(i - step[a]);
        }
        if (c[a] + 1 < n[a] && open.get(i + step[a])) {
          open.set(i + step[a], false);
          next.push_back(i + step[a]);
        }
      }
    }
    std::swap(front, next);
  }
}

// The open voxels on the box's faces, closed: the outside's seeds.
std::vector<uint64_t> border_seeds(VoxelBits& open) {
  std::vector<uint64_t> seeds;
  const auto& n = open.size();
  for (uint64_t x = 0; x < n[0]; ++x)
    for (uint64_t y = 0; y < n[1]; ++y) {
      const bool face = x == 0 || y == 0 || x + 1 == n[0] || y + 1 == n[1];
      for (uint64_t z = 0; z < n[2]; z += face ? 1 : std::max<uint64_t>(1, n[2] - 1)) {
        const uint64_t i = (x * n[1] + y) * n[2] + z;
        if (open.get(i)) {
          open.set(i, false);
          seeds.push_back(i);
        }
      }
    }
  return seeds;
}

}  // namespace

VoidReport find_enclosed_voids(VoxelBits& void_bits, double voxel_mm) {
  const auto start = std::chrono::steady_clock::now();
  VoidReport report;
  report.analysed = true;
  report.voxel = voxel_mm;
  report.bytes = void_bits.memory_bytes();
  if (void_bits.count() == 0) return report;
  flood(void_bits, border_seeds(void_bits), [](uint64_t) {});
  const double voxel3 = std::pow(voxel_mm, 3);
  for (uint64_t i = 0; i < void_bits.count(); ++i) {
    if (!void_bits.get(i)) continue;
    VoidRegion region;
    region.seed = void_bits.point(i);
    for (auto& axis : region.extreme) axis = {region.seed, region.seed};
    void_bits.set(i, false);
    flood(void_bits, {i}, [&](uint64_t j) {
      ++region.voxels;
      const auto p = void_bits.point(j);
      for (size_t a = 0; a < 3; ++a) {
        if (p[a] < region.extreme[a][0][a]) region.extreme[a][0] = p;
        if (p[a] > region.extreme[a][1][a]) region.extreme[a][1] = p;
      }
    });
    region.volume = double(region.voxels) * voxel3;
    report.total += region.volume;
    report.largest = std::max(report.largest, region.volume);
    if (region.volume >= kDrainRegionMm3) {
      ++report.large;
      report.large_volume += region.volume;
    }
    report.regions.push_back(region);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

namespace {

// The part's values over a box of voxels, from the sampled band; blocks the band left out are void.
class LocalValues {
 public:
  LocalValues(const VoxelBox& box, const SampledBand& band) : box_(box) {
    for (size_t a = 0; a < 3; ++a) n_[a] = box[1][a] - box[0][a];
    values_.assign(size_t(n_[0]) * size_t(n_[1]) * size_t(n_[2]), band.background);
    for (const BandBlock& block : band.blocks)
      for (int x = 0; x < kBlock; ++x)
        for (int y = 0; y < kBlock; ++y)
          for (int z = 0; z < kBlock; ++z) {
            const std::array<int, 3> p{block.origin[0] + x, block.origin[1] + y, block.origin[2] + z};
            if (!contains(p)) continue;
            at(p) = block.solid ? -band.background : block.values[size_t(block_offset(x, y, z))];
          }
  }
  bool contains(const std::array<int, 3>& p) const {
    for (size_t a = 0; a < 3; ++a)
      if (p[a] < box_[0][a] || p[a] >= box_[1][a]) return false;
    return true;
  }
  size_t index(const std::array<int, 3>& p) const {
    return (size_t(p[0] - box_[0][0]) * size_t(n_[1]) + size_t(p[1] - box_[0][1])) * size_t(n_[2]) +
           size_t(p[2] - box_[0][2]);
  }
  size_t size() const { return values_.size(); }
  float at(const std::array<int, 3>& p) const { return values_[index(p)]; }
  float& at(const std::array<int, 3>& p) { return values_[index(p)]; }

 private:
  VoxelBox box_;
  std::array<int, 3> n_{};
  std::vector<float> values_;
};

using Vec = std::array<double, 3>;

// The point OpenVDB's volumeToMesh puts in the cell whose lowest corner is voxel c: the average of
// where the value crosses zero, linearly, along the cell's edges that change sign.
Vec cell_point(const LocalValues& values, const std::array<int, 3>& c) {
  Vec sum{0, 0, 0};
  int crossings = 0;
  for (size_t a = 0; a < 3; ++a)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        std::array<int, 3> u = c;
        u[(a + 1) % 3] += i;
        u[(a + 2) % 3] += j;
        std::array<int, 3> w = u;
        w[a] += 1;
        const double vu = values.at(u), vw = values.at(w);
        if ((vu > 0) == (vw > 0)) continue;
        const double t = vu / (vu - vw);
        for (size_t k = 0; k < 3; ++k) sum[k] += double(u[k]) + (k == a ? t : 0.0);
        ++crossings;
      }
  for (double& x : sum) x /= std::max(crossings, 1);
  return sum;
}

// The region's void in voxels as the mesh encloses it: its voxels flooded from the seed; each edge
// from one of them to a material voxel carries a quad through the points of the four cells around it
// (as volumeToMesh builds the surface), and the quads, facing out of the void, enclose its volume
// (divergence theorem). The mesh cuts a thin region's corners by several percent; so does this.
double meshed_voxels(const LocalValues& values, const std::array<int, 3>& seed) {
  std::vector<std::array<int, 3>> stack{seed}, members{seed};
  std::vector<uint8_t> in(values.size(), 0);
  in[values.index(seed)] = 1;
  while (!stack.empty()) {
    const auto p = stack.back();
    stack.pop_back();
    for (size_t a = 0; a < 3; ++a)
      for (int side : {-1, 1}) {
        auto q = p;
        q[a] += side;
        if (!values.contains(q) || in[values.index(q)] || !(values.at(q) > 0)) continue;
        in[values.index(q)] = 1;
        stack.push_back(q);
        members.push_back(q);
      }
  }
  const Vec r{double(seed[0]), double(seed[1]), double(seed[2])};
  auto tetra = [&r](const Vec& x, const Vec& y, const Vec& z) {
    const Vec a{x[0] - r[0], x[1] - r[1], x[2] - r[2]}, b{y[0] - r[0], y[1] - r[1], y[2] - r[2]},
        c{z[0] - r[0], z[1] - r[1], z[2] - r[2]};
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
            a[2] * (b[0] * c[1] - b[1] * c[0])) /
           6;
  };
  double volume = 0;
  for (const auto& p : members)
    for (size_t a = 0; a < 3; ++a)
      for (int side : {-1, 1}) {
        auto q = p;
        q[a] += side;
        if (!values.contains(q) || in[values.index(q)]) continue;
        // The four cells around edge pq, counter-clockwise seen from +a.
        const size_t b = (a + 1) % 3, c = (a + 2) % 3;
        const int ob[4] = {-1, 0, 0, -1}, oc[4] = {-1, -1, 0, 0};
        Vec corner[4];
        for (int k = 0; k < 4; ++k) {
          std::array<int, 3> cell = p;
          cell[a] = std::min(p[a], q[a]);
          cell[b] += ob[k];
          cell[c] += oc[k];
          corner[k] = cell_point(values, cell);
        }
        const double quad = tetra(corner[0], corner[1], corner[2]) + tetra(corner[0], corner[2], corner[3]);
        volume += side > 0 ? quad : -quad;
      }
  return volume;
}

}  // namespace

void refine_small_regions(VoidReport& report, const BandSampler& sample) {
  const double voxel3 = std::pow(report.voxel, 3);
  for (VoidRegion& region : report.regions) {
    if (region.volume < kRefineAboveMm3 || region.volume >= kRefineBelowMm3) continue;
    // The region's box and a voxel around it, in whole blocks.
    VoxelBox box{};
    for (size_t a = 0; a < 3; ++a) {
      const int lo = region.extreme[a][0][a] - 1, hi = region.extreme[a][1][a] + 2;
      box[0][a] = lo >= 0 ? lo / kBlock * kBlock : -((-lo + kBlock - 1) / kBlock) * kBlock;
      box[1][a] = hi >= 0 ? (hi + kBlock - 1) / kBlock * kBlock : -(-hi / kBlock) * kBlock;
    }
    const LocalValues values(box, sample(box));
    if (!(values.at(region.seed) > 0)) continue;  // not the void recorded: keep the count
    region.volume = meshed_voxels(values, region.seed) * voxel3;
  }
  report.total = report.largest = report.large_volume = 0;
  report.large = 0;
  for (const VoidRegion& region : report.regions) {
    report.total += region.volume;
    report.largest = std::max(report.largest, region.volume);
    if (region.volume >= kDrainRegionMm3) {
      ++report.large;
      report.large_volume += region.volume;
    }
  }
}

VoxelBits pockets_to_fill(const VoxelBits& void_bits, const VoidReport& report, double below_mm3, double& filled) {
  // Each small region flooded from its seed in a copy of the void, its voxels marked.
  VoxelBits open = void_bits;
  VoxelBits fill(void_bits.box(), false);
  filled = 0;
  for (const VoidRegion& region : report.regions) {
    if (region.volume >= below_mm3) continue;
    const uint64_t i = open.index(region.seed[0], region.seed[1], region.seed[2]);
    open.set(i, false);
    fill.set(i, true);
    flood(open, {i}, [&fill](uint64_t j) { fill.set(j, true); });
    filled += region.volume;
  }
  return fill;
}

}  // namespace offsetgen::mesh
