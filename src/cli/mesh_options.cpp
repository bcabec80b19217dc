#include "cli/mesh_options.h"

#include "surfaces/lattice_map.h"

#include <fmt/format.h>

namespace offsetgen {

void add_mesh_command(CLI::App& app, MeshOptions& o) {
  auto* cmd = app.add_subcommand(
      "mesh",
      "Mesh a block of cells of a wall solid (walls of thickness t around F = 0, capped by the block), or fill a\n"
      "part (--body) with it inside a solid skin, as a closed, outward-oriented triangle mesh in millimetres,\n"
      "ready for a slicer (OpenVDB volumeToMesh)");
  add_wall_options(cmd, o);
  auto* cells = cmd->add_option("-c,--cells", o.cells, "Cells of the block: NX[xNY[xNZ]]")
                    ->capture_default_str()
                    ->each([&o](const std::string&) { o.cells_given = true; });
  cmd->add_option("--map", o.map,
                  "Conforming lattice: \"U; V; W\", the lattice coordinates (in cells) of a point x, y, z in mm, or "
                  "a preset: " +
                      map_presets_summary() +
                      ". Walls are --thickness mm thick along the physical normal; fill a --body, or a --domain box "
                      "(docs/maps.md)");
  cmd->add_option("--domain", o.domain, "With --map and no --body: the box X0,Y0,Z0:X1,Y1,Z1 (mm) to fill");
  add_body_options(cmd, o)->excludes(cells);
  add_drain_options(cmd, o);
  cmd->add_option("--cell-size", o.cell_size,
                  "Cell edge length in millimetres: MM (a cube cell), or X,Y,Z (a box cell, \"distorted cells\": the "
                  "lattice u = x/X, v = y/Y, w = z/Z of a block of --cells, meshed as --map \"x/X; y/Y; z/Z\": "
                  "--thickness is then in mm along the physical normal, the voxel is --voxel MM; --density and "
                  "--resolution are refused)")
      ->capture_default_str()
      ->each([&o](const std::string&) { o.cell_size_given = true; });
  auto* resolution =
      cmd->add_option("-r,--resolution", o.resolution,
                      "Voxels per cell (default: the thinnest wall spans 4 voxels, a skin 3; at least 2 are required)");
  cmd->add_option("--voxel", o.voxel, "Voxel edge in millimetres, instead of --resolution")->excludes(resolution);
  cmd->add_option("-a,--adaptivity", o.adaptivity,
                  "Merge flat regions into larger triangles, 0 (off) to 1: smaller files")
      ->capture_default_str();
  cmd->add_option("--min-piece", o.min_piece,
                  "Drop disconnected pieces with less than this fraction of the largest piece's volume")
      ->capture_default_str();
  cmd->add_option("--tile", o.tile,
                  "Voxels per tile side, a multiple of 8: STL and PLY are sampled, meshed and written one tile at a "
                  "time, so memory stays bounded (under 1 GB at 256); 0: the whole domain at once. 3MF holds the "
                  "whole mesh (lib3mf)")
      ->capture_default_str();
  cmd->add_option("--tile-range", o.tile_range,
                  "I/N: mesh only share I (0 to N-1) of the tiles into a partial STL, for a cluster; join the parts "
                  "with --merge");
  cmd->add_option("--merge", o.merge,
                  "Join partial STL files of one run (--tile-range 0/N ... N-1/N, in that order) into -o; nothing "
                  "else is meshed")
      ->expected(1, -1);
  cmd->add_option("-o,--output", o.output, "Output mesh: .stl (binary STL), .ply (binary PLY) or .3mf (3MF)");
  cmd->add_option("-j,--threads", o.threads, "Sampling threads (default: one per hardware thread)");
  cmd->add_flag("-q,--quiet", o.quiet, "Print nothing on success");
  cmd->footer(
      "Exit status: 0 success, 2 usage or input error (no file is written then), 3 the part failed its own check\n"
      "(open or non-manifold edges, degenerate facets, a skin thinner than --skin less a voxel; nothing is kept),\n"
      "out of memory or disk, or an internal error, 130/143 interrupted by SIGINT/SIGTERM (the unfinished file\n"
      "removed, an existing -o unchanged).\n"
      "Examples: offsetgen mesh --surface gyroid --thickness 0.1 --cells 4 --cell-size 10 -o gyroid.stl\n"
      "          offsetgen mesh --surface gyroid --density 0.2 --cells 4 --cell-size 10 -o gyroid.stl\n"
      "          offsetgen mesh --surface gyroid --density 0.2 --body part.stl --skin 1.2 --cell-size 4 -o filled.stl\n"
      "          offsetgen mesh --surface diamond --network --density 0.3 --cells 3 --cell-size 8 -o struts.stl\n"
      "          offsetgen mesh --surface gyroid --thickness 1 --cells 2 --cell-size 10,10,15 -o box_cells.stl\n"
      "          offsetgen mesh ... --tile-range 0/4 -o part0.stl   (... 3/4 -o part3.stl, on four machines)\n"
      "          offsetgen mesh --merge part0.stl part1.stl part2.stl part3.stl -o part.stl\n"
      "With --body, inside is where the body's facets wind around a point (their orientation does not change\n"
      "it); the body must be closed (see --repair). docs/parts.md explains.");
}

}  // namespace offsetgen
