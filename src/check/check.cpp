#include "check/check.h"

#include "check/domain_cube.h"
#include "check/reference.h"
#include "emit/backend.h"
#include "support/progress_line.h"
#include "validate/cell_domain.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

namespace offsetgen::check {
namespace {

Verdict order_verdict(const std::string& name, const OrderFit& fit, double expected, double slack, bool judged) {
  Verdict v;
  v.name = name;
  v.judged = judged;
  if (!fit.fitted) {
    v.pass = true;
    v.detail = fit.note.empty() ? "not fitted" : fit.note;
    return v;
  }
  v.pass = !judged || fit.slope >= expected - slack;
  v.detail = fmt::format("fitted order {:.2f} over h = {:g}..{:g} ({} points), expected >= {:.2f}{}", fit.slope,
                         fit.h_min, fit.h_max, fit.points, expected - slack, judged ? "" : " (reported, not judged)");
  return v;
}

// Rays without a crossing are judged up to the sweep's geometric middle.
double crossing_limit(const std::vector<double>& sweep) { return std::sqrt(sweep.front() * sweep.back()); }

// Rays without a crossing inside the fitted (small-h) range fail the check; beyond it they are
// reported (large h on strongly curved surfaces leaves the method's validity range).
Verdict missed_verdict(const std::string& name, const std::vector<std::pair<double, const ErrorStats*>>& rows,
                       double h_limit) {
  Verdict v;
  v.name = name;
  int inside = 0, outside = 0, rays = 0;
  for (const auto& [h, stats] : rows) {
    rays += stats->rays;
    (h <= h_limit * (1 + 1e-12) ? inside : outside) += stats->missed;
  }
  v.pass = inside == 0;
  v.detail = fmt::format("{} of {} rays without a crossing for h <= {:g}, {} beyond", inside, rays, h_limit, outside);
  return v;
}

void add_density_verdicts(const DensityReport& d, std::vector<Verdict>& verdicts) {
  // Double: a few rounding errors of the cubic and its Newton steps. Float: the same in float's
  // epsilon, amplified by the inverse's conditioning near the limits.
  constexpr double kDoubleLimit = 1e-12, kFloatLimit = 1e-5;
  verdicts.push_back(
      {"density relations",
       d.max_relation_error <= kDoubleLimit && d.max_float_relation_error <= kFloatLimit && d.nan_failures == 0, true,
       fmt::format("emitted vs model: max relative difference {:.1e} (limit {:.0e}){}{}; {} out-of-range "
                   "argument(s) without NaN{}",
                   d.max_relation_error, kDoubleLimit, d.worst_relation.empty() ? "" : " at " + d.worst_relation,
                   d.has_float ? fmt::format(", float {:.1e} (limit {:.0e}){}", d.max_float_relation_error, kFloatLimit,
                                             d.worst_float_relation.empty() ? "" : " at " + d.worst_float_relation)
                               : std::string(),
                   d.nan_failures, d.nan_failure_examples.empty() ? "" : ": " + d.nan_failure_examples[0])});
  for (const DensityRow& row : d.rows)
    verdicts.push_back({fmt::format("density {} {:g}", row.solid, row.requested),
                        std::fabs(row.deviation) <= d.tolerance, true,
                        fmt::format("volume fraction {:.6f} +- {:.1e} (column integration), {} {:.6f}: deviation "
                                    "{:+.1e} (limit {:.0e})",
                                    row.measured.value, row.measured.standard_error, row.solid == "network" ? "h" : "t",
                                    row.parameter, row.deviation, d.tolerance)});
  if (!d.cells.empty()) {
    const DensityCellRow* worst = &d.cells.front();
    for (const DensityCellRow& c : d.cells)
      if (std::fabs(c.deviation) > std::fabs(worst->deviation)) worst = &c;
    verdicts.push_back(
        {"density field cells", std::fabs(worst->deviation) <= d.cell_tolerance, true,
         fmt::format("{} cells: largest deviation {:+.1e} in cell ({}, {}, {}) (requested mean {:.6f}, "
                     "measured {:.6f} +- {:.1e}; limit {:.0e})",
                     d.cells.size(), worst->deviation, worst->cell[0], worst->cell[1], worst->cell[2], worst->requested,
                     worst->measured.value, worst->measured.standard_error, d.cell_tolerance)});
  }
}

// Every function against its own tolerance: the verdict names those out of it.
Verdict values_verdict(const std::string& name, const ValueReport& values) {
  Verdict v{name, values.pass, true, ""};
  std::string failed;
  for (const auto& f : values.functions) {
    if (f.pass) continue;
    failed += fmt::format("{}{} {:.2e} > {:.0e}", failed.empty() ? "" : "; ", f.function, f.max_shift, f.tolerance);
  }
  v.detail = values.pass
                 ? fmt::format("{} functions within their tolerance", values.functions.size())
                 : (values.functions.empty() ? std::string("no function was compared") : "out of tolerance: " + failed);
  return v;
}

// What every value check starts from: the 40-digit reference rebuilt from the file's metadata (its
// warnings and the surface's title go into the report), and the value options, which show each
// point on the progress line.
struct ValueCheckSetup {
  std::unique_ptr<Reference> reference;
  ValueCheckOptions options;
};

ValueCheckSetup prepare_value_check(const CheckRequest& s, ProgressLine& progress, CheckReport& report) {
  progress.show("model: rebuilding the symbolic offset model from the metadata");
  ValueCheckSetup setup{rebuild_reference(report.meta), s.values};
  report.warnings.insert(report.warnings.end(), setup.reference->warnings.begin(), setup.reference->warnings.end());
  report.surface_title = setup.reference->generation.surface.title;
  setup.options.progress = [&progress, &s](int done, int total) {
    progress.show(fmt::format("values: point {}/{} against {}-digit CLN", done + 1, total, s.values.digits));
  };
  return setup;
}

// The thickness expressions a check reads: the one to measure (--thickness, else the file's), and the
// file's own, which its _graded function was built with. Parsed first, so that a bad expression is
// refused before any long work.
struct WallThickness {
  std::optional<GiNaC::ex> measured;
  std::optional<std::string> measured_text;
  std::optional<GiNaC::ex> file;
};

WallThickness read_thickness(const CheckRequest& s, const run::FileMetadata& meta) {
  WallThickness w;
  w.measured_text = s.thickness ? s.thickness : meta.thickness;
  if (w.measured_text) w.measured = parse_thickness(*w.measured_text, meta, s.params);
  if (s.thickness) require_positive_thickness(*w.measured, meta.dims, *s.thickness);  // as generate does
  if (meta.thickness) w.file = parse_thickness(*meta.thickness, meta, {});
  return w;
}

// The runner of the file's target, found through the backend registry (run/runner.h).
const run::Runner& runner_for(const run::FileMetadata& meta) {
  const run::Runner* runner = run::find_runner(meta.language);
  if (runner == nullptr)
    throw InputError(
        fmt::format("offsetgen check cannot run {} files here (language \"{}\"); the test suite "
                    "compiles them (see README)",
                    backend(meta.language).title(), meta.language));
  return *runner;
}

// The runner's outcomes become verdicts, its warnings the report's.
void record_preparation(CheckReport& report) {
  for (const run::Outcome& o : report.prepared.outcomes) report.verdicts.push_back({o.name, o.pass, true, o.detail});
  report.warnings.insert(report.warnings.end(), report.prepared.warnings.begin(), report.prepared.warnings.end());
}

// The runner compiles, loads or launches the file; its outcomes and warnings go into the report.
void prepare(const CheckRequest& s, const std::string& text, const run::Runner& runner, ProgressLine& progress,
             CheckReport& report) {
  report.prepared = runner.prepare(
      s.file, text, report.meta,
      [&progress](const std::string& stage, const std::string& what) { progress.show(stage + ": " + what); });
  progress.clear();
  record_preparation(report);
}

// A shader, module or kernel: its lanes against the 40-digit reference, each within the limits of its
// precision. The thickness sweep and the density relations are left to the C header of the same
// generation.
void check_lane_values(const CheckRequest& s, const WallThickness& walls, CheckReport& report) {
  ProgressLine progress("[offsetgen check]");
  ValueCheckSetup setup = prepare_value_check(s, progress, report);
  const std::string& verdict = report.words.verdict;
  if (report.prepared.cannot_run) {
    report.verdicts.push_back({verdict, false, true, *report.prepared.cannot_run});
  } else {
    Implementations impl;
    impl.lanes = report.prepared.lanes;
    try {
      report.values = check_values(impl, *setup.reference, report.meta, walls.file, setup.options);
      report.verdicts.push_back(values_verdict(verdict, *report.values));
    } catch (const std::runtime_error& e) {
      report.verdicts.push_back({verdict, false, true, fmt::format("{}: {}", report.words.failure, e.what())});
    }
  }
  progress.clear();
}

// Item 3: the paper's ray measurement of the constant wall, its convergence orders, and the rays that
// found no crossing.
void check_constant_wall(const CheckRequest& s, const Probe& probe, const ThicknessOptions& options,
                         CheckReport& report) {
  report.thickness = measure_constant(probe, options);
  const ThicknessReport& t = *report.thickness;
  const run::FileMetadata& meta = report.meta;
  const double m = meta.order;
  // Beyond order 4 much of the asymptotic range lies under the double-precision floor: a slope is
  // judged there only when at least 3 sweep points lie above the floor.
  auto judge = [&](const OrderFit& fit) { return !probe.float_only && (meta.order <= 4 || fit.points >= 3); };
  report.verdicts.push_back(order_verdict("order F -> phi", t.fit_f_to_phi, m, s.order_slack, judge(t.fit_f_to_phi)));
  report.verdicts.push_back(order_verdict("order phi -> F", t.fit_phi_to_f, m, s.order_slack, judge(t.fit_phi_to_f)));
  report.verdicts.push_back(order_verdict("order shell", t.fit_shell, m, s.order_slack, judge(t.fit_shell)));
  std::vector<std::pair<double, const ErrorStats*>> rays;
  for (const auto& row : t.rows) {
    rays.emplace_back(row.h, &row.f_to_phi);
    rays.emplace_back(row.h, &row.phi_to_f);
    rays.emplace_back(row.h, &row.shell);
  }
  report.verdicts.push_back(missed_verdict("crossings", rays, crossing_limit(report.sweep)));
}

// The method's documented Lipschitz bounds, measured in the band |F| <= M|h|.
void check_lipschitz(const Probe& probe, const Reference& reference, CheckReport& report) {
  const MethodFacts& facts = reference.generation.method();
  // Through a mapped file's domain cube, lengths are in sides of the cube: gradients scale by it.
  const double scale = report.meta.scale * domain_cube(report.meta).side;
  report.lipschitz =
      measure_lipschitz(probe, facts.lipschitz_bounds, reference.generation.construction->bounds().gradient, scale);
  for (const LipschitzRow& row : report.lipschitz)
    report.verdicts.push_back({fmt::format("lipschitz |h| <= {:g}", row.h), row.pass, !probe.float_only,
                               fmt::format("max |grad phi| {:.4g} over {} points of the band |F| <= M|h|, "
                                           "documented bound {:.4g}",
                                           row.measured, row.points, row.bound)});
}

// The graded wall t(x): its total, one-sided and paper orders against those the file's method
// promises (offset/method.h, MethodFacts), and its rays without a crossing.
void check_graded_wall(const CheckRequest& s, Probe probe, const Reference& reference, const WallThickness& walls,
                       bool compiled, const ThicknessOptions& options, CheckReport& report) {
  const run::FileMetadata& meta = report.meta;
  ThicknessFunction tfun(*walls.measured, meta.dims);
  const Generation& g0 = reference.generation;
  auto wall_program = std::make_shared<Program>(lower_graded_wall(g0.surface, *g0.construction, *walls.measured));
  auto wall = std::make_shared<Evaluator>(*wall_program);
  probe.graded_wall = [wall_program, wall, dims = meta.dims](const double* q, double s_value) {
    std::vector<double> in(q, q + dims);
    in.push_back(s_value);
    return (*wall)(in).at(0);
  };
  report.graded = measure_graded(probe, tfun, *walls.measured_text, compiled, options);
  const GradedReport& g = *report.graded;
  if (!(g.t_peak > 0)) {
    report.verdicts.push_back(
        {"graded", false, true, fmt::format("thickness '{}' is never positive in the cell", *walls.measured_text)});
    return;
  }
  const MethodFacts& promised = g0.method();
  report.graded->expected_total = promised.graded_order;
  report.graded->expected_one_sided = promised.graded_wall_order;
  report.graded->expected_paper = promised.graded_paper_order;
  report.graded->method_reads = promised.method;
  const bool judged = !probe.float_only;
  report.verdicts.push_back(
      order_verdict("graded total thickness", g.fit_total, promised.graded_order, s.order_slack, judged));
  report.verdicts.push_back(order_verdict("graded one-sided (each wall)", g.fit_one_sided, promised.graded_wall_order,
                                          s.order_slack, judged));
  report.verdicts.push_back(order_verdict("graded paper (wall -> F)", g.fit_paper, promised.graded_paper_order,
                                          s.order_slack, judged && promised.graded_paper_order >= 2));
  std::vector<std::pair<double, const ErrorStats*>> graded_rays;
  for (const auto& row : g.rows) {
    if (row.as_given) continue;
    graded_rays.emplace_back(row.h_max, &row.total);
    graded_rays.emplace_back(row.h_max, &row.one_sided);
    graded_rays.emplace_back(row.h_max, &row.paper);
  }
  report.verdicts.push_back(missed_verdict("graded crossings", graded_rays, crossing_limit(report.sweep)));
}

// Items 3 and 4 through the loaded functions: the constant wall, the Lipschitz bounds, the graded wall.
void check_walls(const CheckRequest& s, const run::LoadedFunctions& functions, const Reference& reference,
                 const WallThickness& walls, ProgressLine& progress, CheckReport& report) {
  // A mapped file is measured in the largest cube centred in its domain (check/domain_cube.h).
  const DomainCube cube = domain_cube(report.meta);
  Probe probe = in_cube(make_probe(functions), cube, report.meta.dims);
  report.thickness_float_only = probe.float_only;
  ThicknessOptions options;
  options.h = report.sweep;
  options.grid = s.grid;
  options.scan = s.scan;
  options.progress = [&progress](const std::string& what) { progress.show("thickness: " + what); };
  check_constant_wall(s, probe, options, report);
  check_lipschitz(probe, reference, report);
  if (walls.measured && cube.identity) {  // a mapped file's graded wall is not measured (docs/maps.md)
    const bool compiled = !s.thickness.has_value() && functions.graded != nullptr;
    check_graded_wall(s, probe, reference, walls, compiled, options, report);
  }
}

// Item 5: the density relations and the volume fractions of files with density functions.
void check_density(const CheckRequest& s, const run::LoadedFunctions& functions, const Reference& reference,
                   ProgressLine& progress, CheckReport& report) {
  const run::FileMetadata& meta = report.meta;
  DensityCheckOptions options = s.density;
  options.progress = [&progress](const std::string& what) { progress.show("density: " + what); };
  std::optional<GiNaC::ex> field;
  if (meta.density_field) field = parse_thickness(*meta.density_field, meta, {});
  report.density = measure_density(functions, meta, *reference.generation.density, field, options);
  add_density_verdicts(*report.density, report.verdicts);
}

// Code loaded into this process (a C header): every check, through its functions.
void check_loaded_code(const CheckRequest& s, const std::string& text, const run::Runner& runner, WallThickness walls,
                       CheckReport& report) {
  ProgressLine progress("[offsetgen check]");
  auto [reference, value_options] = prepare_value_check(s, progress, report);
  // A density field's _graded reads t = thickness_for_density(rho(x)): the rebuilt model holds it.
  const run::FileMetadata& meta = report.meta;
  if (meta.density_field && !s.thickness && reference->generation.graded_thickness) {
    walls.measured = walls.file = reference->generation.graded_thickness;
    walls.measured_text = "thickness_for_density(" + *meta.density_field + ")";
  }
  prepare(s, text, runner, progress, report);
  if (!report.prepared.library) {
    progress.clear();
    return;
  }
  const run::LoadedFunctions& functions = report.prepared.library->functions();
  if (s.run_values) {
    report.values = check_values(functions, *reference, meta, walls.file, value_options);
    report.verdicts.push_back(values_verdict(report.words.verdict, *report.values));
  }
  if (s.run_thickness) check_walls(s, functions, *reference, walls, progress, report);
  if (s.run_density && meta.has_density && reference->generation.density)
    check_density(s, functions, *reference, progress, report);
  progress.clear();
}

}  // namespace

std::vector<double> default_sweep() {
  std::vector<double> h;
  for (int k = 0; k <= 8; ++k) h.push_back(std::stod(fmt::format("{:.3g}", 0.001 * std::pow(10.0, k / 4.0))));
  return h;
}

std::vector<double> parse_h_list(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    std::string word = b == std::string::npos ? "" : item.substr(b, e - b + 1);
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (word.empty() || used != word.size() || !std::isfinite(v))
      throw InputError(
          fmt::format("--h: '{}' is not a number (expected a comma-separated list like 0.001,0.01,0.1)", word));
    if (!(v > 0) || v > 0.5)
      throw InputError(fmt::format("--h: {} is outside (0, 0.5]: offsets are positive distances in cell units", word));
    out.push_back(v);
  }
  if (out.empty()) throw InputError("--h: empty list");
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

CheckReport run_checks(const CheckRequest& s) {
  CheckReport report;
  report.file = s.file;
  std::string text;
  report.meta = run::read_metadata(s.file, &text);
  report.sweep = s.h.empty() ? default_sweep() : s.h;
  const WallThickness walls = read_thickness(s, report.meta);  // input problems first, before any long work
  const run::Runner& runner = runner_for(report.meta);
  report.words = runner.words();
  if (runner.loads_in_process()) {
    check_loaded_code(s, text, runner, walls, report);
  } else {
    ProgressLine progress("[offsetgen check]");
    prepare(s, text, runner, progress, report);
    if (s.run_values && report.prepared.ready) check_lane_values(s, walls, report);
  }
  report.pass = std::all_of(report.verdicts.begin(), report.verdicts.end(), [](const Verdict& v) { return v.pass; });
  return report;
}

}  // namespace offsetgen::check
