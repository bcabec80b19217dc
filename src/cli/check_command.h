// `offsetgen check FILE`: compile, load and measure an emitted header (or compile a GLSL snippet).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace offsetgen {

struct CheckOptions {
  std::string file;
  std::string h_list;
  std::string json_path;
  std::string plot_path;
  std::string plot_script;
  std::string thickness;
  bool thickness_given = false;  // an empty --thickness is refused, not ignored
  std::vector<std::string> params;
  int grid = 21;
  int scan = 200;
  int points = 0;  // 0: by order (check/value_check.h)
  unsigned seed = 20210415;
  double tolerance = 1e-12;
  double float_tolerance = 2e-4;
  double normal_tolerance = 1e-6;
  double float_normal_tolerance = 1e-3;
  double order_slack = 0.3;
  bool no_values = false;
  bool no_thickness = false;
  bool no_density = false;
  std::string block = "2,2,2";
  double density_tolerance = 2e-4;
  int density_grid = 40, density_shifts = 6;
};

void add_check_command(CLI::App& app, CheckOptions& options);

// Exit codes: kExitOk all checks pass, kExitCheckFailed a check failed, kExitUsage usage or input error,
// kExitNotChecked a tool the check needs is missing.
int run_check(const CheckOptions& options);

// Whether `offsetgen check` was given a STEP file (.step or .stp, any case): offsetgen-step checks
// those, since only it loads OpenCASCADE.
bool names_a_step_file(const std::string& path);

}  // namespace offsetgen
