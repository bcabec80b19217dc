#include "mesh/mesher.h"

#include "body/body_request.h"
#include "emit/file_writer.h"
#include "mesh/body_domain.h"
#include "mesh/box_domain.h"
#include "mesh/mapped_region.h"
#include "mesh/mesh_audit.h"
#include "mesh/narrow_band.h"
#include "mesh/ply_stream.h"
#include "mesh/stl_stream.h"
#include "mesh/tiles.h"
#include "mesh/vdb_surface.h"
#include "support/stopwatch.h"
#include "validate/block_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
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

// --drain and its company apply to a body, analysed whole.
void validate_drain(const MeshRequest& s) {
  const DrainRequest& d = s.drain;
  if (!(d.diameter >= 0) || !std::isfinite(d.diameter))
    throw InputError(fmt::format("--drain {} is not a diameter (mm)", d.diameter));
  if (!(d.fill_below >= 0) || !std::isfinite(d.fill_below))
    throw InputError(fmt::format("--fill-pockets {} is not a volume (mm^3)", d.fill_below));
  if (!d.at.empty() && d.diameter <= 0) throw InputError("--drain-at needs the holes' diameter: --drain D (mm)");
  if (d.any() && !s.body)
    throw InputError("--drain and --fill-pockets act on a part's enclosed voids: they need --body");
  if (d.any() && s.tile_range)
    throw InputError("--drain and --fill-pockets plan over the whole part: not with --tile-range");
}

void validate(const MeshRequest& s) {
  check_block(s.cells, s.cell_size);
  if (s.resolution < 0) throw InputError(fmt::format("--resolution {} is not a positive voxel count", s.resolution));
  if (s.voxel != 0 && !positive_length(s.voxel))
    throw InputError(fmt::format("--voxel {} is not a positive length (mm)", s.voxel));
  if (s.voxel != 0 && s.resolution != 0) throw InputError("give --resolution or --voxel, not both");
  if (!(s.adaptivity >= 0 && s.adaptivity <= 1))
    throw InputError(fmt::format("--adaptivity {} is outside [0, 1]", s.adaptivity));
  if (!(s.min_piece >= 0 && s.min_piece < 1))
    throw InputError(fmt::format("--min-piece {} is outside [0, 1)", s.min_piece));
  if (s.output.empty()) throw InputError("no output file: use -o part.stl (or .ply, .3mf)");
  if (s.tile < 0 || s.tile % kBlock != 0)
    throw InputError(fmt::format("--tile {}: a tile is a multiple of {} voxels a side (0: one tile)", s.tile, kBlock));
  if (s.tile_range && format_for_path(s.output) != MeshFormat::Stl)
    throw InputError(fmt::format("--tile-range writes a partial binary STL: -o '{}' is not .stl", s.output));
  if (s.body) body::validate_body(*s.body, s.output);
  validate_drain(s);
}

// What sets the wall: "t=0.1", "rho=0.2" or "rho=<expression>".
std::string wall_text(const MeshRequest& s) {
  const GenerationRequest& g = s.wall.generation;
  if (s.wall.network) return g.density ? fmt::format("network rho={}", *g.density) : "network h=" + s.wall.thickness;
  if (g.density) return fmt::format("rho={}", *g.density);
  if (g.density_field) return "rho=" + *g.density_field;
  return "t=" + s.wall.thickness;
}

std::string description(const MeshRequest& s, const MeshSummary& m, const std::string& surface) {
  if (m.body)
    return fmt::format("offsetgen mesh {} {} in {}, skin {} mm, {} mm cells, voxel {:.4g} mm", surface, wall_text(s),
                       std::filesystem::path(m.body->path).filename().string(), m.body->skin, m.cell_size,
                       m.body->voxel);
  return fmt::format("offsetgen mesh {} {} {}x{}x{} cells of {} mm, {} voxels/cell", surface, wall_text(s), m.cells[0],
                     m.cells[1], m.cells[2], m.cell_size, m.resolution);
}

// `setting` is what set the voxels ("--resolution 24", "--voxel 0.2 mm"); `cell_size` in mm.
void check_wall_voxels(double min_thickness, double voxels_per_cell, const std::string& setting, double cell_size,
                       bool by_voxel, bool network) {
  if (min_thickness * voxels_per_cell >= kMinVoxelsPerWall) return;
  const std::string fix =
      by_voxel ? fmt::format("--voxel {:.3g} or less", min_thickness * cell_size / kMinVoxelsPerWall)
               : fmt::format("--resolution {} or more", static_cast<int>(std::ceil(kMinVoxelsPerWall / min_thickness)));
  throw InputError(fmt::format(
      "{} ({:.4g} cell) spans {:.3g} voxels at {}: {} need at least {} voxels; use {} (the default gives {})",
      network ? "the network's narrowest neck, about 2 (h_max - |h|)," : "the thinnest wall", min_thickness,
      min_thickness * voxels_per_cell, setting, network ? "necks" : "walls", kMinVoxelsPerWall, fix,
      kDefaultVoxelsPerWall));
}

