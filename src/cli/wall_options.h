// The options that say which solid a part is made of, shared by `mesh` and `slice`: the generation
// options (generation_options.h) and the wall: --thickness, --density, --density-field, --network.
#pragma once

#include "cli/generation_options.h"
#include "wall/wall_field.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace offsetgen {

struct WallOptions : GenerationOptions {
  std::string thickness;
  std::optional<double> density;             // --density R: the sheet of relative density R
  std::optional<std::string> density_field;  // --density-field E: graded, rho(x, y, z)
  bool network = false;                      // --network: the network solid phi(p, h) < 0
};

// Adds the generation options and the wall's four to `cmd`.
void add_wall_options(CLI::App* cmd, WallOptions& options);

// The request as given; the library checks it (one of the three, validate/wall_choice.h).
wall::WallRequest wall_request(const WallOptions& options);

}  // namespace offsetgen
