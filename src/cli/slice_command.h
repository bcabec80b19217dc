// `offsetgen slice`: its options (CLI11) and the command, run in offsetgen itself (slice/slicer.h).
#pragma once

#include "cli/body_options.h"
#include "cli/wall_options.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace offsetgen {

struct SliceOptions : WallOptions, BodyOptions {
  std::string cells = "1", output, printer, layer_range;
  std::vector<std::string> merge;
  std::string cell_size = "10";  // MM (a box cell X,Y,Z is refused: slice_command.cpp)
  double layer_height = 0.05;
  std::optional<double> first_layer;
  double tolerance = 0.005;
  bool cli_ascii = false;
  int threads = 0;
  bool quiet = false;
  std::string hatch, center;          // --hatch, --center
  std::optional<double> beam_offset;  // --beam-offset
};

void add_slice_command(CLI::App& app, SliceOptions& options);
int run_slice_command(const SliceOptions& options);

}  // namespace offsetgen
