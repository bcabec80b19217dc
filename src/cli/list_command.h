// `offsetgen list`: the catalog with formulas and sources.
#pragma once

#include <CLI/CLI.hpp>

namespace offsetgen {

void add_list_command(CLI::App& app, bool& json);
int run_list(bool json);

}  // namespace offsetgen
