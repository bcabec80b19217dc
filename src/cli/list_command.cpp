#include "cli/list_command.h"

#include "cli/command_line.h"
#include "surfaces/catalog.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace offsetgen {

void add_list_command(CLI::App& app, bool& json) {
  auto* cmd = app.add_subcommand("list", "List the built-in surfaces with their formulas");
  cmd->add_flag("--json", json, "Print as JSON");
}

int run_list(bool json) {
  if (json) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& e : catalog())
      out.push_back({{"name", e.name}, {"title", e.title}, {"formula", e.formula}, {"citation", e.citation}});
    fmt::print("{}\n", out.dump(2));
    return kExitOk;
  }
  fmt::print("Built-in surfaces (cell length L = 1; X = 2*pi*x, Y = 2*pi*y, Z = 2*pi*z):\n\n");
  for (const auto& e : catalog()) {
    fmt::print("{:<12} {}\n{:<12} F = {}\n{:<12} {}\n\n", e.name, e.title, "", e.formula, "", e.citation);
  }
  return kExitOk;
}

}  // namespace offsetgen
