#include "cli/wall_options.h"

namespace offsetgen {

void add_wall_options(CLI::App* cmd, WallOptions& o) {
  add_generation_options(cmd, o, "Catalog surface (see `offsetgen list`)",
                         "Your own F(x, y, z) in cell units, as in `generate`");
  cmd->add_option("-t,--thickness", o.thickness,
                  "Total wall thickness in cell units: a number, or an expression of x, y, z (x runs over [0, NX])");
  cmd->add_option("--density", o.density,
                  "Instead of --thickness: the relative density R of the wall (its volume fraction; periodic "
                  "surfaces; docs/density.md)");
  cmd->add_option("--density-field", o.density_field,
                  "Instead of --thickness: a graded relative density rho(x, y, z), t(p) = "
                  "thickness_for_density(rho(p))");
  cmd->add_flag("--network", o.network,
                "The network (skeletal, strut) solid offset(p, h) < 0 instead of the sheet: --thickness is then the "
                "offset h in cell units (either sign; h > 0 grows the network), --density the network's relative "
                "density (offsetgen density --network)");
}

wall::WallRequest wall_request(const WallOptions& o) {
  wall::WallRequest r;
  r.generation = generation_request(o);
  r.thickness = o.thickness;
  r.network = o.network;
  r.generation.density = o.density;
  r.generation.density_field = o.density_field;
  return r;
}

}  // namespace offsetgen
