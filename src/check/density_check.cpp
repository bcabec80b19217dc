#include "check/density_check.h"

#include "check/reference.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace offsetgen::check {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Columns per side for one cell of a density field's block (volume_fraction.h: periodic = false).
constexpr int kMinimumCellGrid = 32;

// Gauss-Legendre nodes and weights on [0, 1], 6 points: exact for polynomials of degree 11.
constexpr std::array<double, 6> kGaussNodes = {0.033765242898423987, 0.16939530676686776, 0.38069040695840156,
                                               0.61930959304159845,  0.83060469323313224, 0.96623475710157603};
constexpr std::array<double, 6> kGaussWeights = {0.085662246189585178, 0.18038078652406931, 0.23395696728634552,
                                                 0.23395696728634552,  0.18038078652406931, 0.085662246189585178};

// The emitted relations of one precision (T) against the model over the valid range, and NaN out of
// range. `r_error`/`r_worst`: where the largest relative difference goes.
template <typename T>
void check_relations(T (*density)(T), T (*thickness_for_density)(T), T (*network_density)(T),
                     T (*offset_for_density)(T), const run::FileMetadata& meta, const density::DensityModel& m,
                     double& r_error, std::string& r_worst, DensityReport& r) {
  const char* suffix = sizeof(T) == sizeof(float) ? "f" : "";
  auto compare = [&](const char* name, double argument, T emitted, double expected) {
    const double scale = std::max(std::fabs(expected), 1e-3);
    const double error = std::fabs(double(emitted) - expected) / scale;
    if (!(error <= r_error)) {
      r_error = std::isnan(error) ? INFINITY : error;
      r_worst = fmt::format("{}{}({:.9g}) = {:.9g}, model {:.9g}", name, suffix, argument, double(emitted), expected);
    }
  };
  constexpr int n = 200;
  for (int i = 0; i <= n; ++i) {
    const double u = double(i) / n;
    // The arguments as the precision holds them, so the model sees the same input.
    const double t = double(T(u * m.thickness_limit())), rho = double(T(u * m.sheet_density_limit()));
    if (t <= m.thickness_limit()) compare("density", t, density(T(t)), m.sheet_density(t));
    if (rho <= m.sheet_density_limit())
      compare("thickness_for_density", rho, thickness_for_density(T(rho)), m.sheet_thickness(rho));
    const double h = double(T((2 * u - 1) * m.offset_limit()));
    const double rn = double(T(m.network_density_min() + u * (m.network_density_max() - m.network_density_min())));
    if (std::fabs(h) <= m.offset_limit()) compare("network_density", h, network_density(T(h)), m.network_density(h));
    if (rn >= m.network_density_min() && rn <= m.network_density_max())
      compare("offset_for_density", rn, offset_for_density(T(rn)), m.network_offset(rn));
  }
  auto must_be_nan = [&r, suffix](const char* name, double argument, T value) {
    if (std::isnan(value)) return;
    ++r.nan_failures;
    if (r.nan_failure_examples.size() < 4)
      r.nan_failure_examples.push_back(fmt::format("{}{}({:g}) = {:g}", name, suffix, argument, double(value)));
  };
  // Just outside each limit, in the precision's own steps.
  const double above = sizeof(T) == sizeof(float) ? 1 + 1e-5 : 1 + 1e-9;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  must_be_nan("density", -1e-6, density(T(-1e-6)));
  must_be_nan("density", meta.thickness_limit * above, density(T(meta.thickness_limit * above)));
  must_be_nan("density", kNaN, density(nan));
  must_be_nan("thickness_for_density", -1e-6, thickness_for_density(T(-1e-6)));
  must_be_nan("thickness_for_density", meta.density_limit * above,
              thickness_for_density(T(meta.density_limit * above)));
  must_be_nan("thickness_for_density", kNaN, thickness_for_density(nan));
  must_be_nan("network_density", -meta.offset_limit * above, network_density(T(-meta.offset_limit * above)));
  must_be_nan("network_density", meta.offset_limit * above, network_density(T(meta.offset_limit * above)));
  must_be_nan("network_density", kNaN, network_density(nan));
  must_be_nan("offset_for_density", meta.network_density_min - 1e-4,
              offset_for_density(T(meta.network_density_min - 1e-4)));
  must_be_nan("offset_for_density", meta.network_density_max + 1e-4,
              offset_for_density(T(meta.network_density_max + 1e-4)));
  must_be_nan("offset_for_density", -1.0, offset_for_density(T(-1.0)));
  must_be_nan("offset_for_density", kNaN, offset_for_density(nan));
}

