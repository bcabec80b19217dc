#include "pipeline/generate.h"

#include "emit/emitted_api.h"
#include "emit/render.h"
#include "lowering/program.h"
#include "surfaces/catalog.h"
#include "surfaces/expression_input.h"
#include "validate/request_checks.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>

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
  std::vector<std::string> precisions;
  for (auto p : language.precisions(request.precisions))
    precisions.push_back(p == Precision::Double ? "double" : "float");
  j["precisions"] = precisions;
  j["gradient_bound"] = g.construction->bounds().gradient;
  j["hessian_bound"] = g.construction->bounds().hessian;
  nlohmann::ordered_json ops;
  for (const auto& f : emitted_functions(g.programs, g.surface.dims, method)) ops[f.suffix] = count_ops(*f.program);
  j["ops"] = ops;
  return j;
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

Surface resolve_surface(const GenerationRequest& request) {
  if (!request.surface.empty() && !request.expression.empty())
    throw InputError("give either --surface or --expr, not both");
  if (request.surface.empty() && request.expression.empty())
    throw InputError("no surface given: use --surface NAME (see `offsetgen list`) or --expr EXPRESSION");
  if (!request.surface.empty()) {
    if (!request.params.empty() && !request.thickness)
      throw InputError("--param only applies to --expr and --thickness expressions");
    return catalog_surface(request.surface);
  }
  if (request.name.empty()) throw InputError("--expr needs --name NAME, the stem of the emitted function names");
  require_identifier(request.name);
  std::map<std::string, std::string> surface_params;
  for (const auto& [k, v] : request.params)
    if (request.expression.find(k) != std::string::npos || !request.thickness) surface_params[k] = v;
  return parse_user_expression(request.expression, surface_params, request.name);
}

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

  LoweringOptions options;
  if (request.thickness)
    options.thickness = parse_thickness_expression(*request.thickness, request.params, g.surface.dims);
  RequestFacts facts_to_check{&g.surface,
                              g.prefix,
                              method.effective_order(request.order),
                              method.cost_grows_geometrically(),
                              requested_backends(request),
                              emits_float(request),
                              &options.thickness,
                              request.thickness.value_or(""),
                              request.notice};
  check_before_build(facts_to_check);

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
  auto functions = emitted_functions(g.programs, g.surface.dims, g.method());
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
