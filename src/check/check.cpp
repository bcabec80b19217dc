#include "check/check.h"

#include "check/cuda_runner.h"
#include "check/numpy_runner.h"
#include "check/opencl_runner.h"
#include "check/plot.h"
#include "check/progress.h"
#include "check/reference.h"
#include "validate/cell_domain.h"
#ifdef OFFSETGEN_CHECK_HAVE_GL
#include "check/glsl_executor.h"
#endif

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
  v.detail = values.pass ? fmt::format("{} functions within their tolerance", values.functions.size())
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

ValueCheckSetup prepare_value_check(const CheckSettings& s, Progress& progress, CheckReport& report) {
  progress.update("model", "rebuilding the symbolic offset model from the metadata");
  ValueCheckSetup setup{rebuild_reference(report.meta), s.values};
  report.warnings.insert(report.warnings.end(), setup.reference->warnings.begin(), setup.reference->warnings.end());
  report.surface_title = setup.reference->generation.surface.title;
  setup.options.progress = [&progress, &s](int done, int total) {
    progress.update("values", fmt::format("point {}/{} against {}-digit CLN", done + 1, total, s.values.digits));
  };
  return setup;
}

#ifdef OFFSETGEN_CHECK_HAVE_GL
// The snippet's functions on llvmpipe: inputs (x, y, z, h|t) or (x, y, h|t, 0).
Float32Runner llvmpipe_runner(const std::string& snippet, const FileMetadata& meta) {
  return [snippet, meta](const std::string& function, const std::vector<std::array<float, 4>>& inputs,
                         int components) {
    const bool with_distance = function == "offset" || function == "shell" || function == "normal";
    const std::string call = fmt::format("{}_{}({}{})", meta.prefix, function, meta.dims == 3 ? "p.xyz" : "p.xy",
                                         with_distance ? (meta.dims == 3 ? ", p.w" : ", p.z") : "");
    return glsl::run(glsl::Path::Compute, snippet, call, inputs, components);
  };
}
#endif

// A GLSL snippet: glslang for the four targets, then its values on Mesa llvmpipe against the
// 40-digit reference, within the float32 tolerance.
void check_glsl(const CheckSettings& s, const std::string& text, const std::optional<GiNaC::ex>& file_thickness,
                CheckReport& report) {
  const FileMetadata& meta = report.meta;
  report.glsl = compile_glsl(text, meta, s.file);
  bool compiled = true;
  for (const auto& r : report.glsl) {
    report.verdicts.push_back({"glslang " + r.name, r.ok, true, r.ok ? "compiles and links" : "does not compile"});
    compiled = compiled && r.ok;
  }
  if (s.run_values && compiled) {
    Progress progress;
    ValueCheckSetup setup = prepare_value_check(s, progress, report);
#ifdef OFFSETGEN_CHECK_HAVE_GL
    Implementations impl;
    impl.float32 = llvmpipe_runner(text, meta);
    impl.float32_label = "glsl";
    impl.float32_graded = meta.thickness.has_value();
    try {
      report.values = check_values(impl, *setup.reference, meta, file_thickness, setup.options);
      report.verdicts.push_back(values_verdict("values on llvmpipe", *report.values));
    } catch (const std::runtime_error& e) {
      report.verdicts.push_back({"values on llvmpipe", false, true, fmt::format("cannot run the snippet: {}", e.what())});
    }
#else
    (void)file_thickness;
    report.verdicts.push_back({"values on llvmpipe", false, true,
                               "this offsetgen was built without EGL, so it cannot run GLSL (Debian: libegl-dev "
                               "libgl1-mesa-dri; rebuild)"});
#endif
    progress.clear();
  }
  report.pass = std::all_of(report.verdicts.begin(), report.verdicts.end(), [](const Verdict& v) { return v.pass; });
}

