// `offsetgen mesh`: a block of cells of a wall solid as a closed, outward-oriented triangle mesh in
// millimetres. Stages: generate + compile the header (wall_field), sample a narrow band
// (narrow_band), extract with OpenVDB (vdb_surface), keep the large pieces (triangle_mesh), write
// the file atomically (mesh_files).
#pragma once

#include "mesh/mesh_files.h"
#include "mesh/triangle_mesh.h"
#include "mesh/wall_field.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::mesh {

struct MeshSettings {
  WallRequest wall;
  std::array<int, 3> cells{1, 1, 1};
  double cell_size = 10;    // mm
  int resolution = 0;       // voxels per cell; 0 picks automatic_resolution()
  double adaptivity = 0;    // OpenVDB volumeToMesh adaptivity, [0, 1]
  double min_piece = 0.01;  // pieces below this fraction of the largest piece's volume are dropped
  std::string output;
  int threads = 0;  // 0: one per hardware thread
};

inline constexpr int kMinVoxelsPerWall = 2;  // thinner walls are refused
// The automatic resolution: the thinnest wall spans 4 voxels, and the block's longest side at least
// 128, since the faces where the box cuts the walls lose O(voxel^2) of volume along every cut edge.
inline constexpr int kDefaultVoxelsPerWall = 4;
inline constexpr int kDefaultBlockVoxels = 128;
inline constexpr double kMaxVoxels = 4.0e9;  // the padded block, a guard against typos

struct StageTime {
  std::string name;
  double seconds = 0;
};

struct MeshSummary {
  std::string output;
  MeshFormat format = MeshFormat::Stl;
  std::array<int, 3> cells{};
  double cell_size = 0;
  int resolution = 0;
  bool automatic_resolution = false;
  double min_thickness = 0, max_thickness = 0;  // cell units
  size_t wall_samples = 0, skipped_voxels = 0;
  bool field_bound_used = true;   // blocks ruled out by F (narrow_band.h)
  double samples_per_second = 0;  // wall samples (each two _offset values) per second of the sample stage
  size_t points = 0, triangles = 0, file_bytes = 0;
  double volume = 0, box_volume = 0;  // mm^3
  std::optional<double> requested_density;  // --density R
  PieceReport pieces;
  std::string compile_flags;
  std::vector<StageTime> stages;
};

// Called with a stage name and a fraction in [0, 1] (negative: no fraction known).
using ProgressCallback = std::function<void(const std::string& stage, double fraction)>;

int automatic_resolution(const std::array<int, 3>& cells, double min_thickness);

// Throws InputError for bad settings before any file is touched.
MeshSummary run_mesh(const MeshSettings& settings, const ProgressCallback& progress);

std::string format_summary(const MeshSummary& summary);

}  // namespace offsetgen::mesh
