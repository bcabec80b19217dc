#include "surfaces/lattice_map.h"

#include "surfaces/expression_input.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace offsetgen {
namespace {

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t at = text.find(separator); at != std::string::npos; at = text.find(separator, start)) {
    parts.push_back(trimmed(text.substr(start, at - start)));
    start = at + 1;
  }
  parts.push_back(trimmed(text.substr(start)));
  return parts;
}

// A preset's parameter: a positive number, or (for counts) a whole number >= 1. Returned as text,
// so the parser reads it as an exact rational.
std::string preset_number(const std::string& preset, const std::string& role, const std::string& text, bool count) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || !(value > 0))
    throw InputError(fmt::format("--map {}: {} '{}' must be a positive number", preset, role, text));
  if (count && value != std::floor(value))
    throw InputError(
        fmt::format("--map {}: {} '{}' must be a whole number, or the cells do not close up around the "
                    "axis (the field would jump where the angle wraps)",
                    preset, role, text));
  return text;
}

struct Preset {
  const char* name;
  int dims;
  std::vector<std::pair<const char*, bool>> parameters;  // role, whether a count
  std::vector<const char*> components;                   // with {0}, {1}, {2} for the parameters
};

const std::vector<Preset>& presets() {
  static const std::vector<Preset> list = {
      {"cylindrical",
       3,
       {{"N (cells around)", true}, {"A (radial cell size)", false}, {"C (axial cell size)", false}},
       {"sqrt(x^2+y^2)/({1})", "{0}*atan2(y,x)/(2*Pi)", "z/({2})"}},
      {"spherical",
       3,
       {{"N (cells around)", true}, {"M (cells pole to pole)", true}, {"A (radial cell size)", false}},
       {"sqrt(x^2+y^2+z^2)/({2})", "{0}*atan2(y,x)/(2*Pi)", "{1}*atan2(sqrt(x^2+y^2),z)/Pi"}},
      {"polar",
       2,
       {{"N (cells around)", true}, {"A (radial cell size)", false}},
       {"sqrt(x^2+y^2)/({1})", "{0}*atan2(y,x)/(2*Pi)"}},
  };
  return list;
}

std::vector<std::string> expand_preset(const Preset& preset, const std::string& arguments, int dims) {
  if (preset.dims != dims)
    throw InputError(fmt::format("--map {}: a {}D map, but the surface is {}D", preset.name, preset.dims, dims));
  const std::vector<std::string> values = split(arguments, ',');
  if (values.size() != preset.parameters.size()) {
    std::string roles;
    for (const auto& [role, count] : preset.parameters) roles += (roles.empty() ? "" : ", ") + std::string(role);
    throw InputError(fmt::format("--map {}: expected {} numbers ({}), got '{}'", preset.name, preset.parameters.size(),
                                 roles, arguments));
  }
  std::vector<std::string> numbers;
  for (size_t i = 0; i < values.size(); ++i)
    numbers.push_back(preset_number(preset.name, preset.parameters[i].first, values[i], preset.parameters[i].second));
  std::vector<std::string> components;
  for (const char* pattern : preset.components) {
    std::string c = pattern;
    for (size_t i = 0; i < numbers.size(); ++i) {
      const std::string slot = "{" + std::to_string(i) + "}";
      for (size_t at = c.find(slot); at != std::string::npos; at = c.find(slot)) c.replace(at, slot.size(), numbers[i]);
    }
    components.push_back(c);
  }
  return components;
}

// Where the map is singular: the measure is >= 0 and vanishes there. atan2(b, a) at a = b = 0, a
// root or fractional power at a zero base, a logarithm at zero, a division by zero, asin or acos at
// +-1 (their derivatives are infinite).
void collect_singular_measures(const GiNaC::ex& e, std::vector<GiNaC::ex>& out) {
  const Symbols& sym = Symbols::get();
  auto varies = [&](const GiNaC::ex& a) { return a.has(sym.X) || a.has(sym.Y) || a.has(sym.Z); };
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    const GiNaC::ex& node = *it;
    if (!varies(node)) continue;  // 1/Pi, sqrt(2): constants are never singular
    if (GiNaC::is_a<GiNaC::function>(node)) {
      const std::string name = GiNaC::ex_to<GiNaC::function>(node).get_name();
      if (name == "atan2") out.push_back(GiNaC::sqrt(GiNaC::pow(node.op(0), 2) + GiNaC::pow(node.op(1), 2)));
      if (name == "log") out.push_back(GiNaC::abs(node.op(0)));
      if (name == "asin" || name == "acos") out.push_back(GiNaC::sqrt(GiNaC::abs(1 - GiNaC::pow(node.op(0), 2))));
    } else if (GiNaC::is_a<GiNaC::power>(node) && GiNaC::is_a<GiNaC::numeric>(node.op(1))) {
      const auto& exponent = GiNaC::ex_to<GiNaC::numeric>(node.op(1));
      if (!exponent.is_integer())
        out.push_back(GiNaC::sqrt(GiNaC::abs(node.op(0))));
      else if (exponent.is_negative())
        out.push_back(GiNaC::abs(node.op(0)));
    }
  }
}

}  // namespace

