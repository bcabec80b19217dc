#include "check/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace offsetgen::check {
namespace {

using ojson = nlohmann::ordered_json;

std::string sci(double v) {
  if (std::isnan(v)) return "-";
  if (v == 0) return "0";
  return fmt::format("{:.2e}", v);
}

ojson number(double v) { return std::isfinite(v) ? ojson(v) : ojson(); }

ojson point_json(const Point& p, int dims) {
  ojson a = ojson::array();
  for (int i = 0; i < dims; ++i) a.push_back(p[static_cast<size_t>(i)]);
  return a;
}

ojson stats_json(const ErrorStats& s, int dims) {
  ojson j;
  j["rays"] = s.rays;
  j["crossed"] = s.crossed;
  j["missed"] = s.missed;
  j["skipped"] = s.skipped;
  if (s.skipped > 0) j["skipped_reason"] = s.skipped_reason;
  j["singular"] = s.singular;
  j["mean_relative_error"] = number(s.mean);
  j["max_relative_error"] = number(s.max);
  j["worst_point"] = s.crossed > 0 ? point_json(s.worst, dims) : ojson();
  ojson missed = ojson::array();
  for (const auto& p : s.missed_at) missed.push_back(point_json(p, dims));
  j["missed_at"] = missed;
  return j;
}

ojson fit_json(const OrderFit& f) {
  ojson j;
  j["fitted"] = f.fitted;
  j["slope"] = f.fitted ? ojson(f.slope) : ojson();
  j["h_min"] = f.fitted ? ojson(f.h_min) : ojson();
  j["h_max"] = f.fitted ? ojson(f.h_max) : ojson();
  j["points"] = f.points;
  j["note"] = f.note;
  return j;
}

std::string fit_text(const OrderFit& f) {
  if (!f.fitted) return f.note;
  return fmt::format("{:.2f}  (h = {:g}..{:g}, {} pts{})", f.slope, f.h_min, f.h_max, f.points,
                     f.note.empty() ? "" : "; " + f.note);
}

std::string missed_text(const ErrorStats& s) { return s.missed == 0 ? "0" : fmt::format("{}/{}", s.missed, s.rays); }

// Section 1, in the layout the runner chose (run/runner.h, Listing).
std::string preparation_text(const run::Prepared& p) {
  std::string out = "\n";
  auto line = [&out](const std::string& s) { out += s + "\n"; };
  if (p.listing == run::Listing::Import) {
    line(fmt::format("1. Import ({})", p.toolchain.empty() ? "no python3 with NumPy" : p.toolchain));
    return out;
  }
  if (p.listing == run::Listing::Shader) {
    line(p.heading + ":");
    for (const auto& step : p.steps) {
      line(fmt::format("  {:<28} {}", step.name, step.ok ? "ok" : "FAILED"));
      if (!step.ok) out += step.output;
    }
    return out;
  }
  line(fmt::format("1. Compile ({})", p.toolchain));
  if (!p.note.empty()) line("   " + p.note);
  for (const auto& step : p.steps) {
    std::string cmd;
    for (const auto& a : step.command) cmd += (cmd.empty() ? "" : " ") + a;
    line(fmt::format("  {:<28} {}{}", step.name, step.skipped ? "skipped" : (step.ok ? "ok" : "FAILED"),
                     step.command.empty() ? "" : fmt::format("  ({:.2f} s)", step.seconds)));
    if (!step.ok || step.skipped) {
      if (!cmd.empty()) line("    $ " + cmd);
      out += step.output;
      if (!step.output.empty() && step.output.back() != '\n') out += "\n";
    }
  }
  return out;
}

ojson preparation_json(const run::Prepared& p) {
  if (p.listing == run::Listing::Import) return p.toolchain;
  if (p.listing == run::Listing::Shader) {
    ojson steps = ojson::array();
    for (const auto& c : p.steps)
      steps.push_back({{"target", c.name}, {"ok", c.ok}, {"command", c.command}, {"output", c.output}});
    return steps;
  }
  ojson compile;
  compile["toolchain"] = p.toolchain;
  compile["ok"] = std::all_of(p.outcomes.begin(), p.outcomes.end(), [](const run::Outcome& o) { return o.pass; });
  compile["optimization"] = p.optimization;
  compile["note"] = p.note;
  ojson steps = ojson::array();
  for (const auto& s : p.steps)
    steps.push_back({{"name", s.name},
                     {"ok", s.ok},
                     {"skipped", s.skipped},
                     {"seconds", s.seconds},
                     {"command", s.command},
                     {"output", s.output}});
  compile["steps"] = steps;
  return compile;
}

// Section 2: each function's largest and mean zero-set shift against its limit.
std::string values_text(const ValueReport& v, const run::ValueWords& words) {
  std::string out;
  auto line = [&out](const std::string& s) { out += s + "\n"; };
  line("");
  line(fmt::format("2. Values: {} vs a {}-digit CLN evaluation of the symbolic model at random points", words.source,
                   v.digits));
  line("   in the cell, h and t/2 uniform in [-0.1, 0.1]; shift = how far the deviation moves the zero set (cell");
  line("   units); for the normal, |dn|. Every function is judged against the limit of its precision.");
  line(fmt::format("  {:<14} {:>6} {:>11} {:>11} {:>8}  {:<4}  {}", "function", "points", "max shift", "mean shift",
                   "limit", "", "measure"));
  for (const auto& f : v.functions)
    line(fmt::format("  {:<14} {:>6} {:>11} {:>11} {:>8.0e}  {:<4}  {}", f.function, f.points, sci(f.max_shift),
                     sci(f.mean_shift), f.tolerance, f.pass ? "ok" : "FAIL", f.measure));
  return out;
}

// Section 3: the constant wall's relative thickness errors per h, the skipped singular samples and
// the fitted orders.
std::string thickness_text(const ThicknessReport& t, int dims, bool float_only) {
  std::string out;
  auto line = [&out](const std::string& s) { out += s + "\n"; };
  line("");
  if (dims == 3)
    line(
        fmt::format("3. Wall thickness (paper section 5.2.1): {} points on F = 0 (x, y on a {}x{} grid, z by "
                    "bracketing + Brent),",
                    t.samples_on_f, t.grid, t.grid));
  else
    line(
        fmt::format("3. Wall thickness (paper section 5.2.1): {} points on F = 0 (x on a grid of {}, y by "
                    "bracketing + Brent),",
                    t.samples_on_f, t.grid));
  if (float_only) line("   (float-only file: measured on the float32 functions, slopes not judged)");
  line("   rays along the unit normal; relative error |h_m - h| / h; 'missed' = rays without a crossing");
  line(fmt::format("  {:>8} | {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6}", "h/L", "F->phi", "max",
                   "missed", "phi->F", "max", "missed", "shell t=2h", "max", "missed"));
  for (const auto& row : t.rows)
    line(fmt::format("  {:>8g} | {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6}", row.h,
                     sci(row.f_to_phi.mean), sci(row.f_to_phi.max), missed_text(row.f_to_phi), sci(row.phi_to_f.mean),
                     sci(row.phi_to_f.max), missed_text(row.phi_to_f), sci(row.shell.mean), sci(row.shell.max),
                     missed_text(row.shell)));
  line("  (mean and max of the relative error; shell: total thickness between both walls of Phi(., t) against t)");
  int singular = 0;
  for (const auto& row : t.rows)
    singular = std::max({singular, row.f_to_phi.singular, row.phi_to_f.singular, row.shell.singular});
  if (singular > 0)
    line(fmt::format(
        "  singular samples skipped, not counted as rays (up to {} per row; {} of the {} points on F = 0):\n"
        "  |grad F| below {:g} of its median on F = 0 where the ray starts or ends, or a ray without a\n"
        "  crossing where |h| ||Hess F|| >= |grad F|: next to a crossing or critical point of the zero set,\n"
        "  where the offset is not defined to any order",
        singular, t.singular_on_f, t.samples_on_f, kSingularGradient));
  line(fmt::format("  fitted order  F->phi: {}", fit_text(t.fit_f_to_phi)));
  line(fmt::format("                phi->F: {}", fit_text(t.fit_phi_to_f)));
  line(fmt::format("                shell:  {}", fit_text(t.fit_shell)));
  return out;
}

// Section 4: the graded wall's three measures per h_max and the orders the method promises.
std::string graded_text(const GradedReport& g) {
  std::string out;
  auto line = [&out](const std::string& s) { out += s + "\n"; };
  line("");
  line(fmt::format("4. Graded wall, total thickness t(x) = {} (peak {:g} in the cell), h(x) = t(x)/2;", g.expression,
                   g.t_peak));
  line("   the sweep scales t so that max h = h_max; the last row is t exactly as given.");
  line(fmt::format("   The walls are the {} method's, read as the compiled _graded reads t; orders it promises:",
                   g.method_reads));
  line(fmt::format("   total:     rays from p on F = 0, distance between the +h(x) and -h(x) walls vs t(p). Order {}.",
                   g.expected_total));
  line(fmt::format("   one-sided: each wall from p on F = 0 vs h(p), the thickness at its foot point. Order {}.",
                   g.expected_one_sided));
  line("   paper:     the paper's Figure 8: rays from points q on each wall along the wall's own normal back");
  line(fmt::format("              to F = 0, vs h(q), the thickness at the wall point. Order {}.", g.expected_paper));
  line(fmt::format("  {:>10} | {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6} | {:>9} {:>9}", "h_max/L", "total", "max",
                   "missed", "paper", "max", "missed", "one-sided", "max"));
  for (const auto& row : g.rows) {
    std::string label = row.as_given ? fmt::format("{:g}*", row.h_max) : fmt::format("{:g}", row.h_max);
    line(fmt::format("  {:>10} | {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6} | {:>9} {:>9}", label, sci(row.total.mean),
                     sci(row.total.max), missed_text(row.total), sci(row.paper.mean), sci(row.paper.max),
                     missed_text(row.paper), sci(row.one_sided.mean), sci(row.one_sided.max)));
  }
  for (const auto& row : g.rows) {
    if (row.as_given)
      line(fmt::format("  * as given{}; {} point(s) with t <= 0 skipped",
                       row.compiled_graded ? ", measured on the compiled _graded function" : "", row.total.skipped));
  }
  line(fmt::format("  fitted order  total:     {}", fit_text(g.fit_total)));
  line(fmt::format("                paper:     {}", fit_text(g.fit_paper)));
  line(fmt::format("                one-sided: {}", fit_text(g.fit_one_sided)));
  return out;
}

// Section 2 as data: every function's deviations.
ojson values_json(const ValueReport& v) {
  ojson vj;
  vj["digits"] = v.digits;
  vj["tolerance"] = v.tolerance;
  vj["pass"] = v.pass;
  vj["max_shift_double"] = v.has_double ? ojson(v.max_shift_double) : ojson();
  vj["max_normal_deviation_double"] = v.max_normal_double;
  vj["max_shift_float"] = v.max_shift_float;
  ojson fs = ojson::array();
  for (const auto& f : v.functions)
    fs.push_back({{"function", f.function},
                  {"float", f.is_float},
                  {"points", f.points},
                  {"max_shift", number(f.max_shift)},
                  {"mean_shift", number(f.mean_shift)},
                  {"worst_point", f.worst_point},
                  {"measure", f.measure},
                  {"tolerance", f.tolerance},
                  {"pass", f.pass}});
  vj["functions"] = fs;
  return vj;
}

// Section 3 as data: the rays per h, their definitions and the fits.
ojson thickness_json(const ThicknessReport& t, int dims) {
  ojson tj;
  tj["grid"] = t.grid;
  tj["scan_intervals"] = t.scan;
  tj["samples_on_f"] = t.samples_on_f;
  tj["singular_on_f"] = t.singular_on_f;
  tj["singular_definition"] = fmt::format(
      "|grad F| < {:g} x its median over the samples on F = 0 where a ray starts or "
      "ends, or a ray without a crossing where |h| ||Hess F|| >= |grad F|: skipped, "
      "not counted as rays",
      kSingularGradient);
  tj["error_definition"] = "relative: |h_m - h| / h per ray; shell: |(s+ - s-) - t| / t with t = 2h";
  ojson rows = ojson::array();
  for (const auto& row : t.rows)
    rows.push_back({{"h", row.h},
                    {"f_to_phi", stats_json(row.f_to_phi, dims)},
                    {"phi_to_f", stats_json(row.phi_to_f, dims)},
                    {"shell", stats_json(row.shell, dims)}});
  tj["rows"] = rows;
  tj["fits"] = {
      {"f_to_phi", fit_json(t.fit_f_to_phi)}, {"phi_to_f", fit_json(t.fit_phi_to_f)}, {"shell", fit_json(t.fit_shell)}};
  return tj;
}

// Section 4 as data: the graded wall's three measures per h_max and their fits.
ojson graded_json(const GradedReport& g, int dims) {
  ojson gj;
  gj["expression"] = g.expression;
  gj["t_peak"] = g.t_peak;
  gj["definitions"] = {
      {"total",
       "rays from p on F = 0 along grad F to the +h(x) and -h(x) walls; |(s+ - s-) - t(p)| / t(p); order <= 2"},
      {"paper",
       "paper Figure 8: rays from q on each wall along the wall's own normal to F = 0; |h_m - h(q)| / h(q); order <= "
       "2"},
      {"one_sided", "rays from p on F = 0 to each wall; |s - h(p)| / h(p); first order"}};
  ojson rows = ojson::array();
  for (const auto& row : g.rows)
    rows.push_back({{"h_max", row.h_max},
                    {"lambda", row.lambda},
                    {"as_given", row.as_given},
                    {"compiled_graded", row.compiled_graded},
                    {"total", stats_json(row.total, dims)},
                    {"paper", stats_json(row.paper, dims)},
                    {"one_sided", stats_json(row.one_sided, dims)}});
  gj["rows"] = rows;
  gj["fits"] = {
      {"total", fit_json(g.fit_total)}, {"paper", fit_json(g.fit_paper)}, {"one_sided", fit_json(g.fit_one_sided)}};
  return gj;
}

}  // namespace