// A NumPy module's functions under python3: inputs (x, y, z, h|t) or (x, y, h|t, 0).
Float64Runner python_runner(const std::string& python, const std::string& path, const FileMetadata& meta) {
  return [python, path, meta](const std::string& function, const std::vector<std::array<double, 4>>& inputs,
                              int components) {
    const bool with_distance = function == "offset" || function == "shell" || function == "normal";
    std::vector<std::vector<double>> columns(static_cast<size_t>(meta.dims + (with_distance ? 1 : 0)),
                                             std::vector<double>(inputs.size()));
    for (size_t i = 0; i < inputs.size(); ++i)
      for (size_t k = 0; k < columns.size(); ++k) columns[k][i] = inputs[i][k];
    return numpy_run::run(python, path, meta.prefix + "_" + function, columns, components);
  };
}

// A NumPy module: python3 imports it, then its values against the 40-digit reference, within the
// double tolerance (the module computes in float64). As for GLSL snippets, the thickness sweep and
// the density relations are left to the C header of the same generation.
void check_numpy(const CheckSettings& s, const std::optional<GiNaC::ex>& file_thickness, CheckReport& report) {
  const FileMetadata& meta = report.meta;
  const std::string python = find_python();
  bool imported = false;
  try {
    report.toolchain = numpy_run::describe_python(python);
    numpy_run::import_module(python, s.file);
    imported = true;
    report.verdicts.push_back({"import", true, true, "python3 imports the module"});
  } catch (const std::runtime_error& e) {
    report.verdicts.push_back({"import", false, true, e.what()});
  }
  if (meta.has_density)
    report.warnings.push_back(
        "the density relations of a NumPy module are not checked (check the C header of the same generation)");
  if (s.run_values && imported) {
    Progress progress;
    ValueCheckSetup setup = prepare_value_check(s, progress, report);
    Implementations impl;
    impl.float64 = python_runner(python, s.file, meta);
    impl.float64_label = "numpy";
    impl.float64_graded = meta.thickness.has_value();
    try {
      report.values = check_values(impl, *setup.reference, meta, file_thickness, setup.options);
      report.verdicts.push_back(values_verdict("values under NumPy", *report.values));
    } catch (const std::runtime_error& e) {
      report.verdicts.push_back(
          {"values under NumPy", false, true, fmt::format("cannot run the module: {}", e.what())});
    }
    progress.clear();
  }
  report.pass = std::all_of(report.verdicts.begin(), report.verdicts.end(), [](const Verdict& v) { return v.pass; });
}

// A runner's inputs (x, y, z, h|t) in float, widened for a float64 program (exactly).
std::vector<std::array<double, 4>> widened(const std::vector<std::array<float, 4>>& inputs) {
  std::vector<std::array<double, 4>> out(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i)
    for (size_t k = 0; k < 4; ++k) out[i][k] = inputs[i][k];
  return out;
}

std::vector<float> narrowed(const std::vector<double>& values) { return {values.begin(), values.end()}; }

// The values of a compiled CUDA or OpenCL file against the 40-digit reference: its double functions at
// the double limits, its float functions at the float limits (value_check.h). The thickness sweep and
// the density relations are left to the C header of the same generation, as for GLSL and NumPy.
void check_program_values(const CheckSettings& s, const std::optional<GiNaC::ex>& file_thickness, Implementations impl,
                          const std::string& verdict, CheckReport& report) {
  const FileMetadata& meta = report.meta;
  if (meta.has_density)
    report.warnings.push_back(
        fmt::format("the density relations of a {} file are not checked (check the C header of "
                    "the same generation)",
                    kind_name(meta.kind)));
  Progress progress;
  ValueCheckSetup setup = prepare_value_check(s, progress, report);
  impl.float32_graded = impl.float64_graded = meta.has_graded();
  try {
    report.values = check_values(impl, *setup.reference, meta, file_thickness, setup.options);
    report.verdicts.push_back(values_verdict(verdict, *report.values));
  } catch (const std::runtime_error& e) {
    report.verdicts.push_back({verdict, false, true, fmt::format("cannot run the functions: {}", e.what())});
  }
  progress.clear();
}

void push_compile_verdict(CheckReport& report) {
  Verdict v{"compile", true, true, ""};
  for (const auto& step : report.compile.steps) {
    const std::string why = step.output.substr(0, step.output.find('\n'));
    v.detail += fmt::format("{}{}: {}", v.detail.empty() ? "" : "; ", step.name,
                            step.ok ? "ok" : (why.empty() ? "FAILED" : "FAILED (" + why + ")"));
    v.pass = v.pass && step.ok;
  }
  report.compile.ok = v.pass;
  report.verdicts.push_back(v);
}

