// `offsetgen mesh`: its options and their CLI11 definition, parsed once, by offsetgen-mesh (offsetgen
// passes the command line on: cli/siblings.h).
#pragma once

#include "cli/body_options.h"
#include "cli/drain_options.h"
#include "cli/wall_options.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace offsetgen {

struct MeshOptions : WallOptions, BodyOptions, DrainOptions {
  std::string cells = "1", output;
  std::string cell_size = "10";  // MM or X,Y,Z (cli/cells_option.h)
  bool cell_size_given = false, cells_given = false;
  std::string map, domain;  // --map, --domain: a conforming lattice (surfaces/lattice_map.h)
  int resolution = 0;
  double voxel = 0;
  int tile = 256;
  std::string tile_range;          // --tile-range I/N
  std::vector<std::string> merge;  // --merge PART...
  double adaptivity = 0;
  double min_piece = 0.01;
  int threads = 0;
  bool quiet = false;
};

void add_mesh_command(CLI::App& app, MeshOptions& options);

}  // namespace offsetgen
