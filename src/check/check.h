// `offsetgen check FILE`: the second stage. Reads the file's metadata, has the runner of its target
// (run/runner.h) compile, load or launch it, rebuilds the symbolic model, compares values with a
// 40-digit evaluation, measures the wall thickness (paper section 5.2.1) and judges the numbers.
#pragma once

#include "check/density_check.h"
#include "check/lipschitz.h"
#include "check/thickness.h"
#include "check/value_check.h"
#include "run/metadata.h"
#include "run/runner.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::check {

struct CheckRequest {
  std::string file;
  std::vector<double> h;                      // sweep, cell units (default: default_sweep())
  std::optional<std::string> thickness;       // graded wall t(x) (overrides the file's)
  std::map<std::string, std::string> params;  // for the thickness expression
  std::string json_path;
  std::string plot_path;
  std::string plot_script;
  int grid = 21;
  int scan = 200;
  ValueCheckOptions values;
  double order_slack = 0.3;  // fitted order must reach expected - slack
  bool run_values = true;
  bool run_thickness = true;
  bool run_density = true;  // files with density functions: volume fractions (density_check.h)
  DensityCheckOptions density;
};

// 0.001 * 10^(k/4), k = 0..8: 0.001 ... 0.1, nine points, 0.01 included.
std::vector<double> default_sweep();

// "0.001,0.01, 0.1" -> values; throws InputError naming the bad entry. Each must be in (0, 0.5].
std::vector<double> parse_h_list(const std::string& text);

struct Verdict {
  std::string name;
  bool pass = true;
  bool judged = true;  // false: reported only
  std::string detail;
};

struct CheckReport {
  std::string file;
  run::FileMetadata meta;
  std::vector<std::string> warnings;
  std::string surface_title;
  run::Prepared prepared;  // what the file's runner compiled, loaded or launched (run/runner.h)
  run::ValueWords words;   // how the report names its value check
  std::optional<ValueReport> values;
  std::optional<ThicknessReport> thickness;
  bool thickness_float_only = false;
  std::optional<GradedReport> graded;
  std::vector<LipschitzRow> lipschitz;  // the method's documented bounds, measured
  std::optional<DensityReport> density;
  std::vector<Verdict> verdicts;
  std::vector<double> sweep;
  bool pass = false;
};

// Runs everything. Throws InputError for usage and input problems (exit 2); a failed check comes
// back as report.pass == false (exit 1).
CheckReport run_checks(const CheckRequest& settings);

}  // namespace offsetgen::check