std::array<std::array<double, 3>, 2> mesh_box(const TriangleMesh& mesh) {
  std::array<std::array<double, 3>, 2> box{};
  box[0].fill(HUGE_VAL);
  box[1].fill(-HUGE_VAL);
  for (const auto& p : mesh.points)
    for (size_t a = 0; a < 3; ++a) {
      box[0][a] = std::min(box[0][a], double(p[a]));
      box[1][a] = std::max(box[1][a], double(p[a]));
    }
  return box;
}

int threads_for(const MeshRequest& s) {
  return s.threads > 0 ? s.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// Each tile's triangles, in millimetres and facing outward, as they are produced.
using TileHook = std::function<void(const TriangleMesh&)>;
// Each tile's sampled band, before it is meshed.
using BandHook = std::function<void(const SampledBand&)>;

std::string tile_progress(size_t done, size_t total, double elapsed) {
  std::string s = fmt::format("tile {} of {}", done + 1, total);
  if (done > 0) {
    const double left = elapsed / double(done) * double(total - done);
    s += left >= 120 ? fmt::format(", about {:.0f} min left", left / 60) : fmt::format(", about {:.0f} s left", left);
  }
  return s;
}

// Points within reach of a face of tile `t` may be shared with the tile across it (`seam`);
// `outside_run`: that tile is not among those this run meshes, [run.first, run.second).
void mark_seams(const TriangleMesh& mesh, const std::vector<Tile>& tiles, size_t t, std::pair<size_t, size_t> run,
                std::vector<uint8_t>& seam, std::vector<uint8_t>& outside_run) {
  const Tile& tile = tiles[t];
  const auto across = tile_neighbours(tiles, t);
  seam.assign(mesh.points.size(), 0);
  outside_run.assign(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i)
    for (size_t a = 0; a < 3; ++a)
      for (size_t side = 0; side < 2; ++side) {
        if (std::abs(mesh.points[i][a] - float(tile.owned[side][a])) >= 1.5f) continue;
        seam[i] = 1;
        const long other = across[a][side];
        if (other >= 0 && (size_t(other) < run.first || size_t(other) >= run.second)) outside_run[i] = 1;
      }
}

// The body's and the core's volumes from the voxels' tally (a block's box is known exactly); a skin
// that leaves no core is bad input.
void record_volumes(const MeshRequest& s, MeshSummary& m) {
  if (!m.body) return;
  BodySummary& b = *m.body;
  const double voxel3 = std::pow(b.voxel, 3);
  b.level_set_volume = m.tally.body * voxel3;
  b.core_volume = m.tally.core * voxel3;
  b.skin_volume = b.level_set_volume - b.core_volume;
  m.box_volume = b.level_set_volume;
  if (!(b.core_volume > 0) && !s.tile_range)
    throw InputError(fmt::format(
        "--skin {:g} mm leaves no core inside the body: the body is nowhere thicker than twice the skin", b.skin));
}

// Refuses a part whose mesh is not a closed, consistently oriented surface without degenerate facets,
// or whose skin came out thinner than requested by more than a voxel: it is not kept.
void require_sound(const MeshRequest& s, const MeshSummary& m) {
  std::vector<std::string> faults;
  if (!m.audit.closed()) faults.push_back(m.audit.describe());
  if (m.body && m.body->skin > 0 && m.body->measured_skin.thinnest < m.body->skin - m.body->voxel)
    faults.push_back(fmt::format(
        "the thinnest skin measured is {:.4g} mm, below {:.4g} mm (--skin {:g} mm less one voxel of {:.4g} mm)",
        m.body->measured_skin.thinnest, m.body->skin - m.body->voxel, m.body->skin, m.body->voxel));
  if (faults.empty()) return;
  std::string list;
  for (const auto& f : faults) list += (list.empty() ? "" : "; ") + f;
  throw UnsoundPartError(fmt::format(
      "the part is not sound: {}. It was not written ({} is unchanged). A slicer would have to repair it; try "
      "another --voxel or --cell-size, and please report the command (it is a bug in offsetgen mesh)",
      list, s.output));
}

// Samples, extracts and sorts the part, tile by tile (tiles.h); points in millimetres through `to_mm`
// (voxel index -> mm). STL and PLY in tiles are streamed to s.output as tiles finish (memory: one
// tile); one tile, and 3MF, are held whole and returned, seams welded, small pieces dropped over the
// whole.
template <typename ToMm>
TriangleMesh mesh_part(const MeshRequest& s, const wall::WallField& field, const Domain& domain, const VoxelGrid& grid,
                       MeshSummary& m, const ProgressCallback& progress, const ToMm& to_mm, const TileHook& hook,
                       const std::string& description, const BandHook& band_hook = {}) {
  const std::vector<Tile> tiles = make_tiles(domain.block_range(), s.tile);
  m.tiles = tiles.size();
  m.tile_size = s.tile;
  m.tile_range = s.tile_range;
  auto [first, last] = s.tile_range ? tile_share(tiles.size(), s.tile_range->first, s.tile_range->second)
                                    : std::pair<size_t, size_t>{0, tiles.size()};
  m.tiles_meshed = last - first;
  m.streamed = m.format != MeshFormat::ThreeMf && (tiles.size() > 1 || s.tile_range);
  if (!m.streamed) {
    double voxels = 1;
    for (size_t a = 0; a < 3; ++a) voxels *= domain.block_range()[1][a] - domain.block_range()[0][a];
    if (voxels > kMaxHeldVoxels)
      throw InputError(
          fmt::format("{} voxels held at once ({} holds the whole mesh): write STL, which is meshed in "
                      "tiles, or use a larger --voxel",
                      voxels, format_name(m.format)));
  }
  std::optional<StlStream> stl;
  std::optional<PlyStream> ply;
  if (m.streamed && m.format == MeshFormat::Stl) stl.emplace(s.output, description);
  if (m.streamed && m.format == MeshFormat::Ply) ply.emplace(s.output, description);
  std::vector<uint8_t> on_seam, outside_run;
  MeshAudit audit;
  const double cell_voxels = std::pow(1.0 / grid.voxel(), 3);
  double sample_seconds = 0, extract_seconds = 0, write_seconds = 0, audit_seconds = 0;
  TriangleMesh held;
  const auto start = std::chrono::steady_clock::now();
  for (size_t t = first; t < last; ++t) {
    const Tile& tile = tiles[t];
    const std::string stage =
        tiles.size() > 1 ? tile_progress(t - first, last - first, seconds_since(start)) + ": " : std::string();
    auto step = std::chrono::steady_clock::now();
    SampledBand band =
        tiles.size() == 1
            ? sample_band(field, domain, grid, m.extent.reach, m.field_bound_used, threads_for(s),
                          [&](double f) { progress(stage + "sampling the narrow band", f); })
            : sample_band(
                  field, domain, grid, m.extent.reach, m.field_bound_used, threads_for(s),
                  [&](double f) { progress(stage + "sampling the narrow band", f); }, tile.blocks, tile.owned);
    sample_seconds += seconds_since(step);
    m.wall_samples += band.wall_samples;
    m.tally += band.tally;
    m.skipped_voxels += band.skipped_voxels;
    if (m.body) m.body->deep_blocks += band.deep_blocks;
    if (band_hook) band_hook(band);

    progress(stage + "extracting the surface (OpenVDB)", -1);
    step = std::chrono::steady_clock::now();
    TriangleMesh mesh =
        tiles.size() == 1 ? extract_surface(band, s.adaptivity) : extract_surface(band, s.adaptivity, tile.owned);
    band = SampledBand{};
    if (m.streamed) {
      flip(mesh);  // OpenVDB faces its polygons into the negative (inside) region
      // Debris inside this tile can be judged here; pieces that reach a seam are kept whole.
      std::array<std::array<float, 3>, 2> inner{};
      for (size_t a = 0; a < 3; ++a) {
        inner[0][a] = static_cast<float>(tile.owned[0][a] + 1);
        inner[1][a] = static_cast<float>(tile.owned[1][a] - 2);
      }
      const auto [dropped, volume] = drop_small_inner_pieces(mesh, inner, s.min_piece * cell_voxels);
      m.inner_dropped += dropped;
      m.inner_dropped_volume += volume * std::pow(s.cell_size * grid.voxel(), 3);
    }
    if (m.streamed) mark_seams(mesh, tiles, t, {first, last}, on_seam, outside_run);
    for (auto& p : mesh.points) p = to_mm(p);
    extract_seconds += seconds_since(step);
    if (m.streamed) {
      step = std::chrono::steady_clock::now();
      audit.add(mesh, on_seam, outside_run);
      audit_seconds += seconds_since(step);
    }
    if (!m.streamed) {
      const auto offset = static_cast<uint32_t>(held.points.size());
      held.points.insert(held.points.end(), mesh.points.begin(), mesh.points.end());
      for (auto tri : mesh.triangles) {
        for (uint32_t& i : tri) i += offset;
        held.triangles.push_back(tri);
      }
      continue;
    }
    hook(mesh);
    m.volume += signed_volume(mesh);
    m.triangles += mesh.triangles.size();
    m.points += mesh.points.size();
    step = std::chrono::steady_clock::now();
    if (stl) stl->append(mesh);
    if (ply) ply->append(mesh, on_seam);
    write_seconds += seconds_since(step);
  }
  m.samples_per_second = sample_seconds > 0 ? double(m.wall_samples) / sample_seconds : 0;
  m.stages.push_back({"sample", sample_seconds});
  m.stages.push_back({"extract", extract_seconds});
  if (m.streamed) {
    progress("writing " + s.output, -1);
    const auto step = std::chrono::steady_clock::now();
    if (m.triangles == 0 && !s.tile_range)
      throw InputError(m.body ? "the body holds no wall: the surface does not cross it, or the walls fall between "
                                "the voxels"
                              : "the block holds no wall: the surface does not cross it, or the walls fall "
                                "between the voxels");
    m.audit = audit.finish();
    m.stages.push_back({"check", audit_seconds});
    record_volumes(s, m);
    require_sound(s, m);
    if (stl) {
      stl->commit();
      m.file_bytes = stl->bytes();
    } else {
      m.points = ply->vertices();  // seams welded
      ply->commit();
      m.file_bytes = ply->bytes();
    }
    m.stages.push_back({"write", write_seconds + seconds_since(step)});
    return {};
  }

  progress("orienting and sorting pieces", -1);
  const auto step = std::chrono::steady_clock::now();
  if (tiles.size() > 1) weld_points(held);
  m.pieces = keep_large_pieces(held, s.min_piece);
  if (held.triangles.empty())
    throw InputError(m.body ? "the body holds no wall: the surface does not cross it, or the walls fall between the "
                              "voxels"
                            : "the block holds no wall: the surface does not cross it, or the walls fall between "
                              "the voxels");
  hook(held);
  const auto audit_start = std::chrono::steady_clock::now();
  audit.add(held);
  m.audit = audit.finish();
  m.stages.push_back({"check", seconds_since(audit_start)});
  record_volumes(s, m);
  require_sound(s, m);
  m.points = held.points.size();
  m.triangles = held.triangles.size();
  m.volume = m.pieces.volume;
  m.stages.push_back({"pieces", seconds_since(step)});
  return held;
}

// Writes a held mesh (a streamed one is written already).
void write_part(const MeshRequest& s, const TriangleMesh& mesh, MeshSummary& m, const std::string& description,
                const ProgressCallback& progress) {
  if (m.streamed) return;
  progress("writing " + s.output, -1);
  const auto start = std::chrono::steady_clock::now();
  const std::string bytes = encode_mesh(mesh, m.format, description);
  m.file_bytes = bytes.size();
  write_file(s.output, bytes);
  m.stages.push_back({"write", seconds_since(start)});
}

// The wall's thickness over the part (a block's cells or a body's box) and what the voxels are sized by.
void record_wall_range(const MeshRequest& s, const wall::WallField& field, const std::array<double, 2>& range,
                       MeshSummary& m) {
  m.min_thickness = range[0];
  m.max_thickness = range[1];
  m.extent = field.extent(range);
  m.network = s.wall.network;
  m.automatic_resolution = s.resolution == 0 && s.voxel == 0;
}

// Compiles and loads the wall's functions, once the request has passed the checks that need no compiler.
void compile_wall(wall::WallField& field, MeshSummary& m, const ProgressCallback& progress) {
  progress("compiling the functions", -1);
  field.compile();
  m.stages.push_back({"compile", field.compile_seconds()});
  m.compile_flags = field.compile_flags();
}

MeshSummary run_block(const MeshRequest& s, MeshSummary m, wall::WallField& field, const ProgressCallback& progress) {
  const auto range = field.thickness_range(s.cells);
  record_wall_range(s, field, range, m);
  if (s.voxel > 0) {
    const double per_cell = s.cell_size / s.voxel;
    if (std::abs(per_cell - std::round(per_cell)) > 1e-6 * per_cell)
      throw InputError(fmt::format(
          "--voxel {:g} mm does not divide the cell ({:g} mm) in a block: the block's faces must lie between "
          "voxels; use --resolution, or a voxel of {:g} mm / N",
          s.voxel, s.cell_size, s.cell_size));
    m.resolution = static_cast<int>(std::lround(per_cell));
  } else {
    m.resolution = m.automatic_resolution ? automatic_resolution(s.cells, m.extent.thinnest) : s.resolution;
  }
  check_wall_voxels(m.extent.thinnest, m.resolution, fmt::format("--resolution {}", m.resolution), s.cell_size,
                    s.voxel > 0, m.network);
  double voxels = 1;
  for (int n : s.cells) voxels *= double(n) * m.resolution + 4;
  if (voxels > kMaxVoxels)
    throw InputError(
        fmt::format("{}x{}x{} cells at {} voxels per cell is {:.3g} voxels, above the limit of {:.3g}; "
                    "lower --resolution or --cells",
                    s.cells[0], s.cells[1], s.cells[2], m.resolution, voxels, kMaxVoxels));

  compile_wall(field, m, progress);

  VoxelGrid grid;
  grid.resolution = m.resolution;
  // M bounds |grad F| over the unit cell; catalog surfaces repeat it, user expressions need not.
  const bool single_cell = s.cells == std::array<int, 3>{1, 1, 1};
  m.field_bound_used = field.generation().surface.from_catalog || single_cell;
  const BoxDomain domain(s.cells, grid.voxel());
  // Voxel i sits at (i + 0.5) voxels, in millimetres.
  const double mm = s.cell_size * grid.voxel();
  m.box_volume = double(s.cells[0]) * s.cells[1] * s.cells[2] * std::pow(s.cell_size, 3);
  m.requested_density = s.wall.generation.density;
  const std::string text = description(s, m, field.generation().surface.name);
  TriangleMesh mesh = mesh_part(
      s, field, domain, grid, m, progress,
      [mm](std::array<float, 3> p) {
        for (float& x : p) x = static_cast<float>((double(x) + 0.5) * mm);
        return p;
      },
      [](const TriangleMesh&) {}, text);
  write_part(s, mesh, m, text, progress);
  return m;
}

// --drain-at points must lie inside the body.
void check_drain_points(const DrainRequest& d, const BodyDomain& domain, int threads) {
  std::vector<std::array<float, 3>> points;
  for (const auto& p : d.at)
    points.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  const std::vector<double> depth = domain.distances(points, threads);
  for (size_t i = 0; i < points.size(); ++i)
    if (!(depth[i] < 0))
      throw InputError(fmt::format("--drain-at {:g},{:g},{:g} lies outside the body: a hole starts inside a void",
                                   d.at[i][0], d.at[i][1], d.at[i][2]));
}

MeshSummary run_body(const MeshRequest& s, MeshSummary m, const body::BodyMesh& body_mesh, wall::WallField& field,
                     const ProgressCallback& progress) {
  BodySummary& b = *m.body;
  const BodyRequest& settings = *s.body;
  b.skin = settings.skin;
  b.fillet = settings.fillet;
  b.origin = settings.origin ? *settings.origin : b.box[0];
  // The thickness over the body's box, in cells from the origin.
  std::array<double, 3> lo{}, hi{};
  double longest = 0;
  for (size_t a = 0; a < 3; ++a) {
    lo[a] = (b.box[0][a] - b.origin[a]) / s.cell_size;
    hi[a] = (b.box[1][a] - b.origin[a]) / s.cell_size;
    longest = std::max(longest, hi[a] - lo[a]);
  }
  const auto range = field.thickness_range(lo, hi);
  record_wall_range(s, field, range, m);
  if (s.voxel > 0) {
    b.voxel = s.voxel;
  } else {
    int resolution = m.automatic_resolution ? automatic_resolution(longest, m.extent.thinnest) : s.resolution;
    // The skin spans at least 3 voxels by default.
    if (m.automatic_resolution && settings.skin > 0)
      resolution = std::max(resolution, static_cast<int>(std::ceil(3 * s.cell_size / settings.skin - 1e-9)));
    b.voxel = s.cell_size / resolution;
  }
  check_drain_diameter(s.drain, b.voxel, b.box);
  const double per_cell = s.cell_size / b.voxel;
  m.resolution = static_cast<int>(std::lround(per_cell));
  check_wall_voxels(
      m.extent.thinnest, per_cell,
      s.voxel > 0 ? fmt::format("--voxel {:g} mm", s.voxel) : fmt::format("{} voxels per cell", m.resolution),
      s.cell_size, s.voxel > 0, m.network);
  if (settings.skin > 0 && settings.skin < 2 * b.voxel)
    throw InputError(
        fmt::format("--skin {:g} mm spans {:.3g} voxels of {:.4g} mm: a skin needs at least 2; use "
                    "--voxel {:g} or less",
                    settings.skin, settings.skin / b.voxel, b.voxel, settings.skin / 2));
  double voxels = 1;
  for (size_t a = 0; a < 3; ++a) voxels *= (b.box[1][a] - b.box[0][a]) / b.voxel + 16;
  if (voxels > kMaxBodyVoxels)
    throw InputError(
        fmt::format("the body's box at {:.4g} mm voxels is {:.3g} voxels, above the limit of {:.3g} (a guard "
                    "against typos: the time grows with the voxels, the memory does not); use a larger --voxel "
                    "(or --resolution)",
                    b.voxel, voxels, kMaxBodyVoxels));

  compile_wall(field, m, progress);
  StageClock clock(m.stages);

  progress("indexing the body's facets", -1);
  const VoxelFrame frame{b.origin, b.voxel};
  BodyDomain domain(body_mesh, frame, settings.skin / b.voxel, settings.fillet / b.voxel);
  b.index_bytes = domain.memory_bytes();
  check_drain_points(s.drain, domain, threads_for(s));
  clock.done("body");

  VoxelGrid grid;
  grid.resolution = m.resolution;
  grid.voxel_size = b.voxel / s.cell_size;
  // M bounds |grad F| over the unit cell (catalog surfaces repeat it) or a mapped lattice's whole box.
  m.field_bound_used = field.generation().surface.from_catalog || field.generation().surface.mapped();
  b.expected_density = s.wall.generation.density ? s.wall.generation.density : field.uniform_density();
  m.requested_density = s.wall.generation.density;
  b.part_box[0].fill(HUGE_VAL);
  b.part_box[1].fill(-HUGE_VAL);
  // The enclosed voids: planned on a first pass with --drain or --fill-pockets, found on the mesh pass.
  VoidStage voids(s.drain, domain.block_range(), b.voxel, s.tile_range.has_value());
  if (voids.plans_edits()) {
    voids.plan(field, domain, grid, m.extent.reach, m.field_bound_used, threads_for(s),
               make_tiles(domain.block_range(), s.tile), body_mesh, frame,
               [&](double f) { progress("finding the enclosed voids", f); });
    domain.edits = &voids.edits();
    m.stages.push_back({"drain plan", voids.first_pass_seconds()});
  }
  const bool holes = !voids.edits().holes.empty();
  double measure_seconds = 0;
  // Each tile's (or the whole mesh's) box and skin: the skin by closed surfaces when the mesh is
  // held, by depth tile by tile when it is streamed.
  auto measure = [&](const TriangleMesh& mesh) {
    const auto start = std::chrono::steady_clock::now();
    const auto box = mesh_box(mesh);
    for (size_t a = 0; a < 3; ++a) {
      b.part_box[0][a] = std::min(b.part_box[0][a], box[0][a]);
      b.part_box[1][a] = std::max(b.part_box[1][a], box[1][a]);
    }
    if (settings.skin > 0) {
      if (holes) {  // the holes' walls cross the skin: measured away from them, vertex by vertex
        measure_skin_by_depth(voids.away_from_holes(mesh.points, domain.distances(mesh.points, threads_for(s)), frame),
                              b.voxel, b.measured_skin);
      } else if (m.streamed) {
        measure_skin_by_depth(domain.distances(mesh.points, threads_for(s)), b.voxel, b.measured_skin);
      } else {
        b.measured_skin = measure_skin(mesh, domain.distances(mesh.points, threads_for(s)), b.voxel);
      }
    }
    measure_seconds += seconds_since(start);
  };
  const std::string text = description(s, m, field.generation().surface.name);
  TriangleMesh mesh = mesh_part(
      s, field, domain, grid, m, progress,
      [&frame](const std::array<float, 3>& p) {
        const auto q = frame.centre_mm({double(p[0]), double(p[1]), double(p[2])});
        return std::array<float, 3>{static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2])};
      },
      measure, text, [&voids](const SampledBand& band) { voids.record(band); });
  m.stages.push_back({"measure", measure_seconds});
  const auto void_start = std::chrono::steady_clock::now();
  b.voids = voids.finish([&](const VoxelBox& blocks) {
    return sample_band(
        field, domain, grid, m.extent.reach, m.field_bound_used, 1, [](double) {}, blocks, blocks);
  });
  m.stages.push_back({"voids", voids.record_seconds() + seconds_since(void_start)});
  write_part(s, mesh, m, text, progress);
  return m;
}

