#include "cli/step_command.h"

#include "cli/cells_option.h"
#include "cli/command_line.h"
#include "step/step_check.h"
#include "step/step_export.h"
#include "surfaces/expression_input.h"

#include <fmt/format.h>

#include <unistd.h>

#include <cstdio>

namespace offsetgen {

int run_step_command(const StepOptions& o) {
  step::StepRequest r;
  // The options as given: export_step validates the request (step_request.h).
  r.wall.generation = generation_request(o);
  r.wall.thickness = o.thickness;
  r.wall.generation.density = o.density;
  r.cells = parse_cells(o.cells);
  r.cell_size = parse_cell_size(o.cell_size);
  r.tolerance = o.tolerance;
  r.output = o.output;
  r.max_control_points = o.max_control_points;
  r.patches = step::patches_from_name(o.patches);
  r.body = body_request(o.body);
  const step::StepSummary s = step::export_step(r, [&](const std::string& stage) {
    if (!o.quiet) std::fprintf(stderr, "[offsetgen step] %s\n", stage.c_str());
  });
  if (!o.quiet || !s.passed) std::fputs(step::format_summary(s, r).c_str(), s.passed ? stdout : stderr);
  return s.passed ? kExitOk : kExitCheckFailed;
}

int run_step_check(const std::string& path) {
  const bool progress = ::isatty(::fileno(stderr)) != 0;  // as check of generated code: on a terminal only
  const step::StepCheck c = step::check_step_file(path, [progress](const std::string& stage) {
    if (progress) std::fprintf(stderr, "[offsetgen check] %s\n", stage.c_str());
  });
  std::fputs(step::format_check_summary(c, path).c_str(), stdout);
  return c.summary.passed ? kExitOk : kExitCheckFailed;
}

}  // namespace offsetgen
