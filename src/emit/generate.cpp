#include "emit/generate.h"

#include "emit/c_emitter.h"
#include "emit/emitted_api.h"
#include "emit/glsl_emitter.h"
#include "lowering/program.h"
#include "surfaces/catalog.h"
#include "surfaces/expression_input.h"
#include "validate/request_checks.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace offsetgen {
namespace {

void require_identifier(const std::string& name) {
  bool ok = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) throw InputError(fmt::format("--name '{}' is not a C identifier (letters, digits, _)", name));
}

// `language` ("c" or "glsl") tells `offsetgen check` what kind of file it reads.
nlohmann::ordered_json metadata(const GenerationRequest& request, const Generation& g, const char* language) {
  nlohmann::ordered_json j;
  j["format"] = 1;
  j["language"] = language;
  j["generator"] = std::string("offsetgen ") + OFFSETGEN_VERSION;
  j["prefix"] = g.prefix;
  j["surface"] = request.surface.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(request.surface);
  j["expression"] = request.expression.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(request.expression);
  j["params"] = request.params;
  j["scale"] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(g.surface.scale)).to_double();
  j["dims"] = g.surface.dims;
  j["order"] = request.order;
  j["thickness"] = request.thickness ? nlohmann::ordered_json(*request.thickness) : nlohmann::ordered_json();
  std::vector<std::string> precisions;
  for (auto p : request.precisions) precisions.push_back(p == Precision::Double ? "double" : "float");
  if (std::string(language) == "glsl") precisions = {"float"};
  j["precisions"] = precisions;
  j["gradient_bound"] = g.programs.gradient_bound;
  j["hessian_bound"] = g.programs.hessian_bound;
  nlohmann::ordered_json ops;
  for (const auto& f : emitted_functions(g.programs, g.surface.dims)) ops[f.suffix] = count_ops(*f.program);
  j["ops"] = ops;
  return j;
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

Generation generate(const GenerationRequest& request) {
  if (request.order < 1 || request.order > kMaxOrder)
    throw InputError(fmt::format("order {} is out of range: offsetgen supports orders 1 to {}", request.order, kMaxOrder));
  if (!request.name.empty()) require_identifier(request.name);
  Generation g;
  g.surface = resolve_surface(request);
  g.prefix = request.name.empty() ? fmt::format("{}_o{}", g.surface.name, request.order) : request.name;

  LoweringOptions options;
  if (request.thickness) options.thickness = parse_thickness_expression(*request.thickness, request.params, g.surface.dims);
  RequestFacts facts_to_check{&g.surface, g.prefix, request.order, request.c, request.glsl,
                              std::count(request.precisions.begin(), request.precisions.end(), Precision::Float) > 0,
                              &options.thickness, request.thickness.value_or(""), request.notice};
  check_before_build(facts_to_check);

  g.model = build_offset_model(g.surface, request.order, /*with_gradient=*/true);
  g.programs = lower_surface(g.surface, g.model, options);
  check_after_build(facts_to_check, g.programs);
  g.metadata_json = metadata(request, g, "c").dump();

  FileFacts facts;
  facts.prefix = g.prefix;
  facts.command = request.command;
  facts.order = request.order;
  facts.dims = g.surface.dims;
  facts.surface = &g.surface;
  facts.gradient_bound = g.programs.gradient_bound;
  facts.hessian_bound = g.programs.hessian_bound;
  facts.metadata_json = g.metadata_json;
  auto functions = emitted_functions(g.programs, g.surface.dims);
  if (request.c) {
    facts.file_name = request.c_file_name.empty() ? g.prefix + ".h" : request.c_file_name;
    g.c_header = emit_c_header(facts, functions, request.precisions);
  }
  if (request.glsl) {
    facts.file_name = request.glsl_file_name.empty() ? g.prefix + ".glsl" : request.glsl_file_name;
    facts.metadata_json = metadata(request, g, "glsl").dump();
    g.glsl_snippet = emit_glsl_snippet(facts, functions);
  }
  return g;
}

}  // namespace offsetgen
