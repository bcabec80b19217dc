#include "check/reference.h"

#include "field/atom_table.h"
#include "lowering/lower.h"
#include "surfaces/expression_input.h"
#include "surfaces/expression_syntax.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace offsetgen::check {
namespace {

bool close(double a, double b, double rel) { return std::fabs(a - b) <= rel * std::max(std::fabs(a), std::fabs(b)); }

}  // namespace

std::unique_ptr<Reference> rebuild_reference(const run::FileMetadata& meta) {
  GenerationRequest request;
  if (meta.surface) request.surface = *meta.surface;
  if (meta.expression) request.expression = *meta.expression;
  request.params = meta.params;
  request.order = meta.order;
  request.method = meta.method;
  request.thickness = meta.thickness;
  if (meta.map) {
    request.map = *meta.map;
    Surface::Box box;
    box.lo = (*meta.domain)[0];
    box.hi = (*meta.domain)[1];
    box.dims = meta.dims;
    request.domain = box;
  }
  request.density_functions = meta.has_density;
  request.density = meta.wall_density;
  request.density_field = meta.density_field;
  // The file's own language: its names need only be valid there.
  request.languages = {meta.language};
  const std::string default_prefix = meta.surface ? fmt::format("{}_o{}", *meta.surface, meta.order) : "";
  if (meta.expression || meta.prefix != default_prefix) request.name = meta.prefix;
  if (meta.expression && meta.prefix.empty()) request.name = "surface";

  auto ref = std::make_unique<Reference>();
  try {
    ref->generation = build_generation(request);
  } catch (const InputError& e) {
    throw InputError(fmt::format("the file's metadata cannot be rebuilt by this offsetgen: {}", e.what()));
  }
  const Generation& g = ref->generation;
  if (g.surface.dims != meta.dims)
    throw InputError(fmt::format("the metadata block is inconsistent: it says dims = {}, but its surface is {}D",
                                 meta.dims, g.surface.dims));
  const double scale = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(g.surface.scale)).to_double();
  if (!close(scale, meta.scale, 1e-15))
    throw InputError(
        fmt::format("the metadata block is inconsistent: scale {} but the surface has k = {}", meta.scale, scale));
  if (g.order() != meta.order)
    throw InputError(
        fmt::format("the metadata block is inconsistent: order {} but the {} method builds order {} "
                    "for it",
                    meta.order, meta.method, g.order()));
  if (!close(g.construction->bounds().gradient, meta.gradient_bound, 1e-12))
    ref->warnings.push_back(
        fmt::format("gradient bound differs: file M = {:.17g}, regenerated M = {:.17g}; the "
                    "regenerated model is the reference",
                    meta.gradient_bound, g.construction->bounds().gradient));
  if (!meta.generator.empty() && meta.generator != std::string("offsetgen ") + OFFSETGEN_VERSION)
    ref->warnings.push_back(
        fmt::format("the file was written by {}, this is offsetgen {}", meta.generator, OFFSETGEN_VERSION));
  if (!meta.ops.empty()) {
    nlohmann::json regenerated = nlohmann::json::parse(g.metadata_json);
    if (auto it = regenerated.find("ops"); it != regenerated.end()) {
      for (const auto& [name, count] : meta.ops) {
        auto r = it->find(name);
        if (r != it->end() && r->is_number_integer() && r->get<int>() != count) {
          ref->warnings.push_back(
              fmt::format("op counts differ from a fresh generation ({}: file {}, now {}): the file "
                          "was made by another version or edited by hand",
                          name, count, r->get<int>()));
          break;
        }
      }
    }
  }
  return ref;
}

GiNaC::ex parse_thickness(const std::string& text, const run::FileMetadata& meta,
                          const std::map<std::string, std::string>& extra) {
  std::map<std::string, std::string> params = meta.params;
  for (const auto& [k, v] : extra) params[k] = v;
  if (auto problem = find_syntax_problem(text))
    throw InputError(fmt::format("--thickness: the expression does not parse: {} at column {}:\n{}", problem->message,
                                 problem->column, caret_line(text, problem->column, 4)));
  try {
    return parse_thickness_expression(text, params, meta.dims);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--thickness '{}': {}", text, e.what()));
  }
}

ThicknessFunction::ThicknessFunction(const GiNaC::ex& t_cell, int dims)
    : expression_(t_cell), dims_(dims), inputs_(static_cast<size_t>(dims)) {
  std::vector<std::string> names = {"x", "y"};
  if (dims == 3) names.push_back("z");
  program_ = Program(names);
  AtomTable no_atoms;
  Lowerer lowerer(program_, no_atoms);
  Environment env;
  env.id = env.shared_id = 1;
  for (int i = 0; i < dims; ++i) env.bindings.emplace_back(Symbols::get().cell(i), program_.input(i));
  program_.add_output("t", lowerer.lower(t_cell, env));
  evaluator_ = std::make_unique<Evaluator>(program_);
}

double ThicknessFunction::operator()(const double* p) {
  for (int i = 0; i < dims_; ++i) inputs_[static_cast<size_t>(i)] = p[i];
  return (*evaluator_)(inputs_).at(0);
}

}  // namespace offsetgen::check