std::string format_box(const std::array<std::array<double, 3>, 2>& box) {
  return fmt::format("({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g}) mm", box[0][0], box[0][1], box[0][2],
                     box[1][0], box[1][1], box[1][2]);
}

// "wall 0.1 cell"-style text without the unit: the sheet's thickness or the network's offset, and
// their range where graded.
std::string wall_range_text(const MeshSummary& m) {
  const std::string range =
      fmt::format("{:.4g}{}", m.min_thickness,
                  m.max_thickness != m.min_thickness ? fmt::format(" to {:.4g}", m.max_thickness) : std::string());
  return m.network ? "network solid phi(p, h) < 0, h " + range : "wall " + range;
}

std::string format_body(const MeshSummary& m) {
  const BodySummary& b = *m.body;
  std::string s;
  s += fmt::format("  body:       {}, {} triangles{}, box {}\n", b.path, b.triangles,
                   b.repaired.empty() ? std::string(", closed") : "; --repair: " + b.repaired, format_box(b.box));
  s += fmt::format("              volume {:.6g} mm^3 (on the voxels: {:.6g}, {:+.3f}%)\n", b.volume, b.level_set_volume,
                   100 * (b.level_set_volume / b.volume - 1));
  if (!m.map.empty())
    s += fmt::format("  lattice:    mapped (its cells come from the map); wall {:.4g}{} mm; voxel {:.4g} mm{}\n",
                     m.min_thickness,
                     m.max_thickness != m.min_thickness ? fmt::format(" to {:.4g}", m.max_thickness) : std::string(),
                     b.voxel, m.automatic_resolution ? " (automatic)" : "");
  else
    s += fmt::format(
        "  lattice:    cells of {:g} mm from the origin ({:.4g}, {:.4g}, {:.4g}) mm (x, y, z of --thickness "
        "and --density-field count cells from there); {} cell; voxel {:.4g} mm ({:.4g} per cell{})\n",
        m.cell_size, b.origin[0], b.origin[1], b.origin[2], wall_range_text(m), b.voxel, m.cell_size / b.voxel,
        m.automatic_resolution ? ", automatic" : "");
  if (!m.map.empty())
    s += fmt::format("  map:        {} (x, y, z in mm){}\n", m.map,
                     m.map_region.empty() ? std::string() : "\n              " + m.map_region);
  if (b.skin > 0) {
    s += fmt::format("  skin:       {:g} mm{}: core {:.6g} mm^3, skin {:.6g} mm^3 (on the voxels)\n", b.skin,
                     b.fillet > 0 ? fmt::format(", walls joined with a {:g} mm fillet", b.fillet) : std::string(),
                     b.core_volume, b.skin_volume);
    s += fmt::format(
        "              measured: thinnest {:.4g} mm {}; requested {:g} mm, one voxel {:.4g} mm; outer surface at "
        "most {:.3g} mm deep\n",
        b.measured_skin.thinnest,
        b.measured_skin.by_pieces ? fmt::format("over {} cavities", b.measured_skin.cavities)
        : b.voids.holes.empty()
            ? std::string("(tile by tile: the vertices deeper than a voxel)")
            : std::string("(the vertices deeper than a voxel, two voxels clear of the drain holes)"),
        b.skin, b.voxel, b.measured_skin.outer_deepest);
  } else {
    s += "  skin:       none (--skin 0): the lattice is cut flush by the body\n";
  }
  const double lattice = (m.volume - b.skin_volume) / b.core_volume;
  s += fmt::format("  density:    lattice {:.4f} of the core measured, {:.4f} sampled on its voxels", lattice,
                   m.tally.core_solid_voxels / m.tally.core_voxels);
  if (b.expected_density) {
    const double expected = b.skin_volume + *b.expected_density * b.core_volume;
    s += fmt::format(" ({} {:.4f}); part {:.6g} mm^3 against V_skin + rho V_core = {:.6g} mm^3 ({:+.2f}%)",
                     m.requested_density ? "--density"
                     : m.network         ? "the network's density"
                                         : "the wall's sheet density",
                     *b.expected_density, m.volume, expected, 100 * (m.volume / expected - 1));
  }
  s += "\n";
  s += fmt::format("  part box:   {}\n", format_box(b.part_box));
  s += format_voids(b.voids);
  return s;
}

