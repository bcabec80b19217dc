// `offsetgen density`: the wall thickness (or network offset) of a relative density, with the
// surface constants behind it (density/, docs/density.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace offsetgen {

struct DensityOptions {
  std::string surface, expression, name;
  std::vector<std::string> params;
  std::string rho;  // text, parsed in run_density for a clear message
  bool network = false;
  bool json = false;
};

void add_density_command(CLI::App& app, DensityOptions& options);

// A relative density given on the command line (--density): a finite number, or InputError
// naming `option`. The range is checked against the surface's limits later.
double parse_density_value(const std::string& option, const std::string& text);
int run_density(const DensityOptions& options);

}  // namespace offsetgen
