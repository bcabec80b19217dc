// `offsetgen list`: the catalog with formulas and sources; --registries adds the offset methods and the
// targets, as data for build systems (no C++ to parse).
#pragma once

#include <CLI/CLI.hpp>

namespace offsetgen {

struct ListOptions {
  bool json = false;        // the surfaces as JSON
  bool registries = false;  // surfaces, methods and targets as JSON
};

void add_list_command(CLI::App& app, ListOptions& options);
int run_list(const ListOptions& options);

}  // namespace offsetgen