MeshSummary run_mesh_stages(const MeshRequest& s, const ProgressCallback& progress, const WarningCallback& warn) {
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
  // The body first: a bad file fails before anything is generated.
  body::BodyMesh body_mesh;
  if (s.body) {
    progress("reading the body", -1);
    m.body.emplace();
    body::LoadedBody loaded = body::load_body(*s.body, warn);
    body::check_body_size(loaded.box, s.cell_size, s.body->skin);
    BodySummary& b = *m.body;
    b.path = s.body->path;
    b.triangles = loaded.mesh.triangles.size();
    b.repaired = loaded.repaired;
    b.box = loaded.box;
    b.volume = loaded.volume;
    body_mesh = std::move(loaded.mesh);
  }

  // A mapped lattice is bounded over the body's box, clear of the map's singular set.
  wall::WallRequest request = s.wall;
  if (!request.generation.map.empty()) {
    // Bounds over the body's box grown by 1/20 of its longest side: walls reach half their
    // thickness beyond the points that carry them, and the safeguard's M holds only where it was taken.
    const auto box = body::bounding_box(body_mesh);
    double longest = 0;
    for (size_t a = 0; a < 3; ++a) longest = std::max(longest, box[1][a] - box[0][a]);
    m.map_region = bound_map_to_body(request.generation, body_mesh, longest / 20);
    m.map = resolve_surface(request.generation).map_formula;
  }

  progress("generating the functions", -1);
  wall::WallField field(request);
  m.stages.push_back({"generate", field.generate_seconds()});
  return s.body ? run_body(s, std::move(m), body_mesh, field, progress) : run_block(s, std::move(m), field, progress);
}

}  // namespace

