// `offsetgen generate`: options and the run.
#pragma once

#include "cli/generation_options.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace offsetgen {

// The surface, expression, parameters, prefix, method and order are the generation options every command
// shares (generation_options.h); generate defines them with its own, longer help.
struct GenerateOptions : GenerationOptions {
  std::string lang = "c" /* a comma list of backend names, or all */, precision = "double", output, out_dir;
  std::string thickness;
  std::string map, domain;             // --map, --domain (surfaces/lattice_map.h)
  std::string density, density_field;  // --density R, --density-field EXPR (text: parsed in run_generate)
  bool density_functions = false;
  bool quiet = false;
  // Whether the option was on the command line at all: an empty value is refused, not ignored.
  bool output_given = false, out_dir_given = false, thickness_given = false;
  bool density_given = false, density_field_given = false;
};

void add_generate_command(CLI::App& app, GenerateOptions& options);
int run_generate(const GenerateOptions& options, const std::vector<std::string>& args);

}  // namespace offsetgen
