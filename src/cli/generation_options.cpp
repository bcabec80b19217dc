#include "cli/generation_options.h"

#include "surfaces/expression_input.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

namespace offsetgen {

void add_generation_options(CLI::App* cmd, GenerationOptions& o, const std::string& surface_help,
                            const std::string& expression_help) {
  cmd->add_option("-s,--surface", o.surface, surface_help);
  cmd->add_option("-e,--expr", o.expression, expression_help);
  cmd->add_option("-p,--param", o.params, "Constant parameter NAME=VALUE of --expr/--thickness (repeatable)");
  cmd->add_option("-n,--name", o.name, "Function prefix of the generated functions (default <surface>_o<order>)");
  std::string methods;
  for (const OffsetMethod* m : offset_methods()) methods += fmt::format("{}{}", methods.empty() ? "" : ", ", m->name());
  cmd->add_option("-M,--method", o.method, "Offset construction: " + methods)->capture_default_str();
  cmd->add_option("-m,--order", o.order, "Approximation order")->capture_default_str();
}

GenerationRequest generation_request(const GenerationOptions& o) {
  GenerationRequest r;
  r.surface = o.surface;
  r.expression = o.expression;
  r.name = o.name;
  r.method = o.method;
  r.order = o.order;
  r.params = parse_params(o.params);
  return r;
}

}  // namespace offsetgen