// What every volume-fraction measurement of one file shares: its functions, the field's slope bound
// and the band that holds every sign change.
struct FractionContext {
  const run::LoadedFunctions& f;
  const run::FileMetadata& meta;
  const DensityCheckOptions& o;

  // |phi(p, h) - F(p)| <= M |h| (natural units) for both methods: the band holds every sign change.
  double band_for(double h_cell) const { return meta.gradient_bound * meta.scale * std::fabs(h_cell) * (1 + 1e-9); }
  numeric::VolumeFractionSetup setup() const {
    numeric::VolumeFractionSetup s;
    s.field = [f = f.field](const double* p) { return f(p); };
    s.field_slope_bound = meta.scale * meta.gradient_bound;  // >= |grad F| in cell units
    return s;
  }
  void progress(const std::string& what) const {
    if (o.progress) o.progress(what);
  }
};

// The sheet of each requested rho: _shell at t = thickness_for_density(rho).
void measure_sheets(const FractionContext& c, const density::DensityModel& model, DensityReport& r) {
  for (double rho : c.o.sheet) {
    if (!(rho <= model.sheet_density_limit())) {
      r.skipped.push_back(fmt::format("sheet rho = {:g}: above rho_max = {:.6f} (t/2 beyond the curvature limit)", rho,
                                      model.sheet_density_limit()));
      continue;
    }
    c.progress(fmt::format("sheet at rho = {:g}", rho));
    const double t = c.f.thickness_for_density(rho);
    numeric::VolumeFractionSetup s = c.setup();
    s.g = [shell = c.f.shell, t](const double* p) { return shell(p, t); };
    s.band = c.band_for(t / 2);
    s.scan_step = t / 4;  // a wall is at least t long along any column through it
    DensityRow row{"sheet", rho, t, numeric::measure_volume_fraction(s, c.o.sampling), 0};
    row.deviation = row.measured.value - rho;
    r.rows.push_back(row);
  }
}

// The network of each requested rho: _offset at h = offset_for_density(rho).
void measure_networks(const FractionContext& c, const density::DensityModel& model, DensityReport& r) {
  for (double rho : c.o.network) {
    if (!(rho >= model.network_density_min() && rho <= model.network_density_max())) {
      r.skipped.push_back(fmt::format("network rho = {:g}: outside [{:.6f}, {:.6f}] (|h| beyond the curvature limit)",
                                      rho, model.network_density_min(), model.network_density_max()));
      continue;
    }
    c.progress(fmt::format("network at rho = {:g}", rho));
    const double h = c.f.offset_for_density(rho);
    numeric::VolumeFractionSetup s = c.setup();
    s.g = [offset = c.f.offset, h](const double* p) { return offset(p, h); };
    s.band = c.band_for(h);
    s.outside_follows_field = true;
    // The network's features along a column are no shorter than about the smallest radius of
    // curvature h_max (a smaller one would put a focal point inside |h| <= h_max): a fraction of it.
    s.scan_step = std::min(1.0 / 128, model.offset_limit() / 8);
    DensityRow row{"network", rho, h, numeric::measure_volume_fraction(s, c.o.sampling), 0};
    row.deviation = row.measured.value - rho;
    r.rows.push_back(row);
  }
}

// _wall, the sheet of the file's own --density.
void measure_wall(const FractionContext& c, DensityReport& r) {
  const run::FileMetadata& meta = c.meta;
  c.progress(fmt::format("_wall at rho = {:g}", *meta.wall_density));
  const double t = *meta.wall_thickness;
  numeric::VolumeFractionSetup s = c.setup();
  s.g = [wall = c.f.wall](const double* p) { return wall(p); };
  s.band = c.band_for(t / 2);
  s.scan_step = t / 4;
  DensityRow row{"wall", *meta.wall_density, t, numeric::measure_volume_fraction(s, c.o.sampling), 0};
  row.deviation = row.measured.value - *meta.wall_density;
  r.rows.push_back(row);
}