std::string format_report(const CheckReport& r) {
  const run::FileMetadata& m = r.meta;
  std::string out;
  auto line = [&out](const std::string& s) { out += s + "\n"; };
  line(fmt::format("offsetgen check {}", r.file));
  line(fmt::format("  made from  {} {}, order {}, {}D, prefix {}, {}", m.surface ? "surface" : "expression",
                   m.surface ? *m.surface : *m.expression, m.order, m.dims, m.prefix, m.generator));
  if (!r.surface_title.empty())
    line(fmt::format("             {}; safeguard bound M = {:.6g}", r.surface_title, m.gradient_bound));
  for (const auto& w : r.warnings) line("  warning    " + w);

  out += preparation_text(r.prepared);

  if (r.values) out += values_text(*r.values, r.words);
  if (r.thickness) out += thickness_text(*r.thickness, m.dims, r.thickness_float_only);
  if (r.graded) out += graded_text(*r.graded);
  if (r.density) out += format_density(*r.density);

  line("");
  line("Verdict:");
  for (const auto& v : r.verdicts)
    line(fmt::format("  {:<6} {:<26} {}", v.judged ? (v.pass ? "PASS" : "FAIL") : "info", v.name, v.detail));
  line(r.pass ? "offsetgen check: all checks passed" : "offsetgen check: FAILED");
  return out;
}