// A CUDA header: nvcc compiles a host program calling its __host__ __device__ functions (the host path,
// no GPU needed), then their values in double and float.
void check_cuda(const CheckSettings& s, const std::optional<GiNaC::ex>& file_thickness, CheckReport& report) {
  const FileMetadata& meta = report.meta;
  std::string nvcc = cuda_run::find_nvcc();
  try {
    report.toolchain = cuda_run::describe_nvcc(nvcc, meta);
  } catch (const std::runtime_error& e) {
    report.verdicts.push_back({"compile", false, true, e.what()});
    report.pass = false;
    return;
  }
  Progress progress;
  progress.update("compile", "nvcc: the host path of the CUDA header");
  auto program = std::make_shared<cuda_run::HostProgram>(nvcc, s.file, meta);
  progress.clear();
  report.compile.optimization = program->step().command.size() > 2 ? program->step().command[2] : "";
  report.compile.steps.push_back(program->step());
  push_compile_verdict(report);
  if (s.run_values && program->ok()) {
    Implementations impl;
    impl.float64 = [program](const std::string& function, const std::vector<std::array<double, 4>>& inputs,
                             int components) { return program->run(function, inputs, components); };
    impl.float64_label = "cuda";
    impl.float32 = [program](const std::string& function, const std::vector<std::array<float, 4>>& inputs,
                             int components) {
      return narrowed(program->run(function + "f", widened(inputs), components));
    };
    impl.float32_label = "cuda";
    impl.float32_suffix = "f";
    check_program_values(s, file_thickness, impl, "values of the host path", report);
  }
  report.pass = std::all_of(report.verdicts.begin(), report.verdicts.end(), [](const Verdict& v) { return v.pass; });
}

