#include "cli/step_command.h"

#include "cli/cells_option.h"
#include "cli/command_line.h"
#include "step/step_export.h"
#include "surfaces/expression_input.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <unistd.h>

#include <cstdio>

namespace offsetgen {

int run_step_command(const StepOptions& o) {
  step::StepRequest r;
  r.wall.generation = generation_request(o);
  if (o.thickness.empty() == !o.density.has_value())
    throw InputError("give one of --thickness T (cell units) and --density R: each one sets the wall's thickness");
  r.wall.thickness = o.thickness;
  r.wall.generation.density = o.density;
  r.cells = parse_cells(o.cells);
  r.cell_size = o.cell_size;
  r.tolerance = o.tolerance;
  r.output = o.output;
  if (o.max_control_points < 4) throw InputError("--max-control-points: a cubic patch needs at least 4 a side");
  r.max_control_points = o.max_control_points;
  r.patches = o.patches;
  const step::StepSummary s = step::export_step(r, [&](const std::string& stage) {
    if (!o.quiet) std::fprintf(stderr, "[offsetgen step] %s\n", stage.c_str());
  });
  if (!o.quiet || !s.written) std::fputs(step::format_summary(s, r).c_str(), s.written ? stdout : stderr);
  return s.written ? kExitOk : kExitCheckFailed;
}

int run_step_check(const std::string& path) {
  const bool progress = ::isatty(::fileno(stderr)) != 0;  // as check of generated code: on a terminal only
  const step::StepCheck c = step::check_step_file(path, [progress](const std::string& stage) {
    if (progress) std::fprintf(stderr, "[offsetgen check] %s\n", stage.c_str());
  });
  std::fputs(step::format_check_summary(c, path).c_str(), stdout);
  return c.summary.written ? kExitOk : kExitCheckFailed;
}

}  // namespace offsetgen
