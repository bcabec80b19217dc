// The enclosed voids of a body's part (issue 43), found on the level set: the sampled bands of the
// tiles are recorded into part-wide void bits as they are meshed, and flood-filled once all are in
// (void_regions.h). With --drain or --fill-pockets a first pass samples the part without meshing it,
// plans the holes and the pockets to fill (drain_plan.h), and the mesh pass cuts them (part_edits.h)
// and records the part again: the report gives the voids before and after.
#pragma once

#include "mesh/drain_plan.h"
#include "mesh/part_edits.h"
#include "mesh/tiles.h"
#include "mesh/void_regions.h"
#include "mesh/voxel_bits.h"
#include "wall/wall_field.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::mesh {

// Past this many voxels a bit grid would hold more than 1 GB: the voids are not analysed.
inline constexpr double kMaxVoidVoxels = 8.0e9;

struct VoidSummary {
  bool analysed = false;
  std::string not_analysed;          // why not, when not
  VoidReport after;                  // the part as written
  std::optional<VoidReport> before;  // with --drain or --fill-pockets: before the edits
  std::vector<PlannedHole> holes;
  int up = 2;
  double fill_below = 0;  // --fill-pockets V
  size_t filled_regions = 0;
  double filled_volume = 0;       // mm^3 made solid
  double first_pass_seconds = 0;  // sampling the part once more to plan the edits
  size_t bytes = 0;               // the bit grids held at once, at their most (one bit a voxel each)
};

class VoidStage {
 public:
  // `range`: the domain's voxel box; `partial`: a --tile-range share, which cannot see the whole part.
  VoidStage(const DrainRequest& request, const VoxelBox& range, double voxel_mm, bool partial);

  bool plans_edits() const { return request_.any(); }
  // Samples every tile (no meshing) and plans the holes and fills; then edits() holds them.
  void plan(const wall::WallField& field, const Domain& domain, const VoxelGrid& grid, double reach,
            bool use_field_bound, int threads, const std::vector<Tile>& tiles, const body::BodyMesh& body,
            const VoxelFrame& frame, const std::function<void(double)>& progress);
  const PartEdits& edits() const { return edits_; }
  double first_pass_seconds() const { return summary_.first_pass_seconds; }
  double record_seconds() const { return record_seconds_; }

  // The mesh pass: each tile's band, as it is sampled (with the edits cut).
  void record(const SampledBand& band);
  // Labels the recorded part; `sample` samples it again where regions near 1 mm^3 are re-measured.
  VoidSummary finish(const BandSampler& sample);

  // The depths of the points (mm) that lie away from every hole's wall: near one, the hole's wall is
  // not skin (skin_measure.h).
  std::vector<double> away_from_holes(const std::vector<std::array<float, 3>>& points_mm,
                                      const std::vector<double>& depths, const VoxelFrame& frame) const;

 private:
  DrainRequest request_;
  double voxel_ = 0;
  VoidSummary summary_;
  VoxelBits bits_;
  VoxelBits filled_;
  PartEdits edits_;
  double record_seconds_ = 0;
};

std::string format_voids(const VoidSummary& voids);

}  // namespace offsetgen::mesh
