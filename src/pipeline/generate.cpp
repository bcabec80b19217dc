#include "pipeline/generate.h"

#include "density/density_model.h"
#include "emit/emitted_api.h"
#include "emit/render.h"
#include "lowering/lower.h"
#include "lowering/program.h"
#include "surfaces/catalog.h"
#include "surfaces/expression_input.h"
#include "surfaces/lattice_map.h"
#include "validate/request_checks.h"
#include "validate/wall_choice.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace offsetgen {
namespace {

void require_identifier(const std::string& name) {
  bool ok = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) throw InputError(fmt::format("--name '{}' is not a C identifier (letters, digits, _)", name));
}

// `language` (a backend's name) tells `offsetgen check` what kind of file it reads.
nlohmann::ordered_json metadata(const GenerationRequest& request, const Generation& g, const Backend& language) {
  const MethodFacts& method = g.method();
  nlohmann::ordered_json j;
  j["format"] = 1;
  j["language"] = language.name();
  j["generator"] = std::string("offsetgen ") + OFFSETGEN_VERSION;
  j["prefix"] = g.prefix;
  j["surface"] = request.surface.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(request.surface);
  j["expression"] = request.expression.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(request.expression);
  j["params"] = request.params;
  j["scale"] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(g.surface.scale)).to_double();
  j["dims"] = g.surface.dims;
  j["method"] = method.method;
  j["order"] = method.order;
  if (method.requested_order != method.order) j["requested_order"] = method.requested_order;
  j["graded_order"] = method.graded_order;
  j["graded_wall_order"] = method.graded_wall_order;
  for (const auto& [key, value] : method.metadata.items()) j[key] = value;
  j["thickness"] = request.thickness ? nlohmann::ordered_json(*request.thickness) : nlohmann::ordered_json();
  if (g.surface.mapped()) {  // only in mapped files, so other files keep their bytes
    j["map"] = g.surface.map;
    j["map_formula"] = g.surface.map_formula;
    const Surface::Box& box = *g.surface.domain;
    std::vector<double> lo(box.lo.begin(), box.lo.begin() + g.surface.dims);
    std::vector<double> hi(box.hi.begin(), box.hi.begin() + g.surface.dims);
    j["domain"] = {lo, hi};
  }
  if (g.density) {  // only in files with density functions, so other files keep their bytes
    j["density"] = density::constants_json(*g.density, false);
    j["wall_density"] = request.density ? nlohmann::ordered_json(*request.density) : nlohmann::ordered_json();
    j["wall_thickness"] = g.wall_thickness ? nlohmann::ordered_json(*g.wall_thickness) : nlohmann::ordered_json();
    j["density_field"] =
        request.density_field ? nlohmann::ordered_json(*request.density_field) : nlohmann::ordered_json();
  }
  std::vector<std::string> precisions;
  for (auto p : language.precisions(request.precisions))
    precisions.push_back(p == Precision::Double ? "double" : "float");
  j["precisions"] = precisions;
  j["gradient_bound"] = g.construction->bounds().gradient;
  j["hessian_bound"] = g.construction->bounds().hessian;
  nlohmann::ordered_json ops;
  for (const auto& f : emitted_functions(g)) ops[f.suffix] = count_ops(*f.program);
  j["ops"] = ops;
  return j;
}

// Parses --density-field as an expression of the cell coordinates.
GiNaC::ex parse_density_field(const GenerationRequest& request, int dims) {
  try {
    return parse_thickness_expression(*request.density_field, request.params, dims);
  } catch (const InputError& e) {
    std::string message = e.what();
    for (auto at = message.find("thickness expression"); at != std::string::npos;
         at = message.find("thickness expression"))
      message.replace(at, 20, "density field");
    throw InputError(fmt::format("--density-field '{}': {}", *request.density_field, message));
  }
}

