#include "mesh/narrow_band.h"

#include "mesh/part_edits.h"

#include "wall/field_bound.h"
#include "wall/parallel_blocks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

namespace offsetgen::mesh {
namespace {

constexpr float kActiveBand = 2.0f;  // voxels
// Values are kept at least this far from zero (voxels). A sample at zero puts the crossings of all its
// edges on it, so the vertices of the cells around it coincide once written as floats: a degenerate
// facet. The shift, 1/100 voxel at most, is far below the mesher's own error.
constexpr float kLeastMagnitude = 0.01f;
constexpr double kFarFromWalls = 1e30;  // voxels: w where F rules the walls out

struct BlockResult {
  BandBlock block;
  size_t wall_samples = 0, skipped_voxels = 0;
  size_t inside = 0;  // voxels stored with a negative value
  VoxelTally tally;
  bool any = false, deep = false;
  // Solid throughout and nowhere near the surface: every voxel was stored, all inside.
  bool solid() const { return !any && inside == static_cast<size_t>(kBlockVoxels); }
};

class BlockSampler {
 public:
  BlockSampler(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
               bool use_field_bound, float background)
      : field_(field),
        worker_(field),
        reader_(domain.reader()),
        background_(background),
        v_(grid.voxel()),
        fillet_(domain.fillet),
        // Far from the walls: the voxel and its neighbours within 2 voxels outside them, and beyond the
        // reach of the skin's fillet.
        bound_(field, use_field_bound ? field.field_lipschitz() : 0, reach, (kActiveBand + domain.fillet) * v_) {
    skin_given_ = domain.skin;
    margin_ = domain.lattice_margin();
    edits_ = domain.edits;
    // Planted faults for the tests of the part's check (docs/testing.md), as git's GIT_TEST_*.
    if (const char* fault = std::getenv("OFFSETGEN_TEST_FAULT")) {
      plant_shallow_skin_ = std::string(fault) == "shallow-skin";
      plant_dropped_blocks_ = std::string(fault) == "drop-solid-blocks";
    }
  }
  bool drops_solid_blocks() const { return plant_dropped_blocks_; }

  void sample(const std::array<int, 3>& origin, BlockResult& out) {
    sample_part(origin, out);
    if (!edits_ || !apply_part_edits(*edits_, origin, background_, out.block.values)) return;
    // The edited values decide again which voxels are inside and active.
    out.inside = 0;
    out.any = false;
    out.block.active.assign(kBlockVoxels, 0);
    for (size_t i = 0; i < static_cast<size_t>(kBlockVoxels); ++i) store(out, i, out.block.values[i]);
  }

