#include "cli/body_options.h"

#include "cli/number_list.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <vector>

namespace offsetgen {

CLI::Option* add_body_options(CLI::App* cmd, BodyOptions& o) {
  CLI::Option* body =
      cmd->add_option("-b,--body", o.body,
                      "Fill this part instead of a block: a closed surface as STL (binary or ASCII), PLY, "
                      "OBJ or 3MF, in millimetres");
  cmd->add_option("--skin", o.skin,
                  "With --body: a solid skin this thick (mm) inward from the body's surface; the lattice fills the "
                  "core inside it and joins it (0: the lattice cut flush by the body)")
      ->capture_default_str()
      ->needs(body);
  cmd->add_option("--fillet", o.fillet, "With --skin: blend the walls into the skin with this radius (mm)")
      ->needs(body);
  cmd->add_option("--origin", o.origin,
                  "With --body: X,Y,Z (mm) where a lattice cell's corner sits (default the body's bounding-box "
                  "minimum); x, y, z of --thickness and --density-field count cells from it")
      ->needs(body);
  cmd->add_option("--scale", o.scale, "With --body: multiply its coordinates (25.4 for inches, 1000 for metres)")
      ->capture_default_str()
      ->needs(body);
  cmd->add_flag("--repair", o.repair,
                "With --body: weld, drop degenerate and duplicate facets, orient them consistently and fill simple "
                "holes instead of refusing an open body (the summary says what was repaired)")
      ->needs(body);
  return body;
}

std::optional<body::BodyRequest> body_request(const BodyOptions& o) {
  if (o.body.empty()) return std::nullopt;
  body::BodyRequest b;
  b.path = o.body;
  b.skin = o.skin;
  b.fillet = o.fillet;
  b.scale = o.scale;
  b.repair = o.repair;
  if (!o.origin.empty()) b.origin = parse_point(o.origin, "--origin");
  return b;
}

std::array<double, 3> parse_point(const std::string& text, const std::string& option) {
  const auto v = parse_number_list(text);
  if (!v || v->size() != 3) throw InputError(fmt::format("{} '{}': expected X,Y,Z (three numbers, mm)", option, text));
  return {(*v)[0], (*v)[1], (*v)[2]};
}

}  // namespace offsetgen