// rho(p) must lie in (0, rho_max] over the unit cell: sampled on a grid holding every multiple of 1/16.
void check_density_field(const GiNaC::ex& rho, const std::string& text, const density::DensityModel& model) {
  const Symbols& sym = Symbols::get();
  Program program({"x", "y", "z"});
  AtomTable no_atoms;
  Lowerer lowerer(program, no_atoms);
  Environment env;
  env.id = env.shared_id = 1;
  for (int i = 0; i < 3; ++i) env.bindings.emplace_back(sym.cell(i), program.input(i));
  program.add_output("rho", lowerer.lower(rho, env));
  Evaluator evaluate(program);
  constexpr int n = 16;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const std::vector<double> p = {double(i) / n, double(j) / n, double(k) / n};
        const double value = evaluate(p)[0];
        if (!(value > 0) || !(value <= model.sheet_density_limit()))
          throw InputError(fmt::format(
              "--density-field '{}' is {:.6g} at (x, y, z) = ({}, {}, {}): a relative density must lie in (0, "
              "rho_max = {:.6f}] over the cell (rho_max: the sheet thickness reaches the smallest radius of "
              "curvature)",
              text, value + 0.0, p[0], p[1], p[2], model.sheet_density_limit()));  // + 0.0: no "-0"
      }
}

std::vector<const Backend*> requested_backends(const GenerationRequest& request) {
  std::vector<const Backend*> chosen;
  for (const auto& language : request.languages) chosen.push_back(&backend(language));
  return chosen;
}

// Whether any requested file holds float functions (its constants must be printable as floats).
bool emits_float(const GenerationRequest& request) {
  for (const Backend* b : requested_backends(request))
    for (Precision p : b->precisions(request.precisions))
      if (p == Precision::Float) return true;
  return false;
}

}  // namespace

bool wants_density(const GenerationRequest& request) {
  return request.density_functions || request.density || request.density_field;
}

density::DensityModel resolve_density(const GenerationRequest& request, const Surface& surface) {
  if (auto why = density::density_unavailable(surface))
    throw InputError(fmt::format("no density output for {}: {}", surface.name, *why));
  density::DensityModel model(density::surface_constants(surface));
  if (request.density) {
    const double rho = *request.density;
    if (!std::isfinite(rho) || !(rho > 0))
      throw InputError(fmt::format("--density {}: a relative density must be a number > 0", rho));
    if (rho > model.sheet_density_limit())
      throw InputError(fmt::format(
          "--density {} is above rho_max = {:.6f} of {}: its sheet would be thicker than t_max = {:.6f}, where t/2 "
          "reaches the smallest radius of curvature and the thickness no longer determines the density",
          rho, model.sheet_density_limit(), surface.name, model.thickness_limit()));
  }
  return model;
}

std::vector<EmittedFunction> emitted_functions(const Generation& g) {
  return emitted_functions(g.programs, g.surface.dims, g.method(), g.density_programs ? &*g.density_programs : nullptr);
}

namespace {

Surface unmapped_surface(const GenerationRequest& request);

// The request's surface composed with its --map, over its --domain.
Surface mapped_surface(const GenerationRequest& request, const Surface& surface) {
  if (request.map.empty()) {
    if (request.domain)
      throw InputError(
          "--domain applies to a mapped lattice (--map); an unmapped lattice is periodic and is bounded "
          "over one cell");
    return surface;
  }
  Surface mapped = map_surface(surface, parse_lattice_map(request.map, request.params, surface.dims));
  mapped.domain = request.domain;
  mapped.singular_clearance = request.singular_clearance;
  if (request.domain && request.domain->dims != surface.dims)
    throw InputError(fmt::format("--domain has {} coordinates per corner, but the surface is {}D", request.domain->dims,
                                 surface.dims));
  return mapped;
}

}  // namespace

Surface resolve_surface(const GenerationRequest& request) { return mapped_surface(request, unmapped_surface(request)); }

