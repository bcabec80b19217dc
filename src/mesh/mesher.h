// `offsetgen mesh`: a block of cells of a wall solid, or a body filled with it inside a skin, as a
// closed, outward-oriented triangle mesh in millimetres. Stages: generate + compile the header
// (wall_field), read the body and index its facets (body/, body_domain), sample a narrow band
// (narrow_band), extract with OpenVDB (vdb_surface), keep the large pieces (triangle_mesh), measure
// the skin (skin_measure), write the file atomically (mesh_files).
#pragma once

#include "body/body_request.h"
#include "mesh/mesh_audit.h"
#include "mesh/mesh_files.h"
#include "mesh/narrow_band.h"
#include "mesh/skin_measure.h"
#include "mesh/triangle_mesh.h"
#include "mesh/void_stage.h"
#include "wall/wall_field.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace offsetgen::mesh {

// A part to fill instead of a block (docs/parts.md).
using body::BodyRequest;

struct MeshRequest {
  wall::WallRequest wall;
  std::array<int, 3> cells{1, 1, 1};
  std::optional<BodyRequest> body;  // instead of cells
  double cell_size = 10;            // mm
  int resolution = 0;               // voxels per cell; 0 picks automatic_resolution()
  double voxel = 0;                 // mm, instead of resolution (with a body it need not divide the cell)
  double adaptivity = 0;            // OpenVDB volumeToMesh adaptivity, [0, 1]
  double min_piece = 0.01;          // pieces below this fraction of the largest piece's volume are dropped
  int tile = 256;                   // voxels per tile side (a multiple of 8); 0: one tile (tiles.h)
  std::optional<std::pair<int, int>> tile_range;  // --tile-range I/N: share I of N, a partial STL
  std::string output;
  int threads = 0;     // 0: one per hardware thread
  DrainRequest drain;  // --drain, --drain-at, --up, --fill-pockets (with a body)
};

inline constexpr int kMinVoxelsPerWall = 2;  // thinner walls are refused
// The automatic resolution: the thinnest wall spans 4 voxels, and the block's longest side at least
// 128, since the faces where the box cuts the walls lose O(voxel^2) of volume along every cut edge.
inline constexpr int kDefaultVoxelsPerWall = 4;
inline constexpr int kDefaultBlockVoxels = 128;
inline constexpr double kMaxVoxels = 4.0e9;  // the padded block, a guard against typos
// A body's box: memory no longer grows with it (body_distance.h), only the time; a guard against typos.
inline constexpr double kMaxBodyVoxels = 1.0e12;
// Without tiles (PLY, 3MF, or --tile 0) every sample and triangle is held at once: a guard.
inline constexpr double kMaxHeldVoxels = 4.0e9;

struct StageTime {
  std::string name;
  double seconds = 0;
};

struct BodySummary {
  std::string path;
  size_t triangles = 0;
  std::string repaired;                             // what --repair did; empty without it
  std::array<std::array<double, 3>, 2> box{};       // mm, after --scale
  std::array<std::array<double, 3>, 2> part_box{};  // of the written mesh
  std::array<double, 3> origin{};                   // the lattice's origin, mm
  double voxel = 0;                                 // mm
  double skin = 0, fillet = 0;                      // mm, as requested
  double volume = 0;                                // of the body's mesh, mm^3
  double level_set_volume = 0;                      // counted on the voxels: the error of the two below
  double core_volume = 0, skin_volume = 0;
  size_t index_bytes = 0, deep_blocks = 0;
  std::optional<double> expected_density;  // --density, or the sheet density of a uniform --thickness
  SkinReport measured_skin;
  VoidSummary voids;  // enclosed voids, before and after --drain and --fill-pockets
};

struct MeshSummary {
  std::string output;
  std::optional<BodySummary> body;
  std::string map;  // a mapped lattice's formula, and what was decided about its singular set
  std::string map_region;
  size_t tiles = 1, tiles_meshed = 1;  // tiles of the domain, and those this run meshed (--tile-range)
  int tile_size = 0;                   // voxels a side
  bool streamed = false;               // STL or PLY written tile by tile; else the mesh was held whole
  std::optional<std::pair<int, int>> tile_range;
  double inner_dropped_volume = 0;  // streamed: small pieces inside one tile, dropped (mm^3)
  int inner_dropped = 0;
  MeshFormat format = MeshFormat::Stl;
  std::array<int, 3> cells{};
  double cell_size = 0;
  int resolution = 0;
  bool automatic_resolution = false;
  double min_thickness = 0, max_thickness = 0;  // cell units: the wall's thickness, or the network's offset h
  bool network = false;
  wall::WallExtent extent;  // what the voxels and the F bound were sized by
  size_t wall_samples = 0, skipped_voxels = 0;
  bool field_bound_used = true;   // blocks ruled out by F (narrow_band.h)
  double samples_per_second = 0;  // wall samples (each two _offset values) per second of the sample stage
  size_t points = 0, triangles = 0, file_bytes = 0;
  double volume = 0, box_volume = 0;        // mm^3
  std::optional<double> requested_density;  // --density R
  PieceReport pieces;
  AuditReport audit;  // the mesh as written, judged before it is kept
  VoxelTally tally;   // volumes counted on the voxels (narrow_band.h)
  std::string compile_flags;
  std::vector<StageTime> stages;
};

// Called with a stage name and a fraction in [0, 1] (negative: no fraction known).
using ProgressCallback = std::function<void(const std::string& stage, double fraction)>;
// Called with a warning that does not stop the run (a body whose size suggests other units).
using WarningCallback = std::function<void(const std::string& message)>;

// Voxels per cell: the thinnest wall spans 4 voxels and the longest side of the block (or body,
// `longest` in cells) at least 128.
int automatic_resolution(double longest, double min_thickness);
int automatic_resolution(const std::array<int, 3>& cells, double min_thickness);

// Throws InputError for bad settings before any file is touched.
MeshSummary run_mesh(const MeshRequest& settings, const ProgressCallback& progress, const WarningCallback& warn = {});

std::string format_summary(const MeshSummary& summary);

}  // namespace offsetgen::mesh
