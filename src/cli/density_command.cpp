#include "cli/density_command.h"

#include "cli/command_line.h"
#include "density/density_model.h"
#include "pipeline/generate.h"
#include "surfaces/expression_input.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace offsetgen {

void add_density_command(CLI::App& app, DensityOptions& o) {
  auto* cmd = app.add_subcommand(
      "density",
      "The sheet thickness (or network offset) of a relative density, exactly: rho(t) = A t + (pi chi / 6) t^3,\n"
      "with the surface's area A and Euler characteristic chi computed here (docs/density.md)");
  cmd->add_option("-s,--surface", o.surface, "Catalog surface (see `offsetgen list`)");
  cmd->add_option("-e,--expr", o.expression, "Your own F(x, y, z), periodic with period 1 in x, y and z");
  cmd->add_option("-n,--name", o.name, "Name of the --expr surface");
  cmd->add_option("-p,--param", o.params, "Constant parameter NAME=VALUE of --expr (repeatable)");
  // --density as in generate, mesh and step; --rho, its first name, still works.
  cmd->add_option("--density,--rho", o.rho, "Relative density (volume fraction of the cell), e.g. 0.2")->required();
  cmd->add_flag("--network", o.network,
                "The network solid offset(p, h) < 0 instead of the sheet: prints the offset h of that density");
  cmd->add_flag("--json", o.json, "Print as JSON");
  cmd->footer(
      "Lengths are in cell units (multiply by the cell length). Exit status: 0, or 2 for bad input (rho <= 0,\n"
      "rho beyond the validity limit, a surface without density: 2D or not periodic).\n"
      "Example: offsetgen density --surface gyroid --density 0.2");
}

double parse_density_value(const std::string& option, const std::string& text) {
  size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    throw InputError(fmt::format("{} '{}' is not a number (a relative density, e.g. 0.2)", option, text));
  return value;
}

int run_density(const DensityOptions& o) {
  GenerationRequest request;
  request.surface = o.surface;
  request.expression = o.expression;
  request.name = o.name.empty() && !o.expression.empty() ? "surface" : o.name;
  request.params = parse_params(o.params);
  const double rho = parse_density_value("--density", o.rho);
  const Surface surface = resolve_surface(request);
  const density::DensityModel m = resolve_density(request, surface);
  const density::SurfaceConstants& k = m.constants();

  double value = NAN;
  if (!o.network) {
    if (!(rho > 0)) throw InputError(fmt::format("--density {}: a relative density must be > 0", rho));
    if (rho > m.sheet_density_limit())
      throw InputError(fmt::format(
          "--density {} is above rho_max = {:.6f} of the sheet: its thickness would pass t_max = {:.6f}, where t/2 "
          "reaches the smallest radius of curvature and the thickness no longer determines the density",
          rho, m.sheet_density_limit(), m.thickness_limit()));
    value = m.sheet_thickness(rho);
  } else {
    if (!(rho > 0) || !(rho < 1))
      throw InputError(fmt::format("--density {}: a relative density of the network must lie in (0, 1)", rho));
    if (rho < m.network_density_min() || rho > m.network_density_max())
      throw InputError(fmt::format(
          "--density {} is outside [{:.6f}, {:.6f}], the network densities with |h| <= h_max = {:.6f}, where the "
          "offset reaches the smallest radius of curvature",
          rho, m.network_density_min(), m.network_density_max(), m.offset_limit()));
    value = m.network_offset(rho);
  }

  if (o.json) {
    nlohmann::ordered_json j;
    j["surface"] = surface.name;
    j["title"] = surface.title;
    j["solid"] = o.network ? "network" : "sheet";
    j["rho"] = rho;
    j[o.network ? "offset" : "thickness"] = value;
    j.update(density::constants_json(m, true));
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  if (o.network) {
    fmt::print("{}: network solid offset(p, h) < 0 of relative density {}\n", surface.title, rho);
    fmt::print("  offset h = {:.10f} cell units (the surface moved along +grad F; scale by the cell length)\n", value);
  } else {
    fmt::print("{}: sheet of relative density {}\n", surface.title, rho);
    fmt::print("  thickness t = {:.10f} cell units (total, centred on F = 0; scale by the cell length)\n", value);
  }
  fmt::print("  A = {:.9f} (area of F = 0 per cell), chi = {} (integral K dA / 2 pi = {:.9f})\n", k.area,
             k.euler_characteristic, k.gauss_integral / (2 * M_PI));
  fmt::print("  V_0 = {:.9f} (volume of F < 0), integral H dA = {:.9f}\n", k.volume_inside,
             std::fabs(k.mean_integral) < 1e-12 ? 0.0 : k.mean_integral);
  fmt::print("  sheet:   rho(t) = A t + (pi chi / 6) t^3, exact for t <= t_max = {:.6f} (rho <= {:.6f})\n",
             m.thickness_limit(), m.sheet_density_limit());
  fmt::print(
      "  network: rho(h) = V_0 + A h + h^2 integral(H dA) + (2 pi chi / 3) h^3, exact for |h| <= {:.6f} "
      "({:.6f} <= rho <= {:.6f})\n",
      m.offset_limit(), m.network_density_min(), m.network_density_max());
  fmt::print("  limits from the largest principal curvature of F = 0, {:.6f} per cell length\n", k.max_curvature);
  return kExitOk;
}

}  // namespace offsetgen
