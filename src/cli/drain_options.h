// mesh's options for a part's enclosed voids (issue 43): --drain D, --drain-at X,Y,Z ..., --up X|Y|Z,
// --fill-pockets V, and the request they make.
#pragma once

#include "mesh/drain_plan.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace offsetgen {

struct DrainOptions {
  double drain = 0;                   // --drain D (mm)
  std::vector<std::string> drain_at;  // --drain-at X,Y,Z ...
  std::string up = "Z";
  double fill_pockets = 0;  // --fill-pockets V (mm^3)
};

void add_drain_options(CLI::App* cmd, DrainOptions& options);
// Throws InputError for a bad point or axis.
mesh::DrainRequest drain_request(const DrainOptions& options);

}  // namespace offsetgen