namespace {

Surface unmapped_surface(const GenerationRequest& request) {
  if (!request.surface.empty() && !request.expression.empty())
    throw InputError("give either --surface or --expr, not both");
  if (request.surface.empty() && request.expression.empty())
    throw InputError("no surface given: use --surface NAME (see `offsetgen list`) or --expr EXPRESSION");
  const bool side_expression = request.thickness || request.density_field || !request.map.empty();  // --param too
  if (!request.surface.empty()) {
    if (!request.params.empty() && !side_expression)
      throw InputError("--param only applies to --expr, --thickness and --density-field expressions");
    return catalog_surface(request.surface);
  }
  if (request.name.empty()) throw InputError("--expr needs --name NAME, the stem of the emitted function names");
  require_identifier(request.name);
  std::map<std::string, std::string> surface_params;
  for (const auto& [k, v] : request.params)
    if (request.expression.find(k) != std::string::npos || !side_expression) surface_params[k] = v;
  return parse_user_expression(request.expression, surface_params, request.name);
}

}  // namespace

const OffsetMethod& resolve_method(const GenerationRequest& request) {
  const OffsetMethod& method = offset_method(request.method);
  if (request.order < 1 || request.order > method.max_order())
    throw InputError(fmt::format("order {} is out of range: the {} method supports orders 1 to {}", request.order,
                                 method.name(), method.max_order()));
  return method;
}

std::string default_prefix(const GenerationRequest& request) {
  const int order = resolve_method(request).effective_order(request.order);
  return fmt::format("{}_o{}", resolve_surface(request).name, order);
}

Generation build_generation(const GenerationRequest& request) {
  const OffsetMethod& method = resolve_method(request);
  if (!request.name.empty()) require_identifier(request.name);
  Generation g;
  g.surface = resolve_surface(request);
  g.prefix = request.name.empty() ? fmt::format("{}_o{}", g.surface.name, method.effective_order(request.order))
                                  : request.name;

  check_wall_choice(request.thickness.has_value(), request.density.has_value(), request.density_field.has_value(),
                    WallNeed::Optional);
  LoweringOptions options;
  if (request.thickness)
    options.thickness = parse_thickness_expression(*request.thickness, request.params, g.surface.dims);
  RequestFacts facts_to_check{&g.surface,
                              g.prefix,
                              method.effective_order(request.order),
                              &method,
                              requested_backends(request),
                              emits_float(request),
                              &options.thickness,
                              request.thickness.value_or(""),
                              request.notice};
  check_before_build(facts_to_check);
  if (wants_density(request)) {  // after the cheap checks: the surface constants take seconds
    g.density = resolve_density(request, g.surface);
    g.density_programs = density::density_programs(*g.density);
    if (request.density) options.wall_thickness = g.wall_thickness = g.density->sheet_thickness(*request.density);
    if (request.density_field) {
      const GiNaC::ex rho = parse_density_field(request, g.surface.dims);
      check_density_field(rho, *request.density_field, *g.density);
      options.thickness = density::thickness_for_density_expression(*g.density, rho);
    }
  }
  g.graded_thickness = options.thickness;

  g.construction = method.build(g.surface, request.order);
  g.programs = lower_surface(g.surface, *g.construction, options);
  check_after_build(facts_to_check, *g.construction, g.programs);
  g.metadata_json = metadata(request, g, backend("c")).dump();
  return g;
}

Generation generate(const GenerationRequest& request) {
  Generation g = build_generation(request);
  FileFacts facts;
  facts.prefix = g.prefix;
  facts.command = request.command;
  facts.dims = g.surface.dims;
  facts.surface = &g.surface;
  facts.method = &g.method();
  facts.metadata_json = g.metadata_json;
  if (g.density) facts.density = &*g.density;
  facts.wall_density = request.density;
  facts.wall_thickness = g.wall_thickness;
  facts.density_field = request.density_field;
  auto functions = emitted_functions(g);
  for (const Backend* b : requested_backends(request)) {
    auto name = request.file_names.find(b->name());
    facts.file_name =
        name == request.file_names.end() || name->second.empty() ? g.prefix + "." + b->extension() : name->second;
    facts.metadata_json = metadata(request, g, *b).dump();
    g.files[b->name()] = render_file(*b, facts, functions, request.precisions);
  }
  return g;
}

}  // namespace offsetgen
