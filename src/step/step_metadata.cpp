#include "step/step_metadata.h"

#include "step/cell_frame.h"
#include "surfaces/input_error.h"
#include "validate/block_checks.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <map>

namespace offsetgen::step {
namespace {

constexpr const char* kMetadataTag = "offsetgen-metadata ";

std::string request_metadata(const StepRequest& r, const StepSummary& s) {
  nlohmann::ordered_json j;
  const GenerationRequest& g = r.wall.generation;
  if (g.expression.empty()) {
    j["surface"] = g.surface;
  } else {  // the expression itself, so check can build the same walls again
    j["expr"] = g.expression;
    j["name"] = g.name;
    if (!g.params.empty()) j["params"] = g.params;
  }
  j["method"] = r.wall.generation.method;
  j["order"] = r.wall.generation.order;
  j["thickness"] = s.thickness_text;  // a uniform one as the shortest text that reads back as the same double
  j["cells"] = r.cells;
  if (cube_cell(r.cell_size))
    j["cell_size"] = r.cell_size[0];  // a cube cell's header as before a box cell could be written
  else
    j["cell_size"] = r.cell_size;
  j["tolerance"] = r.tolerance;
  j["solids"] = s.expected_solids;
  return kMetadataTag + j.dump();
}

}  // namespace

std::string file_description(const StepRequest& r, const StepSummary& s) {
  return fmt::format("offsetgen: {} wall, t = {} ({}), {}x{}x{} cells of {} mm, tolerance {} mm; {}", s.surface,
                     s.thickness_text, s.thickness_in_mm ? "mm" : "cell units", r.cells[0], r.cells[1], r.cells[2],
                     cell_size_words(r.cell_size), r.tolerance, request_metadata(r, s));
}

StepRequest request_from_description(const std::string& description, const std::string& path, int& solids) {
  const size_t at = description.find(kMetadataTag);
  if (at == std::string::npos)
    throw InputError(fmt::format(
        "{}: no offsetgen-metadata in its header (FILE_DESCRIPTION): check measures a STEP file of `offsetgen step` "
        "against the walls it was made from, and this one does not say which",
        path));
  StepRequest r;
  try {
    const auto j = nlohmann::json::parse(description.substr(at + std::string(kMetadataTag).size()));
    if (j.contains("expr")) {
      r.wall.generation.expression = j.at("expr").get<std::string>();
      r.wall.generation.name = j.at("name").get<std::string>();
      r.wall.generation.params = j.value("params", std::map<std::string, std::string>{});
    } else {
      r.wall.generation.surface = j.at("surface").get<std::string>();
    }
    r.wall.generation.method = j.at("method").get<std::string>();
    r.wall.generation.order = j.at("order").get<int>();
    r.wall.thickness = j.at("thickness").get<std::string>();
    r.cells = j.at("cells").get<std::array<int, 3>>();
    const auto& size = j.at("cell_size");
    r.cell_size = size.is_array() ? size.get<std::array<double, 3>>()
                                  : std::array<double, 3>{size.get<double>(), size.get<double>(), size.get<double>()};
    r.tolerance = j.at("tolerance").get<double>();
    solids = j.value("solids", 1);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: its offsetgen-metadata cannot be read: {}", path, e.what()));
  }
  if (!(r.tolerance > 0) || !(r.cell_size[0] > 0) || !(r.cell_size[1] > 0) || !(r.cell_size[2] > 0) || r.cells[0] < 1 ||
      r.cells[1] < 1 || r.cells[2] < 1 || solids < 1)
    throw InputError(fmt::format("{}: its offsetgen-metadata holds a block or tolerance out of range", path));
  return r;
}

}  // namespace offsetgen::step
