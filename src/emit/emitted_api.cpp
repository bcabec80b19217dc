#include "emit/emitted_api.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace offsetgen {

std::vector<EmittedFunction> emitted_functions(const SurfacePrograms& programs, int dims, const MethodFacts& method,
                                               const density::DensityPrograms* density) {
  const std::string coords = dims == 3 ? "x, y, z" : "x, y";
  std::vector<EmittedFunction> functions = {
      {"field", &programs.field, "", false, "F, the field; the surface is F = 0.", "(" + coords + ")"},
      {"offset", &programs.offset, "h", false,
       "phi(p, h) of order " + std::to_string(method.order) + ": zero on the surface moved by h along +grad F.",
       "(" + coords + ", h)"},
      {"shell", &programs.shell, "t", false,
       "phi(p, t/2) * phi(p, -t/2): negative inside the wall of total thickness t.", "(" + coords + ", t)"},
  };
  if (!programs.normal.outputs().empty())
    functions.push_back({"normal", &programs.normal, "h", true, method.normal, "(" + coords + ", h" + ")"});
  if (programs.graded) {
    functions.push_back({"graded", &*programs.graded, "", false,
                         "the shell with the --thickness t(p) baked in: negative inside the graded wall.",
                         "(" + coords + ")"});
  }
  if (programs.wall) {
    functions.push_back({"wall", &*programs.wall, "", false,
                         "the shell at the --density thickness: negative inside the wall of that relative density.",
                         "(" + coords + ")"});
  }
  if (density) {
    auto scalar = [](const char* suffix, const Program& p, const char* parameter, const char* doc) {
      EmittedFunction f{suffix, &p, parameter, false, doc, std::string("(") + parameter + ")"};
      f.takes_point = false;
      return f;
    };
    functions.push_back(scalar("density", density->density, "t",
                               "volume fraction of the sheet of total thickness t (shell < 0); NaN out of range."));
    functions.push_back(scalar("thickness_for_density", density->thickness_for_density, "rho",
                               "the total sheet thickness t of volume fraction rho; NaN out of range."));
    functions.push_back(scalar("network_density", density->network_density, "h",
                               "volume fraction of the network solid offset(p, h) < 0; NaN out of range."));
    functions.push_back(scalar("offset_for_density", density->offset_for_density, "rho",
                               "the offset h whose network solid has volume fraction rho; NaN out of range."));
  }
  return functions;
}

std::string density_paragraph(const FileFacts& facts, const std::string& nan_note) {
  if (!facts.density) return "";
  const density::DensityModel& m = *facts.density;
  const density::SurfaceConstants& k = m.constants();
  const std::string& p = facts.prefix;
  std::vector<std::string> lines = {
      fmt::format("Density (docs/density.md; cell length L = 1, so a volume fraction is a volume): constants of "
                  "F = 0 per cell, computed at generation time: area A = {:.9f}, Euler characteristic chi = {} "
                  "(integral K dA / 2 pi = {:.9f}, Gauss-Bonnet self-check), V_0 = {:.9f} (the volume of F < 0), "
                  "integral H dA = {:.9f}, largest principal curvature {:.6f} (estimated errors {:.0e}, {:.0e}, "
                  "{:.0e}).",
                  k.area, k.euler_characteristic, k.gauss_integral / (2 * M_PI), k.volume_inside,
                  std::fabs(k.mean_integral) < 5e-10 ? 0.0 : k.mean_integral,  // no "-0.000000000"
                  k.max_curvature, std::max(k.area_error, 1e-12), std::max(k.volume_error, 1e-12),
                  std::max(k.mean_error, 1e-12)),
      fmt::format("Sheet: {0}_density(t) = A t + (pi chi / 6) t^3 is the volume fraction of {0}_shell(p, t) < 0, "
                  "exact (tube formula and Gauss-Bonnet) for 0 <= t <= t_max = {1:.6f}, where t/2 reaches the "
                  "smallest radius of curvature; {0}_thickness_for_density(rho) is its inverse for 0 <= rho <= "
                  "rho_max = {2:.6f}.",
                  p, m.thickness_limit(), m.sheet_density_limit()),
      fmt::format("Network: {0}_network_density(h) = V_0 + A h + h^2 integral(H dA) + (2 pi chi / 3) h^3 is the "
                  "volume fraction of {0}_offset(p, h) < 0 for |h| <= h_max = {1:.6f}; {0}_offset_for_density(rho) "
                  "is its inverse for {2:.6f} <= rho <= {3:.6f}.",
                  p, m.offset_limit(), m.network_density_min(), m.network_density_max()),
      std::string("Out of range (or for a NaN argument) the four return NaN: beyond the limit the relation is "
                  "not exact, and a negative thickness or density means nothing. They are exact for the "
                  "exact offsets; the emitted walls carry the offset error above (offsetgen check measures "
                  "the volume fraction).") +
          (nan_note.empty() ? "" : " " + nan_note),
  };
  if (facts.wall_density)
    lines.push_back(
        fmt::format("--density {}: {}_wall(p) = {}_shell(p, t) with t = {:.17g}, the sheet of "
                    "relative density {}.",
                    *facts.wall_density, p, p, *facts.wall_thickness, *facts.wall_density));
  if (facts.density_field)
    lines.push_back(
        fmt::format("--density-field: {}_graded(p) is the sheet with t(p) = "
                    "thickness_for_density(rho(p)), rho(p) = {}. rho was checked to lie in (0, rho_max] "
                    "on the unit cell; it is not checked at run time.",
                    p, *facts.density_field));
  std::string out;
  for (const auto& line : lines) out += (out.empty() ? "" : "\n") + line;
  return out;
}

// Distinct prefixes must give distinct guards (foo and FOO, too). An all-lowercase prefix gives the
// usual OFFSETGEN_FOO_H; one with capitals keeps its case and ends in a lowercase extension
// (OFFSETGEN_FOO_h), which no all-lowercase prefix produces.
std::string guard_name(const std::string& prefix, const std::string& extension) {
  const bool has_capitals =
      std::any_of(prefix.begin(), prefix.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); });
  std::string guard = "OFFSETGEN_";
  for (char c : prefix) {
    const auto u = static_cast<unsigned char>(c);
    guard += std::isalnum(u) ? static_cast<char>(has_capitals ? c : std::toupper(u)) : '_';
  }
  guard += "_";
  for (char c : extension)
    guard += static_cast<char>(has_capitals ? std::tolower(static_cast<unsigned char>(c)) : std::toupper(static_cast<unsigned char>(c)));
  return guard;
}

std::string wrap_paragraph(const std::string& text, const std::string& first, const std::string& rest, size_t width) {
  std::istringstream words(text);
  std::string out, line = first, word;
  bool empty = true;
  while (words >> word) {
    if (!empty && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line = rest;
      empty = true;
    }
    line += (empty ? "" : " ") + word;
    empty = false;
  }
  return out + line;
}

}  // namespace offsetgen
