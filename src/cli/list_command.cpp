#include "cli/list_command.h"

#include "cli/command_line.h"
#include "emit/backend.h"
#include "offset/method.h"
#include "surfaces/catalog.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <vector>

namespace offsetgen {

namespace {

// The registries as data, for build systems and tools that must not read C++ (issue 27).
nlohmann::ordered_json registries() {
  nlohmann::ordered_json out;
  out["surfaces"] = nlohmann::ordered_json::array();
  for (const auto& e : catalog())
    out["surfaces"].push_back({{"name", e.name}, {"title", e.title}, {"formula", e.formula}, {"citation", e.citation}});
  out["methods"] = nlohmann::ordered_json::array();
  for (const OffsetMethod* m : offset_methods()) {
    // The orders a request can get: the effective order of each requested one (projection rounds
    // odd orders up).
    std::vector<int> orders;
    for (int k = 1; k <= m->max_order(); ++k)
      if (orders.empty() || orders.back() != m->effective_order(k)) orders.push_back(m->effective_order(k));
    out["methods"].push_back({{"name", m->name()},
                              {"description", m->description()},
                              {"default", m->name() == kDefaultMethod},
                              {"max_order", m->max_order()},
                              {"orders", orders}});
  }
  out["targets"] = nlohmann::ordered_json::array();
  for (const Backend* b : backends())
    out["targets"].push_back({{"name", b->name()}, {"title", b->title()}, {"extension", b->extension()}});
  return out;
}

}  // namespace

void add_list_command(CLI::App& app, ListOptions& options) {
  auto* cmd = app.add_subcommand("list", "List the built-in surfaces with their formulas");
  auto* json = cmd->add_flag("--json", options.json, "Print the surfaces as JSON");
  cmd->add_flag("--registries", options.registries,
                "Print the registries as JSON: surfaces, offset methods with their orders, targets with their "
                "file extensions")
      ->excludes(json);
}

int run_list(const ListOptions& options) {
  if (options.registries) {
    fmt::print("{}\n", registries().dump(2));
    return kExitOk;
  }
  if (options.json) {
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
