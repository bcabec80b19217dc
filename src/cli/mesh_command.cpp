#include "cli/mesh_command.h"

#include "cli/cells_option.h"
#include "cli/command_line.h"
#include "mesh/mesher.h"
#include "mesh/narrow_band.h"
#include "mesh/stl_stream.h"
#include "mesh/tiles.h"
#include "support/progress_line.h"
#include "surfaces/expression_input.h"
#include "surfaces/lattice_map.h"
#include "surfaces/surface.h"
#include "validate/block_checks.h"

#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace offsetgen {
namespace {

int run_merge(const MeshOptions& o) {
  if (!o.surface.empty() || !o.expression.empty() || !o.body.empty())
    throw InputError("--merge joins the parts of a run: give only the parts and -o");
  if (o.output.empty()) throw InputError("--merge: no output file: use -o part.stl");
  if (mesh::format_for_path(o.output) != mesh::MeshFormat::Stl)
    throw InputError(fmt::format("--merge writes binary STL: -o '{}' is not .stl", o.output));
  const mesh::MergeReport r = mesh::merge_stl_parts(o.merge, o.output);
  if (!o.quiet)
    std::printf("offsetgen mesh: %s written (binary STL, %.1f MB): %llu facets from %zu parts\n", o.output.c_str(),
                double(r.bytes) / 1e6, static_cast<unsigned long long>(r.facets), o.merge.size());
  return kExitOk;
}

// A mapped lattice takes x, y, z in millimetres: its cells come from the map, so the lattice's unit
// is 1 mm and its origin the body's; a block is the --domain box, meshed as a body without a skin.
void apply_map_options(const MeshOptions& o, mesh::MeshRequest& s) {
  if (o.cell_size_given || o.cells_given)
    throw InputError(
        "--map sets the cells (their size and number come from the map): drop --cell-size and --cells; "
        "fill a --body, or give the box with --domain X0,Y0,Z0:X1,Y1,Z1 (mm)");
  if (!o.origin.empty())
    throw InputError("--origin does not apply with --map: the map's x, y, z are the body's own coordinates (mm)");
  s.wall.generation.map = o.map;
  s.cell_size = 1;
  if (s.body) {
    if (!o.domain.empty())
      throw InputError("--domain is the box of a mapped block; with --body the body's box is the domain");
    s.body->origin = std::array<double, 3>{0, 0, 0};
    return;
  }
  if (o.domain.empty())
    throw InputError("--map needs a region to fill: --body part.stl, or --domain X0,Y0,Z0:X1,Y1,Z1 (mm)");
  const Surface::Box box = parse_domain(o.domain);
  if (box.dims != 3) throw InputError("--domain: mesh needs a 3D box, X0,Y0,Z0:X1,Y1,Z1");
  mesh::BodyRequest b;
  b.path = "--domain " + o.domain;
  b.box = std::array<std::array<double, 3>, 2>{box.lo, box.hi};
  b.origin = std::array<double, 3>{0, 0, 0};
  s.body = b;
}

// A box cell (--cell-size X,Y,Z of unequal sides) is the linear map u = x/X, v = y/Y, w = z/Z: the
// composed field is offset in mm along the physical normal (docs/maps.md), over the block of --cells.
void apply_box_cell(const MeshOptions& o, const std::array<double, 3>& size, mesh::MeshRequest& s) {
  if (s.body)
    throw InputError(
        "a box cell (--cell-size X,Y,Z) fills a block of --cells; to fill a --body with it, give the same lattice "
        "as --map \"x/X; y/Y; z/Z\" (its origin then at x = y = z = 0 of the body's coordinates)");
  if (o.density || o.density_field)
    throw InputError(
        "--density and --density-field need a cube cell: with --cell-size X,Y,Z of unequal sides the cell is "
        "stretched differently along each axis and no closed-form density relation holds; give the wall as "
        "--thickness T (mm)");
  if (o.resolution != 0)
    throw InputError(
        "--resolution counts voxels per cell, which a box cell (--cell-size X,Y,Z) does not have one of: give "
        "--voxel MM, or neither (automatic)");
  if (!o.domain.empty())
    throw InputError(
        "--domain sets the box of a mapped lattice (--map); a block of box cells is --cells and --cell-size");
  s.wall.generation.map = fmt::format("x/{}; y/{}; z/{}", size[0], size[1], size[2]);
  s.cell_size = 1;  // the map's x, y, z are mm
  mesh::BodyRequest b;
  b.path = fmt::format("--cells {} --cell-size {}", o.cells, o.cell_size);
  b.box = std::array<std::array<double, 3>, 2>{
      std::array<double, 3>{0, 0, 0},
      std::array<double, 3>{s.cells[0] * size[0], s.cells[1] * size[1], s.cells[2] * size[2]}};
  b.origin = std::array<double, 3>{0, 0, 0};
  s.body = b;
}

}  // namespace

int run_mesh_command(const MeshOptions& o) {
  if (!o.merge.empty()) return run_merge(o);
  mesh::MeshRequest s;
  s.wall = wall_request(o);
  s.cells = parse_cells(o.cells);
  s.body = body_request(o);
  const std::array<double, 3> cell_size = parse_cell_size(o.cell_size);
  s.cell_size = cell_size[0];
  if (!o.map.empty())
    apply_map_options(o, s);
  else if (!cube_cell(cell_size))
    apply_box_cell(o, cell_size, s);
  else if (!o.domain.empty())
    throw InputError("--domain sets the box of a mapped lattice (--map); a block is --cells NXxNYxNZ --cell-size MM");
  s.resolution = o.resolution;
  s.voxel = o.voxel;
  s.tile = o.tile;
  if (!o.tile_range.empty()) s.tile_range = mesh::parse_tile_range(o.tile_range);
  s.adaptivity = o.adaptivity;
  s.min_piece = o.min_piece;
  s.output = o.output;
  s.threads = o.threads;
  s.drain = drain_request(o);
  ProgressLine bar("[offsetgen mesh]");
  mesh::MeshSummary summary = mesh::run_mesh(
      s, [&](const std::string& stage, double f) { bar.show(stage, f); },
      [&](const std::string& warning) {
        bar.clear();
        std::fprintf(stderr, "offsetgen mesh: warning: %s\n", warning.c_str());
      });
  bar.clear();
  if (!o.quiet) std::fputs(mesh::format_summary(summary).c_str(), stdout);
  return kExitOk;
}

}  // namespace offsetgen