ojson report_json(const CheckReport& r) {
  ojson j;
  const run::FileMetadata& m = r.meta;
  const int dims = m.dims;
  j["file"] = r.file;
  j["kind"] = m.language;
  j["metadata"] = ojson::parse(m.json);
  j["warnings"] = r.warnings;
  j["pass"] = r.pass;
  j["exit_code"] = r.pass ? 0 : 1;
  ojson verdicts = ojson::array();
  for (const auto& v : r.verdicts)
    verdicts.push_back({{"name", v.name}, {"pass", v.pass}, {"judged", v.judged}, {"detail", v.detail}});
  j["verdicts"] = verdicts;

  j[r.prepared.json_key] = preparation_json(r.prepared);

  if (r.values) j["values"] = values_json(*r.values);
  if (r.thickness) j["thickness"] = thickness_json(*r.thickness, dims);
  if (r.graded) j["graded"] = graded_json(*r.graded, dims);
  if (r.density) j["density"] = density_json(*r.density);
  return j;
}

nlohmann::json plot_spec(const CheckReport& r) {
  nlohmann::json spec;
  spec["title"] = fmt::format("{}: measured offset error (order {})", r.meta.prefix, r.meta.order);
  spec["xlabel"] = "h/L";
  spec["ylabel"] = "mean relative error";
  spec["slope_triangles"] = true;
  nlohmann::json series = nlohmann::json::array();
  auto add = [&](const std::string& label, double order, const std::vector<double>& x, const std::vector<double>& y) {
    nlohmann::json s;
    s["label"] = label;
    s["order"] = order;
    s["x"] = x;
    nlohmann::json ys = nlohmann::json::array();
    // points under 1e-12 are roundoff; leaving them out keeps the slope triangles on real slopes
    for (double v : y) ys.push_back(std::isfinite(v) && v > 1e-12 ? nlohmann::json(v) : nlohmann::json());
    s["y"] = ys;
    series.push_back(s);
  };
  const double m = r.meta.order;
  if (r.thickness) {
    std::vector<double> h, a, b, c;
    for (const auto& row : r.thickness->rows) {
      h.push_back(row.h);
      a.push_back(row.f_to_phi.mean);
      b.push_back(row.phi_to_f.mean);
      c.push_back(row.shell.mean);
    }
    add("F -> phi", m, h, a);
    add("phi -> F", m, h, b);
    add("shell, t = 2h", m, h, c);
  }
  if (r.graded) {
    std::vector<double> h, a, b, c;
    for (const auto& row : r.graded->rows) {
      if (row.as_given) continue;
      h.push_back(row.h_max);
      a.push_back(row.total.mean);
      b.push_back(row.paper.mean);
      c.push_back(row.one_sided.mean);
    }
    add("graded: total (vs h_max)", r.graded->expected_total, h, a);
    add("graded: paper Fig. 8", r.graded->expected_paper, h, b);
    add("graded: one-sided", r.graded->expected_one_sided, h, c);
  }
  spec["series"] = series;
  return spec;
}

}  // namespace offsetgen::check
