#include "mesh/narrow_band.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace offsetgen::mesh {
namespace {

constexpr float kActiveBand = 2.0f;  // voxels

// Box distance along one axis: max(-x, x - length), negative inside [0, length].
double axis_distance(double x, double length) { return std::max(-x, x - length); }

struct BlockResult {
  BandBlock block;
  size_t wall_samples = 0, skipped_voxels = 0;
  bool any = false;
};

class BlockSampler {
 public:
  BlockSampler(const WallField& field, const VoxelGrid& grid, double max_thickness, bool use_field_bound,
               float background)
      : field_(field), worker_(field), background_(background) {
    v_ = grid.voxel();
    for (int a = 0; a < 3; ++a) length_[a] = grid.cells[a];
    // A point q with |F(q)| > L h_max is outside the wall: both offsets have the sign of F there (the
    // methods' safeguards guarantee it, see the headers' SAFETY notes). So a voxel with
    // |F| > L (h_max + 2 voxels) is outside with all its neighbours within 2 voxels. L = k M bounds
    // |grad F| only where M was computed: the unit cell, so everywhere for periodic (catalog) surfaces.
    lipschitz_ = use_field_bound ? field.field_lipschitz() : 0;
    far_ = lipschitz_ * (0.5 * max_thickness + 2 * v_);
  }

  void sample(const std::array<int, 3>& origin, BlockResult& out) {
    out = BlockResult{};
    out.block.origin = origin;
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = (origin[a] + 0.5) * v_;
      hi[a] = (origin[a] + kBlock - 0.5) * v_;
    }
    // The whole block more than a voxel outside the box?
    double box_min = -HUGE_VAL;
    for (int a = 0; a < 3; ++a)
      box_min = std::max(box_min, axis_distance(std::clamp(0.5 * length_[a], lo[a], hi[a]), length_[a]));
    if (box_min > v_) return;  // (these voxels are not counted as skipped: they lie outside the box)
    // The whole block far from F = 0?
    const double c[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    const double radius = 0.5 * std::sqrt(3.0) * (kBlock - 1) * v_;
    if (lipschitz_ > 0 && std::abs(field_.field(c[0], c[1], c[2])) > far_ + lipschitz_ * radius) {
      out.skipped_voxels = kBlockVoxels;
      return;
    }

    out.block.values.assign(kBlockVoxels, background_);
    out.block.active.assign(kBlockVoxels, 0);
    x_.clear();
    y_.clear();
    z_.clear();
    box_.clear();
    slot_.clear();
    // Sub-blocks of 4^3 voxels: one F value at the centre rules out 64 voxels far from the walls.
    constexpr int kSub = kBlock / 2;
    const double sub_radius = 0.5 * std::sqrt(3.0) * (kSub - 1) * v_;
    for (int si = 0; si < kBlock; si += kSub)
      for (int sj = 0; sj < kBlock; sj += kSub)
        for (int sl = 0; sl < kBlock; sl += kSub) {
          const double sc[3] = {(origin[0] + si + 0.5 * kSub) * v_, (origin[1] + sj + 0.5 * kSub) * v_,
                                (origin[2] + sl + 0.5 * kSub) * v_};
          if (lipschitz_ > 0 && std::abs(field_.field(sc[0], sc[1], sc[2])) > far_ + lipschitz_ * sub_radius) {
            out.skipped_voxels += kSub * kSub * kSub;
            continue;
          }
          for (int i = si; i < si + kSub; ++i)
            for (int j = sj; j < sj + kSub; ++j)
              for (int l = sl; l < sl + kSub; ++l) {
                const double p[3] = {(origin[0] + i + 0.5) * v_, (origin[1] + j + 0.5) * v_,
                                     (origin[2] + l + 0.5) * v_};
                const double box = std::max({axis_distance(p[0], length_[0]), axis_distance(p[1], length_[1]),
                                             axis_distance(p[2], length_[2])});
                if (box > v_) continue;  // outside, and no edge to a voxel inside crosses the surface
                x_.push_back(p[0]);
                y_.push_back(p[1]);
                z_.push_back(p[2]);
                box_.push_back(box);
                slot_.push_back(block_offset(i, j, l));
              }
        }
    const size_t n = x_.size();
    out.wall_samples = n;
    if (n == 0) return;
    w_.resize(n);
    field_.walls(n, x_.data(), y_.data(), z_.data(), w_.data(), worker_);
    // Only voxels near the surface are active: OpenVDB looks for crossings around active voxels and
    // reads the stored values of inactive ones. |grad w| stays near 1 (w = phi / (k M), and |grad phi|
    // <= k M (1 + O(|h| H / M))), so |value| >= 2 leaves every edge to a neighbour on one side. (The
    // plain 4x4x4 gyroid mesh came out byte-identical with all evaluated voxels active.)
    for (size_t s = 0; s < n; ++s) {
      const float value = static_cast<float>(std::max(w_[s], box_[s]) / v_);
      const size_t slot = static_cast<size_t>(slot_[s]);
      out.block.values[slot] = std::clamp(value, -background_, background_);
      if (std::abs(value) < kActiveBand) {
        out.block.active[slot] = 1;
        out.any = true;
      }
    }
  }

 private:
  const WallField& field_;
  WallField::Worker worker_;
  float background_;
  double v_ = 0, lipschitz_ = 0, far_ = 0;
  double length_[3] = {0, 0, 0};
  std::vector<double> x_, y_, z_, box_, w_;
  std::vector<int> slot_;
};

}  // namespace

SampledBand sample_band(const WallField& field, const VoxelGrid& grid, double max_thickness, bool use_field_bound,
                        int threads, const std::function<void(double)>& progress) {
  SampledBand band;
  // Blocks cover voxel indices [-2, N + 2) on each axis, aligned to multiples of 8.
  std::vector<std::array<int, 3>> origins;
  std::array<int, 3> first{}, last{};
  for (int a = 0; a < 3; ++a) {
    const int n = grid.cells[a] * grid.resolution;
    first[a] = -kBlock;
    last[a] = ((n + 2 + kBlock - 1) / kBlock) * kBlock;
  }
  for (int i = first[0]; i < last[0]; i += kBlock)
    for (int j = first[1]; j < last[1]; j += kBlock)
      for (int l = first[2]; l < last[2]; l += kBlock) origins.push_back({i, j, l});
  band.blocks_tested = origins.size();

  std::vector<BlockResult> results(origins.size());
  std::atomic<size_t> next{0}, done{0};
  auto work = [&] {
    BlockSampler sampler(field, grid, max_thickness, use_field_bound, band.background);
    for (size_t b = next++; b < origins.size(); b = next++) {
      sampler.sample(origins[b], results[b]);
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(threads, 1); ++t) pool.emplace_back(work);
  std::thread main_worker(work);
  while (done.load() < origins.size()) {
    progress(static_cast<double>(done.load()) / static_cast<double>(origins.size()));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  main_worker.join();
  for (auto& t : pool) t.join();
  progress(1.0);

  // In block order, so the grid (and the mesh) do not depend on the threads' schedule.
  for (size_t b = 0; b < origins.size(); ++b) {
    band.wall_samples += results[b].wall_samples;
    band.skipped_voxels += results[b].skipped_voxels;
    if (results[b].any) band.blocks.push_back(std::move(results[b].block));
  }
  return band;
}

}  // namespace offsetgen::mesh
