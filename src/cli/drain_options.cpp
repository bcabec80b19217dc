#include "cli/drain_options.h"

#include "cli/body_options.h"

namespace offsetgen {

void add_drain_options(CLI::App* cmd, DrainOptions& o) {
  cmd->add_option("--drain", o.drain,
                  "With --body: cut escape holes of this diameter (mm) through the skin, two for every enclosed void "
                  "region of 1 mm^3 or more (at its lowest and highest points along --up), so resin or powder can "
                  "leave (docs/parts.md)");
  cmd->add_option("--drain-at", o.drain_at,
                  "With --drain: place the holes by hand instead, one at each X,Y,Z (mm, inside the body), out through "
                  "the nearest point of the surface")
      ->expected(1, -1);
  cmd->add_option("--up", o.up, "The build direction, X, Y or Z: drain holes go at the voids' extremes along it")
      ->capture_default_str();
  cmd->add_option("--fill-pockets", o.fill_pockets,
                  "With --body: make every enclosed void region under this volume (mm^3) solid");
}

mesh::DrainRequest drain_request(const DrainOptions& o) {
  mesh::DrainRequest r;
  r.diameter = o.drain;
  for (const auto& text : o.drain_at) r.at.push_back(parse_point(text, "--drain-at"));
  r.up = mesh::parse_up_axis(o.up);
  r.fill_below = o.fill_pockets;
  return r;
}

}  // namespace offsetgen