// The least and greatest rho(p) of the block on a grid of 1/8 cell.
std::pair<double, double> block_density_range(ThicknessFunction& rho, const std::array<int, 3>& block) {
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i <= 8 * block[0]; ++i)
    for (int j = 0; j <= 8 * block[1]; ++j)
      for (int k = 0; k <= 8 * block[2]; ++k) {
        const double p[3] = {i / 8.0, j / 8.0, k / 8.0};
        const double v = rho(p);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  return {lo, hi};
}

// The mean of rho over cell (i, j, k): 6-point Gauss-Legendre per axis.
double cell_mean_density(ThicknessFunction& rho, int i, int j, int k) {
  double mean = 0;
  for (size_t a = 0; a < 6; ++a)
    for (size_t b = 0; b < 6; ++b)
      for (size_t c = 0; c < 6; ++c) {
        const double p[3] = {i + kGaussNodes[a], j + kGaussNodes[b], k + kGaussNodes[c]};
        mean += kGaussWeights[a] * kGaussWeights[b] * kGaussWeights[c] * rho(p);
      }
  return mean;
}

// A density field's _graded, cell by cell of the block, against the mean rho each cell requests.
void measure_field_cells(const FractionContext& c, const density::DensityModel& model, const GiNaC::ex& density_field,
                         DensityReport& r) {
  r.field = c.meta.density_field;
  r.block = c.o.block;
  ThicknessFunction rho(density_field, 3);
  // The thinnest and thickest wall in the block, for the scan step and the band.
  const auto [lo, hi] = block_density_range(rho, c.o.block);
  const double t_lo = model.sheet_thickness(std::clamp(lo, 1e-6, model.sheet_density_limit()));
  const double t_hi = model.sheet_thickness(std::clamp(hi, 1e-6, model.sheet_density_limit()));
  for (int i = 0; i < c.o.block[0]; ++i)
    for (int j = 0; j < c.o.block[1]; ++j)
      for (int k = 0; k < c.o.block[2]; ++k) {
        c.progress(fmt::format("density field, cell ({}, {}, {})", i, j, k));
        DensityCellRow row;
        row.cell = {i, j, k};
        row.requested = cell_mean_density(rho, i, j, k);
        numeric::VolumeFractionSetup s = c.setup();
        s.g = [graded = c.f.graded](const double* p) { return graded(p); };
        s.band = c.band_for(t_hi / 2);
        s.scan_step = t_lo / 4;
        s.origin = {double(i), double(j), double(k)};
        s.periodic = false;  // the wall's thickness changes across the cell
        numeric::VolumeFractionOptions sampling = c.o.sampling;
        sampling.seed += unsigned(1 + i + 16 * (j + 16 * k));  // independent shifts per cell
        // The tent transform folds the grid in two: keep at least 16 columns per half side.
        sampling.grid = std::max(sampling.grid, kMinimumCellGrid);
        row.measured = numeric::measure_volume_fraction(s, sampling);
        row.deviation = row.measured.value - row.requested;
        r.cells.push_back(row);
      }
}

}  // namespace

DensityReport measure_density(const run::LoadedFunctions& f, const run::FileMetadata& meta,
                              const density::DensityModel& model, const std::optional<GiNaC::ex>& density_field,
                              const DensityCheckOptions& o) {
  DensityReport r;
  r.tolerance = o.tolerance;
  r.cell_tolerance = o.cell_tolerance;
  r.sampling = o.sampling;
  if (f.density)
    check_relations<double>(f.density, f.thickness_for_density, f.network_density, f.offset_for_density, meta, model,
                            r.max_relation_error, r.worst_relation, r);
  if (f.densityf) {
    r.has_float = true;
    check_relations<float>(f.densityf, f.thickness_for_densityf, f.network_densityf, f.offset_for_densityf, meta, model,
                           r.max_float_relation_error, r.worst_float_relation, r);
  }
  if (!f.shell) {
    r.skipped.push_back(
        "volume fractions: the file has no double functions (--precision float); measured in double only");
    return r;
  }
  const FractionContext context{f, meta, o};
  measure_sheets(context, model, r);
  measure_networks(context, model, r);
  if (meta.wall_density && f.wall) measure_wall(context, r);
  if (density_field && f.graded) measure_field_cells(context, model, *density_field, r);
  return r;
}