// An OpenCL C source: the C compiler builds a host program on the ICD loader, which builds the file on the
// first OpenCL device, then its values in float, and in double where the device reports cl_khr_fp64.
void check_opencl(const CheckSettings& s, const std::string& text, const std::optional<GiNaC::ex>& file_thickness,
                  CheckReport& report) {
  const FileMetadata& meta = report.meta;
  const Toolchain tools = find_toolchain();
  Progress progress;
  progress.update("compile", "the OpenCL host program, then the source on the device");
  auto program = std::make_shared<opencl_run::HostProgram>(tools, text, meta);
  report.compile.steps.push_back(program->step());
  std::optional<opencl_run::Device> device;
  if (program->step().ok) {
    CompileStep build;
    build.name = "clBuildProgram";
    build.command = {"clBuildProgram", "-cl-std=CL1.2 -Werror"};
    const auto start = std::chrono::steady_clock::now();
    try {
      device = program->build();
      build.ok = true;
      build.output = device->build_log;
      report.toolchain =
          fmt::format("{} (from {}); OpenCL: {}, device {}{}", tools.c.front(), tools.c_origin, device->platform,
                      device->name, device->fp64 ? ", cl_khr_fp64" : ", no cl_khr_fp64");
    } catch (const std::runtime_error& e) {
      build.output = e.what();
      report.toolchain = fmt::format("{} (from {}); no OpenCL device", tools.c.front(), tools.c_origin);
    }
    build.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.compile.steps.push_back(build);
  } else {
    report.toolchain = fmt::format("{} (from {})", tools.c.front(), tools.c_origin);
  }
  progress.clear();
  push_compile_verdict(report);
  if (device && !device->fp64)
    report.warnings.push_back(fmt::format("{} has no cl_khr_fp64: only the float functions are checked", device->name));
  if (s.run_values && device) {
    Implementations impl;
    if (device->fp64) {
      impl.float64 = [program](const std::string& function, const std::vector<std::array<double, 4>>& inputs,
                               int components) { return program->run(function, 8, inputs, components); };
      impl.float64_label = "opencl";
    }
    impl.float32 = [program](const std::string& function, const std::vector<std::array<float, 4>>& inputs,
                             int components) {
      return narrowed(program->run(function + "f", 4, widened(inputs), components));
    };
    impl.float32_label = "opencl";
    impl.float32_suffix = "f";
    check_program_values(s, file_thickness, impl, "values on the device", report);
  }
  report.pass = std::all_of(report.verdicts.begin(), report.verdicts.end(), [](const Verdict& v) { return v.pass; });
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

CheckReport run_checks(const CheckSettings& s) {
  CheckReport report;
  report.file = s.file;
  std::string text;
  report.meta = read_metadata(s.file, &text);
  const FileMetadata& meta = report.meta;
  report.sweep = s.h.empty() ? default_sweep() : s.h;

  // Input problems first, before any long work: thickness expression, compiler, model.
  std::optional<GiNaC::ex> thickness_ex;
  std::optional<std::string> thickness_text = s.thickness ? s.thickness : meta.thickness;
  if (thickness_text) thickness_ex = parse_thickness(*thickness_text, meta, s.params);
  if (s.thickness) require_positive_thickness(*thickness_ex, meta.dims, *s.thickness);  // as generate does
  std::optional<GiNaC::ex> file_thickness;
  if (meta.thickness) file_thickness = parse_thickness(*meta.thickness, meta, {});
  if (meta.kind == FileKind::Glsl) {
    check_glsl(s, text, file_thickness, report);
    return report;
  }
  if (meta.kind == FileKind::Numpy) {
    check_numpy(s, file_thickness, report);
    return report;
  }
  if (meta.kind == FileKind::Cuda) {
    check_cuda(s, file_thickness, report);
    return report;
  }
  if (meta.kind == FileKind::Opencl) {
    check_opencl(s, text, file_thickness, report);
    return report;
  }
  const Toolchain tools = find_toolchain();
  report.toolchain = fmt::format("{} (from {})", tools.c.front(), tools.c_origin);
  if (!tools.cxx.empty()) report.toolchain += fmt::format(", {} (from {})", tools.cxx.front(), tools.cxx_origin);

  Progress progress;
  auto [reference, value_options] = prepare_value_check(s, progress, report);
  // A density field's _graded reads t = thickness_for_density(rho(x)): the rebuilt model holds it.
  if (meta.density_field && !s.thickness && reference->generation.graded_thickness) {
    thickness_ex = file_thickness = reference->generation.graded_thickness;
    thickness_text = "thickness_for_density(" + *meta.density_field + ")";
  }

  progress.update("compile", "C99 strict, C++17 strict, shared object");
  report.compile = compile_and_load(s.file, meta, tools);
  {
    Verdict v{"compile", report.compile.ok, true, ""};
    for (const auto& step : report.compile.steps)
      v.detail += fmt::format("{}{}: {}", v.detail.empty() ? "" : "; ", step.name,
                              step.skipped ? "skipped" : (step.ok ? "ok" : "FAILED"));
    report.verdicts.push_back(v);
  }
  if (!report.compile.library) {
    progress.clear();
    report.pass = false;
    return report;
  }
  const LoadedFunctions& functions = report.compile.library->functions();

  if (s.run_values) {
    report.values = check_values(functions, *reference, meta, file_thickness, value_options);
    report.verdicts.push_back(values_verdict("values", *report.values));
  }

  if (s.run_thickness) {
    Probe probe = make_probe(functions);
    report.thickness_float_only = probe.float_only;
    ThicknessOptions options;
    options.h = report.sweep;
    options.grid = s.grid;
    options.scan = s.scan;
    options.progress = [&progress](const std::string& what) { progress.update("thickness", what); };
    report.thickness = measure_constant(probe, options);
    const ThicknessReport& t = *report.thickness;
    const double m = meta.order;
    // Beyond order 4 much of the asymptotic range lies under the double-precision floor: a slope is
    // judged there only when at least 3 sweep points lie above the floor.
    auto judge = [&](const OrderFit& fit) { return !probe.float_only && (meta.order <= 4 || fit.points >= 3); };
    report.verdicts.push_back(order_verdict("order F -> phi", t.fit_f_to_phi, m, s.order_slack, judge(t.fit_f_to_phi)));
    report.verdicts.push_back(order_verdict("order phi -> F", t.fit_phi_to_f, m, s.order_slack, judge(t.fit_phi_to_f)));
    report.verdicts.push_back(order_verdict("order shell", t.fit_shell, m, s.order_slack, judge(t.fit_shell)));
    const double h_limit = std::sqrt(report.sweep.front() * report.sweep.back());
    std::vector<std::pair<double, const ErrorStats*>> rays;
    for (const auto& row : t.rows) {
      rays.emplace_back(row.h, &row.f_to_phi);
      rays.emplace_back(row.h, &row.phi_to_f);
      rays.emplace_back(row.h, &row.shell);
    }
    report.verdicts.push_back(missed_verdict("crossings", rays, h_limit));

    const MethodFacts& facts = reference->generation.method();
    report.lipschitz = measure_lipschitz(probe, facts.lipschitz_bounds,
                                         reference->generation.construction->bounds().gradient, meta.scale);
    for (const LipschitzRow& row : report.lipschitz)
      report.verdicts.push_back({fmt::format("lipschitz |h| <= {:g}", row.h), row.pass, !probe.float_only,
                                 fmt::format("max |grad phi| {:.4g} over {} points of the band |F| <= M|h|, "
                                             "documented bound {:.4g}",
                                             row.measured, row.points, row.bound)});

    if (thickness_ex) {
      ThicknessFunction tfun(*thickness_ex, meta.dims);
      const Generation& g0 = reference->generation;
      auto wall_program = std::make_shared<Program>(lower_graded_wall(g0.surface, *g0.construction, *thickness_ex));
      auto wall = std::make_shared<Evaluator>(*wall_program);
      probe.graded_wall = [wall_program, wall, dims = meta.dims](const double* q, double s_value) {
        std::vector<double> in(q, q + dims);
        in.push_back(s_value);
        return (*wall)(in).at(0);
      };
      const bool compiled = !s.thickness.has_value() && functions.graded != nullptr;
      report.graded = measure_graded(probe, tfun, *thickness_text, compiled, options);
      const GradedReport& g = *report.graded;
      if (!(g.t_peak > 0)) {
        report.verdicts.push_back(
            {"graded", false, true, fmt::format("thickness '{}' is never positive in the cell", *thickness_text)});
      } else {
        // The orders the file's method promises (offset/method.h, MethodFacts).
        const MethodFacts& promised = g0.method();
        report.graded->expected_total = promised.graded_order;
        report.graded->expected_one_sided = promised.graded_wall_order;
        report.graded->expected_paper = promised.graded_paper_order;
        report.graded->method_reads = promised.method;
        const bool judged = !probe.float_only;
        report.verdicts.push_back(
            order_verdict("graded total thickness", g.fit_total, promised.graded_order, s.order_slack, judged));
        report.verdicts.push_back(order_verdict("graded one-sided (each wall)", g.fit_one_sided,
                                                promised.graded_wall_order, s.order_slack, judged));
        report.verdicts.push_back(order_verdict("graded paper (wall -> F)", g.fit_paper, promised.graded_paper_order,
                                                s.order_slack, judged && promised.graded_paper_order >= 2));
        std::vector<std::pair<double, const ErrorStats*>> graded_rays;
        for (const auto& row : g.rows) {
          if (row.as_given) continue;
          graded_rays.emplace_back(row.h_max, &row.total);
          graded_rays.emplace_back(row.h_max, &row.one_sided);
          graded_rays.emplace_back(row.h_max, &row.paper);
        }
        report.verdicts.push_back(missed_verdict("graded crossings", graded_rays, h_limit));
      }
    }
  }
  if (s.run_density && meta.has_density && reference->generation.density) {
    DensityCheckOptions options = s.density;
    options.progress = [&progress](const std::string& what) { progress.update("density", what); };
    std::optional<GiNaC::ex> field;
    if (meta.density_field) field = parse_thickness(*meta.density_field, meta, {});
    report.density = measure_density(functions, meta, *reference->generation.density, field, options);
    add_density_verdicts(*report.density, report.verdicts);
  }
  progress.clear();
  report.pass = std::all_of(report.verdicts.begin(), report.verdicts.end(), [](const Verdict& v) { return v.pass; });
  return report;
}

}  // namespace offsetgen::check
