#include "mesh/void_stage.h"

#include "support/stopwatch.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

namespace offsetgen::mesh {

VoidStage::VoidStage(const DrainRequest& request, const VoxelBox& range, double voxel_mm, bool partial)
    : request_(request), voxel_(voxel_mm) {
  summary_.up = request.up;
  summary_.fill_below = request.fill_below;
  double voxels = 1;
  for (size_t a = 0; a < 3; ++a) voxels *= double(range[1][a] - range[0][a]);
  if (partial) {
    summary_.not_analysed = "a --tile-range share sees part of the body";
  } else if (voxels > kMaxVoidVoxels) {
    summary_.not_analysed = fmt::format("{:.3g} voxels, above {:.3g}: use a larger --voxel", voxels, kMaxVoidVoxels);
  } else {
    bits_ = VoxelBits(range, true);
  }
}

void VoidStage::plan(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
                     bool use_field_bound, int threads, const std::vector<Tile>& tiles, const body::BodyMesh& body,
                     const VoxelFrame& frame, const std::function<void(double)>& progress) {
  if (bits_.count() == 0)
    throw InputError("--drain and --fill-pockets need the enclosed voids, which are not analysed here: " +
                     summary_.not_analysed);
  const auto start = std::chrono::steady_clock::now();
  for (size_t t = 0; t < tiles.size(); ++t) {
    const SampledBand band = sample_band(
        field, domain, grid, reach, use_field_bound, threads,
        [&](double f) { progress((double(t) + f) / double(tiles.size())); }, tiles[t].blocks, tiles[t].owned);
    record_material(band, bits_);
  }
  // The flood clears the bits it reaches: pockets to fill are found in the bits as recorded.
  std::optional<VoxelBits> recorded;
  if (request_.fill_below > 0) recorded = bits_;
  VoidReport before = find_enclosed_voids(bits_, voxel_);
  refine_small_regions(before, [&](const VoxelBox& blocks) {
    return sample_band(
        field, domain, grid, reach, use_field_bound, 1, [](double) {}, blocks, blocks);
  });
  if (recorded) {
    filled_ = pockets_to_fill(*recorded, before, request_.fill_below, summary_.filled_volume);
    recorded.reset();
    for (const VoidRegion& r : before.regions) summary_.filled_regions += r.volume < request_.fill_below ? 1 : 0;
    edits_.filled = &filled_;
  }
  // At the most: the void, its copy and the copy flooded, and the pockets' bits.
  summary_.bytes = before.bytes * (request_.fill_below > 0 ? 4 : 1);
  summary_.holes = plan_drain_holes(before, body, frame, request_);
  edits_.holes = holes_in_voxels(summary_.holes, frame);
  summary_.before = before;
  bits_ = VoxelBits(bits_.box(), true);  // for the mesh pass
  summary_.first_pass_seconds = seconds_since(start);
}

void VoidStage::record(const SampledBand& band) {
  if (bits_.count() == 0) return;
  const auto start = std::chrono::steady_clock::now();
  record_material(band, bits_);
  record_seconds_ += seconds_since(start);
}

VoidSummary VoidStage::finish(const BandSampler& sample) {
  if (bits_.count() == 0) return summary_;
  summary_.after = find_enclosed_voids(bits_, voxel_);
  refine_small_regions(summary_.after, sample);
  summary_.analysed = true;
  summary_.bytes = std::max(summary_.bytes, summary_.after.bytes + filled_.memory_bytes());  // the pockets' kept
  bits_ = VoxelBits();
  return summary_;
}

std::vector<double> VoidStage::away_from_holes(const std::vector<std::array<float, 3>>& points_mm,
                                               const std::vector<double>& depths, const VoxelFrame& frame) const {
  if (edits_.holes.empty()) return depths;
  // Two voxels clear of the hole's wall: the mesh's vertices there lie on the wall within a voxel.
  constexpr double kClear = 2.0;
  std::vector<double> kept;
  kept.reserve(depths.size());
  for (size_t i = 0; i < points_mm.size(); ++i) {
    wall::Point3 p{};
    for (size_t a = 0; a < 3; ++a) p[a] = (double(points_mm[i][a]) - frame.origin[a]) / frame.voxel - 0.5;
    if (wall::hole_distance(edits_.holes, p) > kClear) kept.push_back(depths[i]);
  }
  return kept;
}

namespace {

// The count and volume of the regions of kDrainRegionMm3 or more, the largest few listed, and of the rest.
std::string regions_text(const VoidReport& r) {
  std::vector<double> large;
  for (const VoidRegion& region : r.regions)
    if (region.volume >= kDrainRegionMm3) large.push_back(region.volume);
  std::sort(large.rbegin(), large.rend());
  constexpr size_t kListed = 8;
  std::string list;
  for (size_t i = 0; i < std::min(large.size(), kListed); ++i)
    list += fmt::format("{}{:.1f}", i ? ", " : ": ", large[i]);
  if (large.size() > kListed) list += ", ...";
  return fmt::format("{} of {:g} mm^3 or more ({:.1f} mm^3{}), {} smaller ({:.2f} mm^3)", r.large, kDrainRegionMm3,
                     r.large_volume, list, r.regions.size() - r.large, r.total - r.large_volume);
}

}  // namespace

std::string format_voids(const VoidSummary& v) {
  if (!v.analysed) return fmt::format("  voids: not analysed ({})\n", v.not_analysed);
  const VoidReport& r = v.after;
  // The one line scripts read: the part as written.
  std::string s = fmt::format("  voids: {} enclosed regions, {:.1f} mm^3 trapped (largest {:.1f} mm^3)\n",
                              r.regions.size(), r.total, r.largest);
  s += fmt::format("              {}; flood fill on the {:.4g} mm voxels, {:.2f} s, {:.1f} MB of bits\n",
                   regions_text(r), r.voxel, r.seconds, double(v.bytes) / 1e6);
  if (v.before) {
    const VoidReport& b = *v.before;
    s += fmt::format(
        "              before the edits: {} regions closed in, {:.1f} mm^3 (largest {:.1f} mm^3), {}; planned "
        "on a first pass in {:.2f} s\n",
        b.regions.size(), b.total, b.largest, regions_text(b), v.first_pass_seconds);
  }
  if (v.fill_below > 0)
    s += fmt::format("  pockets:    {} enclosed regions under {:g} mm^3 filled solid, {:.2f} mm^3 added\n",
                     v.filled_regions, v.fill_below, v.filled_volume);
  if (!v.holes.empty()) {
    static const char* const kAxis[] = {"X", "Y", "Z"};
    const bool by_hand = v.holes.front().role == "by hand";
    s += fmt::format(
        "  drain:      {} holes of {:g} mm ({}), each from inside the void out through the nearest point of the "
        "surface\n",
        v.holes.size(), v.holes.front().diameter,
        by_hand ? std::string("placed by hand, --drain-at")
                : fmt::format("drain: the lowest voxel of a region along {}, air: its highest", kAxis[v.up]));
    for (const PlannedHole& h : v.holes)
      s += fmt::format(
          "              {:<7} at ({:.3f}, {:.3f}, {:.3f}) mm, out along ({:.4f}, {:.4f}, {:.4f}), "
          "{:.3f} mm long, diameter {:g} mm\n",
          h.role, h.at[0], h.at[1], h.at[2], h.direction[0], h.direction[1], h.direction[2], h.length, h.diameter);
  }
  return s;
}

}  // namespace offsetgen::mesh