 private:
  void sample_part(const std::array<int, 3>& origin, BlockResult& out) {
    out = BlockResult{};
    out.block.origin = origin;
    // The planted fault: the skin read 1.5 voxels too shallow in one block of every five.
    const bool planted = plant_shallow_skin_ && (origin[0] + origin[1] + origin[2]) / kBlock % 5 == 0;
    skin_ = planted ? skin_given_ - 1.5 : skin_given_;
    // Deep inside the core the domain plays no part (d far below every threshold).
    const BlockPlace place = reader_->read_block(origin, margin_ + fillet_, d_.data());
    if (place == BlockPlace::Outside) return;  // (these voxels are not counted as skipped: outside the domain)
    if (place == BlockPlace::Deep) {
      d_.fill(-1e300);
      out.deep = true;
    }
    solid_.fill(0.0);
    out.block.values.assign(kBlockVoxels, background_);
    out.block.active.assign(kBlockVoxels, 0);
    // The whole block far from F = 0?
    double c[3];
    for (int a = 0; a < 3; ++a) c[a] = 0.5 * ((origin[a] + 0.5) * v_ + (origin[a] + kBlock - 0.5) * v_);
    const double radius = 0.5 * std::sqrt(3.0) * (kBlock - 1) * v_;
    if (const Far far = far_from_walls(c, radius); far != Far::No) {
      out.skipped_voxels = kBlockVoxels;
      if (far == Far::Inside) solid_.fill(1.0);
      tally(place, out);
      if (far == Far::Inside) {
        for (int i = 0; i < kBlockVoxels; ++i) store(out, static_cast<size_t>(i), inside_walls(d_[i]));
      } else if (skin_ > 0 && place == BlockPlace::Mixed) {
        for (int i = 0; i < kBlockVoxels; ++i) store(out, static_cast<size_t>(i), without_wall(d_[i]));
      }
      return;
    }
    x_.clear();
    y_.clear();
    z_.clear();
    dq_.clear();
    slot_.clear();
    // Sub-blocks of 4^3 voxels: one F value at the centre rules out 64 voxels far from the walls.
    constexpr int kSub = kBlock / 2;
    const double sub_radius = 0.5 * std::sqrt(3.0) * (kSub - 1) * v_;
    for (int si = 0; si < kBlock; si += kSub)
      for (int sj = 0; sj < kBlock; sj += kSub)
        for (int sl = 0; sl < kBlock; sl += kSub) {
          const double sc[3] = {(origin[0] + si + 0.5 * kSub) * v_, (origin[1] + sj + 0.5 * kSub) * v_,
                                (origin[2] + sl + 0.5 * kSub) * v_};
          const Far far = far_from_walls(sc, sub_radius);
          if (far != Far::No) out.skipped_voxels += kSub * kSub * kSub;
          for (int i = si; i < si + kSub; ++i)
            for (int j = sj; j < sj + kSub; ++j)
              for (int l = sl; l < sl + kSub; ++l) {
                const int slot = block_offset(i, j, l);
                const double d = d_[static_cast<size_t>(slot)];
                if (far == Far::Inside) {
                  solid_[static_cast<size_t>(slot)] = 1.0;
                  store(out, static_cast<size_t>(slot), inside_walls(d));
                  continue;
                }
                if (far == Far::Outside || !wall_matters(d, skin_, fillet_, margin_)) {
                  if (skin_ > 0) store(out, static_cast<size_t>(slot), without_wall(d));
                  continue;
                }
                x_.push_back((origin[0] + i + 0.5) * v_);
                y_.push_back((origin[1] + j + 0.5) * v_);
                z_.push_back((origin[2] + l + 0.5) * v_);
                dq_.push_back(d);
                slot_.push_back(slot);
              }
        }
    const size_t n = x_.size();
    out.wall_samples = n;
    w_.resize(n);
    if (n > 0) field_.walls(n, x_.data(), y_.data(), z_.data(), w_.data(), worker_);
    for (size_t s = 0; s < n; ++s) {
      solid_[static_cast<size_t>(slot_[s])] = std::clamp(0.5 - w_[s] / v_, 0.0, 1.0);
      store(out, static_cast<size_t>(slot_[s]), part_value(dq_[s], w_[s] / v_, skin_, fillet_));
    }
    tally(place, out);
  }

  using Far = wall::FieldBound::Far;
  Far far_from_walls(const double* centre, double radius) const { return bound_.far_from_walls(centre, radius); }
  double without_wall(double d) const { return part_value_without_wall(d, skin_, kActiveBand, background_); }
  // The part where the lattice is solid throughout (deep inside a network's struts).
  double inside_walls(double d) const { return part_value(d, -kFarFromWalls, skin_, fillet_); }

  // Only voxels near the surface are active: OpenVDB looks for crossings around active voxels and
  // reads the stored values of inactive ones. |grad w| stays near 1 (w = phi / (k M), and |grad phi|
  // <= k M (1 + O(|h| H / M))), and so does the domain's, so |value| >= 2 leaves every edge to a
  // neighbour on one side. (The plain 4x4x4 gyroid mesh came out byte-identical with all evaluated
  // voxels active.)
  void store(BlockResult& out, size_t slot, double value_in_voxels) const {
    auto value = static_cast<float>(value_in_voxels);
    if (std::abs(value) < kLeastMagnitude) value = value < 0 ? -kLeastMagnitude : kLeastMagnitude;
    out.block.values[slot] = std::clamp(value, -background_, background_);
    if (value < 0) ++out.inside;
    if (std::abs(value) < kActiveBand) {
      out.block.active[slot] = 1;
      out.any = true;
    }
  }