std::string format_density(const DensityReport& r) {
  std::string out;
  auto line = [&out](const std::string& text) { out += text + "\n"; };
  line("");
  line("5. Relative density: volume fractions of the emitted solids by column integration (columns along x, y");
  line("   and z split by a smooth partition of unity, segment ends by root finding; " +
       fmt::format("{} random shifts of a {}x{} grid of columns per axis, +- the standard error of their mean),",
                   r.sampling.shifts, r.sampling.grid, r.sampling.grid));
  line("   against the density asked of the emitted inverse (sheet: _shell(p, thickness_for_density(rho));");
  line("   network: _offset(p, offset_for_density(rho)) < 0).");
  line(fmt::format(
      "   relations vs the model: max relative difference {:.1e}{}; out-of-range arguments without NaN: {}",
      r.max_relation_error, r.has_float ? fmt::format(" (float: {:.1e})", r.max_float_relation_error) : std::string(),
      r.nan_failures));
  line(
      fmt::format("  {:<8} {:>8} {:>12} {:>12} {:>9} {:>10}", "solid", "rho", "t or h", "measured", "+-", "deviation"));
  for (const DensityRow& row : r.rows)
    line(fmt::format("  {:<8} {:>8g} {:>12.8f} {:>12.8f} {:>9.1e} {:>+10.1e}", row.solid, row.requested, row.parameter,
                     row.measured.value, row.measured.standard_error, row.deviation));
  for (const auto& why : r.skipped) line("  skipped: " + why);
  if (r.field) {
    line(fmt::format("  density field rho(p) = {}, block of {}x{}x{} cells: fraction of each cell vs the mean of rho",
                     *r.field, r.block[0], r.block[1], r.block[2]));
    line(fmt::format("  {:<12} {:>12} {:>12} {:>9} {:>10}", "cell", "mean rho", "measured", "+-", "deviation"));
    for (const DensityCellRow& c : r.cells)
      line(fmt::format("  {:<12} {:>12.8f} {:>12.8f} {:>9.1e} {:>+10.1e}",
                       fmt::format("({}, {}, {})", c.cell[0], c.cell[1], c.cell[2]), c.requested, c.measured.value,
                       c.measured.standard_error, c.deviation));
  }
  return out;
}

nlohmann::ordered_json density_json(const DensityReport& r) {
  using ojson = nlohmann::ordered_json;
  ojson j;
  j["method"] =
      "column integration: segments of g < 0 along columns in x, y and z (scan + Brent), weighted by a smooth "
      "partition of unity; randomly shifted lattices of columns, error = standard error of the mean over the shifts";
  j["grid"] = r.sampling.grid;
  j["shifts"] = r.sampling.shifts;
  j["tolerance"] = r.tolerance;
  j["max_relation_error"] = r.max_relation_error;
  if (r.has_float) j["max_float_relation_error"] = r.max_float_relation_error;
  j["nan_failures"] = r.nan_failures;
  ojson rows = ojson::array();
  for (const DensityRow& row : r.rows)
    rows.push_back({{"solid", row.solid},
                    {"requested", row.requested},
                    {row.solid == "network" ? "h" : "t", row.parameter},
                    {"measured", row.measured.value},
                    {"standard_error", row.measured.standard_error},
                    {"deviation", row.deviation},
                    {"columns", row.measured.columns}});
  j["rows"] = rows;
  j["skipped"] = r.skipped;
  if (r.field) {
    j["field"] = *r.field;
    j["block"] = r.block;
    j["cell_tolerance"] = r.cell_tolerance;
    ojson cells = ojson::array();
    for (const DensityCellRow& c : r.cells)
      cells.push_back({{"cell", c.cell},
                       {"requested_mean", c.requested},
                       {"measured", c.measured.value},
                       {"standard_error", c.measured.standard_error},
                       {"deviation", c.deviation}});
    j["cells"] = cells;
  }
  return j;
}

}  // namespace offsetgen::check
