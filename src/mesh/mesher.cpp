#include "mesh/mesher.h"

#include "emit/file_writer.h"
#include "mesh/narrow_band.h"
#include "mesh/vdb_surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace offsetgen::mesh {
namespace {

class StageClock {
 public:
  explicit StageClock(std::vector<StageTime>& stages) : stages_(stages) {}
  void done(const std::string& name) {
    const auto now = std::chrono::steady_clock::now();
    stages_.push_back({name, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<StageTime>& stages_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void validate(const MeshSettings& s) {
  for (int n : s.cells)
    if (n < 1) throw InputError(fmt::format("--cells: {} is not a positive number of cells", n));
  if (!(s.cell_size > 0) || !std::isfinite(s.cell_size))
    throw InputError(fmt::format("--cell-size {} is not a positive length (mm)", s.cell_size));
  if (s.resolution < 0) throw InputError(fmt::format("--resolution {} is not a positive voxel count", s.resolution));
  if (!(s.adaptivity >= 0 && s.adaptivity <= 1))
    throw InputError(fmt::format("--adaptivity {} is outside [0, 1]", s.adaptivity));
  if (!(s.min_piece >= 0 && s.min_piece < 1))
    throw InputError(fmt::format("--min-piece {} is outside [0, 1)", s.min_piece));
  if (s.output.empty()) throw InputError("no output file: use -o part.stl (or .ply)");
}

// What sets the wall: "t=0.1", "rho=0.2" or "rho=<expression>".
std::string wall_text(const MeshSettings& s) {
  const GenerationRequest& g = s.wall.generation;
  if (g.density) return fmt::format("rho={}", *g.density);
  if (g.density_field) return "rho=" + *g.density_field;
  return "t=" + s.wall.thickness;
}

std::string description(const MeshSettings& s, const MeshSummary& m, const std::string& surface) {
  return fmt::format("offsetgen mesh {} {} {}x{}x{} cells of {} mm, {} voxels/cell", surface, wall_text(s),
                     m.cells[0], m.cells[1], m.cells[2], m.cell_size, m.resolution);
}

}  // namespace

int automatic_resolution(const std::array<int, 3>& cells, double min_thickness) {
  const int per_wall = static_cast<int>(std::ceil(kDefaultVoxelsPerWall / min_thickness - 1e-9));
  const int largest = *std::max_element(cells.begin(), cells.end());
  const int per_block = (kDefaultBlockVoxels + largest - 1) / largest;
  return std::max(per_wall, per_block);
}

MeshSummary run_mesh(const MeshSettings& s, const ProgressCallback& progress) {
  validate(s);
  MeshSummary m;
  m.output = s.output;
  m.format = format_for_path(s.output);
  m.cells = s.cells;
  m.cell_size = s.cell_size;
  try {
    require_writable(s.output);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }

  progress("generating the functions", -1);
  WallField field(s.wall);
  m.stages.push_back({"generate", field.generate_seconds()});

  const auto range = field.thickness_range(s.cells);
  m.min_thickness = range[0];
  m.max_thickness = range[1];
  m.automatic_resolution = s.resolution == 0;
  m.resolution = m.automatic_resolution ? automatic_resolution(s.cells, m.min_thickness) : s.resolution;
  if (m.min_thickness * m.resolution < kMinVoxelsPerWall)
    throw InputError(fmt::format(
        "the thinnest wall ({:.4g} cell) spans {:.3g} voxels at --resolution {}: walls need at least {} voxels; "
        "use --resolution {} or more (the default gives {})",
        m.min_thickness, m.min_thickness * m.resolution, m.resolution, kMinVoxelsPerWall,
        static_cast<int>(std::ceil(kMinVoxelsPerWall / m.min_thickness)), kDefaultVoxelsPerWall));
  double voxels = 1;
  for (int n : s.cells) voxels *= double(n) * m.resolution + 4;
  if (voxels > kMaxVoxels)
    throw InputError(
        fmt::format("{}x{}x{} cells at {} voxels per cell is {:.3g} voxels, above the limit of {:.3g}; "
                    "lower --resolution or --cells",
                    s.cells[0], s.cells[1], s.cells[2], m.resolution, voxels, kMaxVoxels));

  progress("compiling the functions", -1);
  field.compile();
  m.stages.push_back({"compile", field.compile_seconds()});
  m.compile_flags = field.compile_flags();
  StageClock clock(m.stages);

  VoxelGrid grid;
  grid.cells = s.cells;
  grid.resolution = m.resolution;
  const int threads = s.threads > 0 ? s.threads : std::max(1u, std::thread::hardware_concurrency());
  const auto sample_start = std::chrono::steady_clock::now();
  // M bounds |grad F| over the unit cell; catalog surfaces repeat it, user expressions need not.
  const bool single_cell = s.cells == std::array<int, 3>{1, 1, 1};
  m.field_bound_used = field.generation().surface.from_catalog || single_cell;
  SampledBand band = sample_band(field, grid, m.max_thickness, m.field_bound_used, threads,
                                 [&](double fraction) { progress("sampling the narrow band", fraction); });
  const double sample_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sample_start).count();
  m.wall_samples = band.wall_samples;
  m.skipped_voxels = band.skipped_voxels;
  m.samples_per_second = sample_seconds > 0 ? double(band.wall_samples) / sample_seconds : 0;
  clock.done("sample");

  progress("extracting the surface (OpenVDB)", -1);
  TriangleMesh mesh = extract_surface(band, s.adaptivity);
  band = SampledBand{};
  // Voxel i sits at (i + 0.5) voxels, in millimetres.
  const double mm = s.cell_size * grid.voxel();
  for (auto& p : mesh.points)
    for (float& x : p) x = static_cast<float>((double(x) + 0.5) * mm);
  clock.done("extract");

  progress("orienting and sorting pieces", -1);
  m.pieces = keep_large_pieces(mesh, s.min_piece);
  if (mesh.triangles.empty())
    throw InputError("the block holds no wall: the surface does not cross it, or the walls fall between the voxels");
  m.points = mesh.points.size();
  m.triangles = mesh.triangles.size();
  m.volume = m.pieces.volume;
  m.box_volume = double(s.cells[0]) * s.cells[1] * s.cells[2] * std::pow(s.cell_size, 3);
  m.requested_density = s.wall.generation.density;
  clock.done("pieces");

  progress("writing " + s.output, -1);
  const std::string bytes = encode_mesh(mesh, m.format, description(s, m, field.generation().surface.name));
  m.file_bytes = bytes.size();
  write_file(s.output, bytes);
  clock.done("write");
  return m;
}

std::string format_summary(const MeshSummary& m) {
  std::string s;
  double total = 0;
  std::string stages;
  for (const auto& st : m.stages) {
    total += st.seconds;
    stages += fmt::format("{}{} {:.2f} s", stages.empty() ? "" : ", ", st.name, st.seconds);
  }
  s += fmt::format("offsetgen mesh: {} written ({}, {:.1f} MB)\n", m.output, format_name(m.format),
                   static_cast<double>(m.file_bytes) / 1e6);
  s += fmt::format("  block:      {}x{}x{} cells of {:g} mm, {} voxels per cell{}, wall {:.4g}{} cell\n", m.cells[0],
                   m.cells[1], m.cells[2], m.cell_size, m.resolution, m.automatic_resolution ? " (automatic)" : "",
                   m.min_thickness,
                   m.max_thickness != m.min_thickness ? fmt::format(" to {:.4g}", m.max_thickness) : std::string());
  s += fmt::format("  mesh:       {} triangles, {} vertices\n", m.triangles, m.points);
  s += fmt::format("  volume:     {:.6g} mm^3, relative density {:.4f} (box {:.6g} mm^3{})\n", m.volume,
                   m.volume / m.box_volume, m.box_volume,
                   m.requested_density ? fmt::format("; --density {}", *m.requested_density) : std::string());
  s += fmt::format("  pieces:     {} kept, {} dropped below the volume threshold ({:.3g} mm^3){}\n", m.pieces.kept,
                   m.pieces.dropped, m.pieces.dropped_volume,
                   m.pieces.cavities ? fmt::format(", {} closed cavities", m.pieces.cavities) : std::string());
  s += fmt::format(
      "  evaluation: {} wall samples, {:.3g} samples/s (two <prefix>_offset_n values each, {}); "
      "voxels ruled out by F: {}\n",
      m.wall_samples, m.samples_per_second, m.compile_flags,
      m.field_bound_used ? std::to_string(m.skipped_voxels)
                         : std::string("none (M bounds |grad F| over one cell, and this expression spans several)"));
  s += fmt::format("  time:       {:.2f} s ({})\n", total, stages);
  return s;
}

}  // namespace offsetgen::mesh
