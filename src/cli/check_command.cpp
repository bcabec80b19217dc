#include "cli/check_command.h"

#include "check/check.h"
#include "check/plot.h"
#include "check/report.h"
#include "cli/command_line.h"
#include "emit/backend.h"
#include "emit/file_writer.h"
#include "run/runner.h"
#include "surfaces/expression_input.h"
#include "surfaces/surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace offsetgen {

namespace {

// The help names every target that check can run, as the runner registry has them.
std::string check_description() {
  std::string text =
      "Check an emitted file: run it, compare its values with a 40-digit evaluation and, for C, measure the\n"
      "wall thickness it produces (paper section 5.2.1). The file's target comes from its metadata, not\n"
      "its name. By target:";
  for (const run::Runner* runner : run::runners())
    text += fmt::format("\n  {} (.{}): {}.", runner->backend(), backend(runner->backend()).extension(), runner->how());
  return text;
}

std::string checkable_extensions() {
  std::string list;
  for (const run::Runner* runner : run::runners())
    list += (list.empty() ? "." : ", .") + backend(runner->backend()).extension();
  return list;
}

}  // namespace

bool names_a_step_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".step" || ext == ".stp";
}

void add_check_command(CLI::App& app, CheckOptions& o) {
  CLI::App* cmd = app.add_subcommand("check", check_description());
  cmd->add_option("file", o.file,
                  "A file written by `offsetgen generate` (" + checkable_extensions() +
                      "), or a .step file written by `offsetgen step` (offsetgen-step measures it: one valid "
                      "closed solid, the exact walls within its tolerance, its volume)")
      ->required();
  cmd->add_option("--h", o.h_list,
                  "Offsets to measure, comma-separated, cell units (default 0.001..0.1, 9 log-spaced)");
  cmd->add_option("--json", o.json_path, "Write every number to this JSON file");
  cmd->add_option("--plot", o.plot_path, "Write a log-log convergence figure (PNG) via tools/plot_convergence.py");
  cmd->add_option("--plot-script", o.plot_script,
                  "Path of plot_convergence.py (default: $OFFSETGEN_PLOT_SCRIPT, <prefix>/share/offsetgen/tools, "
                  "the source tree)");
  cmd->add_option("-t,--thickness", o.thickness,
                  "Graded wall: total thickness t(x, y, z) > 0 in cell units, e.g. \"0.1*x\" (default: the file's)")
      ->each([&o](const std::string&) { o.thickness_given = true; });
  cmd->add_option("-p,--param", o.params, "NAME=VALUE for the thickness expression (repeatable)");
  cmd->add_option("--grid", o.grid, "Sample grid points per axis on [0, 1] (21: step 0.05 as in the paper)")
      ->check(CLI::Range(2, 401));
  cmd->add_option("--scan", o.scan, "Bracketing sub-intervals along z when sampling a surface")
      ->check(CLI::Range(4, 100000));
  cmd->add_option("--points", o.points,
                  "Random points of the 40-digit value check (default 200; 60 at orders 5-6, 16 above)")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--seed", o.seed, "Seed of the random points");
  cmd->add_option("--tolerance", o.tolerance, "Max zero-set shift of the double functions (cell units)")
      ->capture_default_str();
  cmd->add_option("--float-tolerance", o.float_tolerance,
                  "Max zero-set shift of the float32 functions (C float twins, GLSL on llvmpipe)")
      ->capture_default_str();
  cmd->add_option("--normal-tolerance", o.normal_tolerance, "Max |delta n| of the double normal")
      ->capture_default_str();
  cmd->add_option("--float-normal-tolerance", o.float_normal_tolerance, "Max |delta n| of the float32 normal")
      ->capture_default_str();
  cmd->add_option("--order-slack", o.order_slack, "Fitted order must reach the expected order minus this");
  cmd->add_flag("--no-values", o.no_values, "Skip the 40-digit value check");
  cmd->add_flag("--no-thickness", o.no_thickness, "Skip the wall-thickness measurement");
  cmd->add_flag("--no-density", o.no_density, "Skip the volume fractions of files with density functions");
  cmd->add_option("--block", o.block,
                  "Cells NX,NY,NZ of the block whose per-cell volume fraction is compared with a density field")
      ->capture_default_str();
  cmd->add_option("--density-grid", o.density_grid,
                  "Columns per side per axis of each random shift when measuring volume fractions")
      ->check(CLI::Range(4, 400))
      ->capture_default_str();
  cmd->add_option("--density-shifts", o.density_shifts,
                  "Random shifts of the grid of columns (their spread gives the stated error)")
      ->check(CLI::Range(2, 100))
      ->capture_default_str();
  cmd->add_option("--density-tolerance", o.density_tolerance,
                  "Largest |measured - requested| volume fraction (each density, each cell)")
      ->capture_default_str();
  cmd->footer(
      "Exit status: 0 all checks pass, 1 a check failed (compile error, numbers out of bound: the file is wrong),\n"
      "2 usage or input error (not an offsetgen file, damaged metadata, bad --thickness), 4 not checked: a tool\n"
      "the check needs is missing (a C compiler, glslang, nvcc, node and Dawn's bindings, python3 with NumPy, an\n"
      "OpenCL platform); the message names it and how to get it.\n"
      "Example: offsetgen check gyroid_o4.h --json gyroid_o4.json --plot gyroid_o4.png");
}

