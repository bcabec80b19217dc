// `offsetgen step`: its options and their CLI11 definition, parsed once, by offsetgen-step (offsetgen
// passes the command line on: cli/siblings.h).
#pragma once

#include "cli/body_options.h"
#include "cli/generation_options.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace offsetgen {

struct StepOptions : GenerationOptions {
  std::string thickness, cells = "1", output;
  std::optional<double> density;
  std::string cell_size = "10";  // MM or X,Y,Z (cli/cells_option.h)
  double tolerance = 0.01;
  int max_control_points = 40;
  std::string patches = "auto";
  bool quiet = false;
  BodyOptions body;  // --body, --skin, --origin, --scale
};

void add_step_command(CLI::App& app, StepOptions& options);

}  // namespace offsetgen