int automatic_resolution(double longest, double min_thickness) {
  const int per_wall = static_cast<int>(std::ceil(kDefaultVoxelsPerWall / min_thickness - 1e-9));
  const int per_block = static_cast<int>(std::ceil(kDefaultBlockVoxels / longest - 1e-9));
  return std::max(per_wall, per_block);
}

int automatic_resolution(const std::array<int, 3>& cells, double min_thickness) {
  const int per_wall = static_cast<int>(std::ceil(kDefaultVoxelsPerWall / min_thickness - 1e-9));
  const int largest = *std::max_element(cells.begin(), cells.end());
  const int per_block = (kDefaultBlockVoxels + largest - 1) / largest;
  return std::max(per_wall, per_block);
}

MeshSummary run_mesh(const MeshRequest& s, const ProgressCallback& progress, const WarningCallback& warn) {
  // The last stage reported, for an out-of-memory message that says where it happened.
  std::string stage = "starting";
  const ProgressCallback tracked = [&](const std::string& name, double fraction) {
    stage = name;
    progress(name, fraction);
  };
  try {
    return run_mesh_stages(s, tracked, warn);
  } catch (const std::bad_alloc&) {
    throw ResourceError(fmt::format(
        "out of memory while {}: {}; the output was not written", stage,
        s.tile > 0 ? fmt::format("lower --tile (now {} voxels a side; a tile's memory grows with its cube), or use a "
                                 "larger --voxel",
                                 s.tile)
                   : std::string("mesh in tiles (--tile 256, STL), or use a larger --voxel")));
  }
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
  if (m.body) {
    s += format_body(m);
  } else {
    s += fmt::format("  block:      {}x{}x{} cells of {:g} mm, {} voxels per cell{}, {} cell\n", m.cells[0], m.cells[1],
                     m.cells[2], m.cell_size, m.resolution, m.automatic_resolution ? " (automatic)" : "",
                     wall_range_text(m));
  }
  s += fmt::format("  mesh:       {} triangles, {} vertices\n", m.triangles, m.points);
  s += fmt::format(
      "  checked:    {} as written{}{}\n", m.audit.describe(), m.tiles > 1 ? ", across the tiles' seams" : "",
      m.tile_range
          ? fmt::format("; {} edges on seams to other shares left to the merged file", m.audit.unmatched_seam_edges)
          : std::string());
  if (m.tiles > 1 || m.tile_range)
    s += fmt::format("  tiles:      {}{} of {} voxels a side; {}\n",
                     m.tile_range ? fmt::format("{} of ", m.tiles_meshed) : std::string(), m.tiles, m.tile_size,
                     m.tile_range ? fmt::format("share {}/{}, a partial STL: join the shares with --merge",
                                                m.tile_range->first, m.tile_range->second)
                     : m.streamed ? fmt::format("{} written tile by tile (memory: one tile{})", format_name(m.format),
                                                m.format == MeshFormat::Ply ? ", and the seams' points" : "")
                                  : fmt::format("{} held whole, seams welded", format_name(m.format)));
  if (!m.body)
    s += fmt::format(
        "  volume:     {:.6g} mm^3, relative density {:.4f}, {:.4f} sampled on the voxels (box {:.6g} mm^3{})\n",
        m.volume, m.volume / m.box_volume, m.tally.core_solid_voxels / m.tally.core_voxels, m.box_volume,
        m.requested_density ? fmt::format("; --density {}", *m.requested_density) : std::string());
  if (m.streamed) {
    s += fmt::format(
        "  pieces:     not counted across tiles; {} small pieces inside single tiles dropped ({:.3g} mm^3)\n",
        m.inner_dropped, m.inner_dropped_volume);
  } else {
    s += fmt::format("  pieces:     {} kept, {} dropped below the volume threshold ({:.3g} mm^3){}\n", m.pieces.kept,
                     m.pieces.dropped, m.pieces.dropped_volume,
                     m.pieces.cavities ? fmt::format(", {} closed cavities", m.pieces.cavities) : std::string());
  }
  s += fmt::format(
      "  evaluation: {} wall samples, {:.3g} samples/s ({} <prefix>_offset_n value{} each, {}); "
      "voxels ruled out by F: {}\n",
      m.wall_samples, m.samples_per_second, m.network ? "one" : "two", m.network ? "" : "s", m.compile_flags,
      m.field_bound_used ? std::to_string(m.skipped_voxels)
                         : std::string("none (M bounds |grad F| over one cell, and this expression spans several)"));
  if (m.body)
    s += fmt::format("  memory:     the body's facets indexed in {:.1f} MB (its distance is computed block by block)\n",
                     double(m.body->index_bytes) / 1e6);
  s += fmt::format("  time:       {:.2f} s ({})\n", total, stages);
  return s;
}

}  // namespace offsetgen::mesh