Surface::Box parse_domain(const std::string& text) {
  const std::vector<std::string> corners = split(text, ':');
  const std::string form = "X0,Y0,Z0:X1,Y1,Z1 (or X0,Y0:X1,Y1 in 2D)";
  if (corners.size() != 2) throw InputError(fmt::format("--domain '{}': expected two corners, {}", text, form));
  Surface::Box box;
  std::array<std::vector<std::string>, 2> numbers = {split(corners[0], ','), split(corners[1], ',')};
  if (numbers[0].size() != numbers[1].size() || numbers[0].size() < 2 || numbers[0].size() > 3)
    throw InputError(
        fmt::format("--domain '{}': each corner needs 2 or 3 coordinates, the same number, {}", text, form));
  box.dims = static_cast<int>(numbers[0].size());
  for (size_t c = 0; c < 2; ++c)
    for (size_t i = 0; i < numbers[c].size(); ++i) {
      char* end = nullptr;
      const double v = std::strtod(numbers[c][i].c_str(), &end);
      if (numbers[c][i].empty() || end != numbers[c][i].c_str() + numbers[c][i].size() || !std::isfinite(v))
        throw InputError(fmt::format("--domain '{}': '{}' is not a number", text, numbers[c][i]));
      (c == 0 ? box.lo : box.hi)[i] = v;
    }
  for (int i = 0; i < box.dims; ++i)
    if (!(box.lo[static_cast<size_t>(i)] < box.hi[static_cast<size_t>(i)]))
      throw InputError(fmt::format("--domain '{}': the box is empty along {} ({:g} to {:g})", text, "xyz"[i],
                                   box.lo[static_cast<size_t>(i)], box.hi[static_cast<size_t>(i)]));
  return box;
}

std::string map_presets_summary() {
  std::string out;
  for (const auto& p : presets()) {
    std::string roles;
    for (const auto& [role, count] : p.parameters) roles += (roles.empty() ? "" : ",") + std::string(1, role[0]);
    out += fmt::format("{}{}:{}", out.empty() ? "" : ", ", p.name, roles);
  }
  return out + " (N, M cells around, A, C cell sizes)";
}

LatticeMap parse_lattice_map(const std::string& text, const std::map<std::string, std::string>& params, int dims) {
  LatticeMap map;
  map.text = text;
  map.kind = "mapped";
  const size_t colon = text.find(':');
  if (colon != std::string::npos && text.find(';') == std::string::npos) {
    const std::string name = trimmed(text.substr(0, colon));
    const Preset* preset = nullptr;
    for (const auto& p : presets())
      if (name == p.name) preset = &p;
    if (!preset)
      throw InputError(
          fmt::format("--map '{}': unknown preset '{}'; the presets are cylindrical, spherical and polar, or give "
                      "the lattice coordinates as \"U; V; W\", expressions of x, y, z",
                      text, name));
    map.kind = preset->name;
    map.components = expand_preset(*preset, text.substr(colon + 1), dims);
  } else {
    map.components = split(text, ';');
    if (map.components.size() != static_cast<size_t>(dims))
      throw InputError(fmt::format(
          "--map '{}' has {} component{}, but the surface is {}D: give {} expressions of "
          "x, y{} separated by ';' (the lattice coordinates of a physical point, in cells)",
          text, map.components.size(), map.components.size() == 1 ? "" : "s", dims, dims, dims == 3 ? ", z" : ""));
  }
  const Symbols& sym = Symbols::get();
  for (size_t i = 0; i < map.components.size(); ++i) {
    const std::string what = fmt::format("--map component {} ('{}')", "uvw"[i], map.components[i]);
    if (map.components[i].empty()) throw InputError(fmt::format("--map '{}': component {} is empty", text, "uvw"[i]));
    GiNaC::ex c = parse_coordinate_expression(map.components[i], params, what);
    if (dims == 2 && c.has(sym.z)) throw InputError(fmt::format("{} uses z, but the surface is 2D", what));
    map.coordinates.push_back(c);
  }
  return map;
}

Surface map_surface(const Surface& surface, const LatticeMap& map) {
  const Symbols& sym = Symbols::get();
  Surface mapped = surface;
  // F(k u, k v, k w) in the cell symbols, then renamed to the natural ones (scale 1).
  GiNaC::lst into_cells, cells_to_natural;
  for (int i = 0; i < surface.dims; ++i) {
    into_cells.append(sym.natural(i) == surface.scale * map.coordinates[static_cast<size_t>(i)]);
    cells_to_natural.append(sym.cell(i) == sym.natural(i));
  }
  mapped.field = surface.field.subs(into_cells).subs(cells_to_natural);
  mapped.scale = 1;
  mapped.name = surface.name + "_" + map.kind;
  mapped.map = map.text;
  std::string formula;
  for (size_t i = 0; i < map.components.size(); ++i)
    formula += fmt::format("{}{} = {}", formula.empty() ? "" : "; ", "uvw"[i], map.components[i]);
  mapped.map_formula = formula;
  mapped.formula = fmt::format("{} at (u, v{}) with {}", surface.formula, surface.dims == 3 ? ", w" : "", formula);
  mapped.title = surface.title + " (mapped)";
  mapped.from_catalog = false;  // not periodic: nothing the catalog knows about it holds
  mapped.singular_measures.clear();
  for (const auto& c : map.coordinates) collect_singular_measures(c.subs(cells_to_natural), mapped.singular_measures);
  return mapped;
}

}  // namespace offsetgen
