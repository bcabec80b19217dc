// The options that say which functions a part is made of (--surface or --expr, --param, --name,
// --method, --order), shared by `mesh` and `step`, and the generation request they give.
#pragma once

#include "offset/method.h"
#include "pipeline/generate.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace offsetgen {

struct GenerationOptions {
  std::string surface, expression, name;
  std::vector<std::string> params;
  std::string method = kDefaultMethod;
  int order = 4;
};

// Adds -s/--surface, -e/--expr, -p/--param, -n/--name, -M/--method and -m/--order to `cmd`, with the
// command's own help for the two that differ.
void add_generation_options(CLI::App* cmd, GenerationOptions& options, const std::string& surface_help,
                            const std::string& expression_help);

// The request's surface, expression, parameters, prefix, method and order. Throws InputError for a
// parameter given twice or not written NAME=VALUE.
GenerationRequest generation_request(const GenerationOptions& options);

}  // namespace offsetgen