namespace {

std::array<int, 3> parse_block(const std::string& text) {
  std::array<int, 3> block{};
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d%c", &block[0], &block[1], &block[2], &extra) != 3)
    throw InputError(fmt::format("--block '{}': expected three cell counts NX,NY,NZ, e.g. 4,1,1", text));
  for (int n : block)
    if (n < 1 || n > 16) throw InputError(fmt::format("--block '{}': each count must be 1 to 16", text));
  return block;
}

}  // namespace

int run_check(const CheckOptions& o) {
  check::CheckRequest s;
  s.file = o.file;
  if (!o.h_list.empty()) s.h = check::parse_h_list(o.h_list);
  if (o.thickness_given) s.thickness = o.thickness;
  s.params = parse_params(o.params);
  s.json_path = o.json_path;
  s.plot_path = o.plot_path;
  s.plot_script = o.plot_script;
  s.grid = o.grid;
  s.scan = o.scan;
  s.values.points = o.points;
  s.values.seed = o.seed;
  s.values.tolerance = o.tolerance;
  s.values.float_tolerance = o.float_tolerance;
  s.values.normal_tolerance = o.normal_tolerance;
  s.values.float_normal_tolerance = o.float_normal_tolerance;
  s.order_slack = o.order_slack;
  s.run_values = !o.no_values;
  s.run_thickness = !o.no_thickness;
  s.run_density = !o.no_density;
  s.density.tolerance = s.density.cell_tolerance = o.density_tolerance;
  s.density.block = parse_block(o.block);
  s.density.sampling.grid = o.density_grid;
  s.density.sampling.shifts = o.density_shifts;
  // Outputs that cannot be written, or that name one file twice, are usage errors before the long run.
  std::vector<std::string> outputs;
  for (const auto* path : {&s.json_path, &s.plot_path})
    if (!path->empty()) outputs.push_back(*path);
  try {
    for (const auto& path : outputs) require_writable(path);
    require_distinct(outputs);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}{}", outputs.size() == 1 && !s.json_path.empty() ? "--json: " : "", e.what()));
  }
  // Find the plot script before the long run, so a missing one is a quick usage error.
  std::string script;
  if (!s.plot_path.empty()) {
    script = check::find_plot_script(s.plot_script);
    if (script.empty())
      throw InputError(
          fmt::format("--plot: plot_convergence.py not found{}; pass --plot-script PATH or set "
                      "$OFFSETGEN_PLOT_SCRIPT",
                      s.plot_script.empty() ? "" : " at " + s.plot_script));
  }

  check::CheckReport report;
  try {
    report = check::run_checks(s);
  } catch (const ToolMissing& e) {
    // The file may be fine: this machine cannot run it. Not a failure of the file, not bad input.
    fmt::print(stderr, "offsetgen check: not checked: {}\n", e.what());
    return kExitNotChecked;
  }
  std::fputs(check::format_report(report).c_str(), stdout);
  std::fflush(stdout);
  if (!s.json_path.empty()) {
    try {
      write_file_if_changed(s.json_path, check::report_json(report).dump(1) + "\n");
    } catch (const std::runtime_error& e) {
      throw InputError(fmt::format("--json: {}", e.what()));
    }
  }
  if (!s.plot_path.empty()) {
    if (report.thickness) {
      check::render_plot(check::plot_spec(report), s.plot_path, script);
    } else {
      fmt::print(stderr, "offsetgen check: --plot: nothing to plot (no thickness measurement ran)\n");
    }
  }
  return report.pass ? kExitOk : kExitCheckFailed;
}

}  // namespace offsetgen