  // The block's share of the body's and the core's volumes, and of the lattice in the core: voxel by
  // voxel, a voxel at signed distance d (voxels) being min(max(1/2 - d, 0), 1) inside.
  void tally(BlockPlace place, BlockResult& out) const {
    VoxelTally& t = out.tally;
    const double core_shift = skin_ > 0 ? skin_ : 0;
    for (size_t i = 0; i < static_cast<size_t>(kBlockVoxels); ++i) {
      const double d = d_[i];
      t.body += std::clamp(0.5 - d, 0.0, 1.0);
      t.core += std::clamp(0.5 - (d + core_shift), 0.0, 1.0);
      if (place == BlockPlace::Deep || d + core_shift < 0) {
        ++t.core_voxels;
        t.core_solid_voxels += solid_[i];
      }
    }
  }

  const wall::WallField& field_;
  wall::WallField::Worker worker_;
  std::unique_ptr<DomainReader> reader_;
  float background_;
  double v_ = 0, fillet_ = 0;
  wall::FieldBound bound_;
  double skin_given_ = 0, skin_ = 0, margin_ = 0;
  bool plant_shallow_skin_ = false, plant_dropped_blocks_ = false;
  const PartEdits* edits_ = nullptr;
  std::array<double, kBlockVoxels> d_{};
  // How much of each voxel the lattice alone fills, min(max(1/2 - w, 0), 1) with w in voxels (as the
  // body's share): a voxel count of w < 0 would alias with the cells when voxels divide them evenly.
  std::array<double, kBlockVoxels> solid_{};
  std::vector<double> x_, y_, z_, dq_, w_;
  std::vector<int> slot_;
};

}  // namespace

SampledBand sample_band(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
                        bool use_field_bound, int threads, const std::function<void(double)>& progress) {
  return sample_band(field, domain, grid, reach, use_field_bound, threads, progress, domain.block_range(),
                     domain.block_range());
}

SampledBand sample_band(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
                        bool use_field_bound, int threads, const std::function<void(double)>& progress,
                        const VoxelBox& blocks, const VoxelBox& owned) {
  SampledBand band;
  std::vector<std::array<int, 3>> origins;
  const auto& [first, last] = blocks;
  for (int i = first[0]; i < last[0]; i += kBlock)
    for (int j = first[1]; j < last[1]; j += kBlock)
      for (int l = first[2]; l < last[2]; l += kBlock) origins.push_back({i, j, l});
  band.blocks_tested = origins.size();

  std::vector<BlockResult> results(origins.size());
  std::atomic<bool> drop_solid{false};
  wall::for_each_block(
      origins.size(), threads, progress,
      [&] {
        auto sampler = std::make_unique<BlockSampler>(field, domain, grid, reach, use_field_bound, band.background);
        if (sampler->drops_solid_blocks()) drop_solid = true;
        return sampler;
      },
      [&](std::unique_ptr<BlockSampler>& sampler, size_t b) { sampler->sample(origins[b], results[b]); });

  // In block order, so the grid (and the mesh) do not depend on the threads' schedule.
  for (size_t b = 0; b < origins.size(); ++b) {
    band.wall_samples += results[b].wall_samples;
    band.skipped_voxels += results[b].skipped_voxels;
    band.deep_blocks += results[b].deep ? 1 : 0;
    bool in_owned = true;
    for (size_t a = 0; a < 3; ++a) in_owned = in_owned && origins[b][a] >= owned[0][a] && origins[b][a] < owned[1][a];
    if (in_owned) band.tally += results[b].tally;
    if (results[b].any) {
      band.blocks.push_back(std::move(results[b].block));
    } else if (results[b].solid() && !drop_solid) {
      BandBlock solid;
      solid.origin = results[b].block.origin;
      solid.solid = true;
      band.blocks.push_back(std::move(solid));
    }
  }
  return band;
}

}  // namespace offsetgen::mesh
