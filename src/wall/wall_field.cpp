#include "wall/wall_field.h"

#include "density/density_model.h"
#include "density/surface_constants.h"
#include "offset/surface_programs.h"
#include "run/c_library.h"
#include "run/process.h"
#include "support/stopwatch.h"
#include "surfaces/expression_input.h"
#include "validate/wall_choice.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace offsetgen::wall {
namespace {

namespace fs = std::filesystem;

// "0.1" -> 0.1; nullopt for anything that is not one plain number.
std::optional<double> plain_number(const std::string& text) {
  try {
    size_t used = 0;
    double value = std::stod(text, &used);
    while (used < text.size() && std::isspace(static_cast<unsigned char>(text[used]))) ++used;
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// The wrapper exports the header's static inline functions with unmangled names.
std::string wrapper_source(const std::string& header, const std::string& prefix) {
  return fmt::format(
      "/* offsetgen mesh: exports the header's functions for dlopen. */\n"
      "#include \"{0}\"\n"
      "void offsetgen_mesh_offset_n(size_t n, const double *x, const double *y, const double *z, "
      "const double *h, double *out);\n"
      "void offsetgen_mesh_offset_n(size_t n, const double *x, const double *y, const double *z, "
      "const double *h, double *out) {{ {1}_offset_n(n, x, y, z, h, out); }}\n"
      "double offsetgen_mesh_field(double x, double y, double z);\n"
      "double offsetgen_mesh_field(double x, double y, double z) {{ return {1}_field(x, y, z); }}\n",
      header, prefix);
}

}  // namespace

WallField::WallField(const WallRequest& request) {
  auto start = std::chrono::steady_clock::now();
  GenerationRequest g = request.generation;
  g.languages = {"c"};
  g.precisions = {Precision::Double};
  if (g.name.empty() && !g.expression.empty()) g.name = "user_surface";
  check_wall_choice(!request.thickness.empty(), g.density.has_value(), g.density_field.has_value(), WallNeed::Required);
  const std::optional<double> number = plain_number(request.thickness);
  if (!request.thickness.empty() && !number)
    g.thickness = request.thickness;  // lets --param values reach the thickness expression
  network_ = request.network;
  // --density with --network: the network's density, not the sheet's (NaN: none given).
  const double network_density = network_ && g.density ? *g.density : std::nan("");
  if (network_) {
    if (g.density_field)
      throw InputError(
          "--density-field grades a sheet: with --network give --density R (uniform) or --thickness H as an "
          "expression of x, y, z (the offset h, graded)");
    // The header's _wall would be the sheet of that density: ask only for the relations.
    g.density.reset();
    g.density_functions = g.density_functions || !std::isnan(network_density);
  }
  generation_ = generate(g);
  const Surface& surface = generation_.surface;
  if (surface.dims != 3)
    throw InputError(fmt::format("'{}' is a 2D surface (x, y); mesh needs a surface of x, y and z", surface.name));
  // A network's offset is bounded by the curvature limit (the sheet's thickness by the safeguards).
  if (generation_.density) {
    density_ = generation_.density;
  } else if (network_ && surface.from_catalog && !density::density_unavailable(surface)) {
    density_ = density::DensityModel(density::surface_constants(surface));
  }

  if (!std::isnan(network_density)) {
    const density::DensityModel& m = *generation_.density;
    const double rho = network_density;
    if (!(rho >= m.network_density_min() && rho <= m.network_density_max()))
      throw InputError(fmt::format(
          "--density {} with --network is outside [{:.4f}, {:.4f}], the network densities of {} whose offset stays "
          "within its curvature limit |h| <= {:.4f}",
          rho, m.network_density_min(), m.network_density_max(), surface.name, m.offset_limit()));
    uniform_thickness_ = m.network_offset(rho);  // the offset h of that density
  } else if (g.density) {
    uniform_thickness_ = *generation_.wall_thickness;  // t of the sheet of relative density R
  } else if (g.density_field) {
    graded_ = true;  // t(p) = thickness_for_density(rho(p))
    thickness_program_ = lower_thickness(surface, *generation_.construction, *generation_.graded_thickness);
  } else if (number) {
    uniform_thickness_ = *number;
  } else {
    GiNaC::ex t = parse_thickness_expression(request.thickness, g.params, 3);
    GiNaC::ex value = GiNaC::evalf(t);
    if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_real()) {
      uniform_thickness_ = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    } else {
      graded_ = true;
      thickness_program_ = lower_thickness(surface, *generation_.construction, t);
    }
  }
  if (!graded_ && !network_ && !(uniform_thickness_ > 0 && std::isfinite(uniform_thickness_)))
    throw InputError(fmt::format("--thickness {} is not a positive wall thickness (cell units)", request.thickness));
  if (!graded_ && network_) check_offset(uniform_thickness_, nullptr);

  const double k = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
  const double m = generation_.construction->bounds().gradient;
  lipschitz_ = k * m;
  if (!(lipschitz_ > 0 && std::isfinite(lipschitz_)))
    throw InputError(fmt::format("the gradient of '{}' has no finite positive bound over the cell", surface.name));
  distance_scale_ = 1.0 / lipschitz_;
  generate_seconds_ = seconds_since(start);
}

void WallField::compile() {
  // The header's documented build of the batch API (-O3 -march=native -fno-math-errno: the loops
  // vectorise; ~8x faster than -O2 for the gyroid at order 4), without contraction into FMA so the
  // values, and the mesh, do not depend on the CPU. -O0 for very large functions, as `check` does.
  const auto start = std::chrono::steady_clock::now();
  run::Toolchain tools = run::find_toolchain();
  const bool large = count_ops(generation_.programs.offset) > run::kLargeFunctionOps;
  compile_flags_ = large ? "-O0" : "-O3 -march=native -fno-math-errno";
  const run::ScratchDir scratch("offsetgen-mesh");  // removed on exit (a loaded library's mapping stays)
  const std::string header = generation_.prefix + ".h";
  std::ofstream(scratch.path() / header) << generation_.c_header();
  std::ofstream(scratch.path() / "wrapper.c") << wrapper_source(header, generation_.prefix);
  std::vector<std::string> flags = run::split_words(compile_flags_);
  flags.push_back("-I" + scratch.path().string());
  library_ = run::build_shared_object(tools, flags, (scratch.path() / "wrapper.c").string(),
                                      (scratch.path() / "wrapper.so").string());
  offset_n_ = library_->symbol<OffsetN>("offsetgen_mesh_offset_n");
  field_ = library_->symbol<Field>("offsetgen_mesh_field");
  if (offset_n_ == nullptr || field_ == nullptr) throw std::runtime_error("dlsym: the wrapper lacks its functions");
  compile_seconds_ = seconds_since(start);
}

WallField::~WallField() = default;

WallField::Worker::Worker(const WallField& field) : input(3) {
  if (field.graded_) thickness = std::make_unique<Evaluator>(field.thickness_program_);
}

WallField::Worker::~Worker() = default;

double WallField::thickness_at(double x, double y, double z, Worker& worker) const {
  if (!graded_) return uniform_thickness_;
  worker.input[0] = x;
  worker.input[1] = y;
  worker.input[2] = z;
  return (*worker.thickness)(worker.input)[0];
}

void WallField::check_offset(double h, const double* at) const {
  const std::string where = at ? fmt::format(" at (x, y, z) = ({}, {}, {})", at[0], at[1], at[2]) : std::string();
  if (!std::isfinite(h)) throw InputError(fmt::format("the network's offset h is {}{}: it must be finite", h, where));
  if (density_ && !(std::abs(h) <= density_->offset_limit()))
    throw InputError(fmt::format(
        "the network's offset h = {:.6g}{} is beyond {}'s curvature limit |h| <= {:.4f}: the offset surface folds "
        "over itself there",
        h, where, generation_.surface.name, density_->offset_limit()));
}

WallExtent WallField::extent(const std::array<double, 2>& range) const {
  if (!network_) return {range[0], 0.5 * range[1]};
  const double reach = std::max(std::abs(range[0]), std::abs(range[1]));
  // Without a density model there is no curvature limit to measure the necks by: a quarter cell.
  const double thinnest = density_ ? 2 * (density_->offset_limit() - reach) : 0.25;
  return {std::max(thinnest, 0.05), reach};
}

std::array<double, 2> WallField::thickness_range(const std::array<int, 3>& cells) const {
  return thickness_range({0, 0, 0}, {double(cells[0]), double(cells[1]), double(cells[2])});
}

std::array<double, 2> WallField::thickness_range(const std::array<double, 3>& box_lo,
                                                 const std::array<double, 3>& box_hi) const {
  if (!graded_) return {uniform_thickness_, uniform_thickness_};
  constexpr int kPerCell = 8;
  Worker worker(*this);
  std::array<int, 3> steps{};
  for (size_t a = 0; a < 3; ++a)
    steps[a] = std::max(1, static_cast<int>(std::ceil((box_hi[a] - box_lo[a]) * kPerCell - 1e-9)));
  auto at = [&](size_t a, int i) { return box_lo[a] + (box_hi[a] - box_lo[a]) * i / steps[a]; };
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 0; i <= steps[0]; ++i)
    for (int j = 0; j <= steps[1]; ++j)
      for (int l = 0; l <= steps[2]; ++l) {
        const double x = at(0, i), y = at(1, j), z = at(2, l);
        const double t = thickness_at(x, y, z, worker);
        if (network_) {
          const double point[3] = {x, y, z};
          check_offset(t, point);
        } else if (!(t > 0) || !std::isfinite(t))
          throw InputError(
              fmt::format("the wall thickness is {} at (x, y, z) = ({}, {}, {}): it must be positive "
                          "everywhere in the block",
                          t, x, y, z));
        lo = std::min(lo, t);
        hi = std::max(hi, t);
      }
  return {lo, hi};
}

std::optional<double> WallField::uniform_density() const {
  if (graded_) return std::nullopt;
  if (network_) return density_ ? std::optional<double>(density_->network_density(uniform_thickness_)) : std::nullopt;
  if (generation_.density) return generation_.density->sheet_density(uniform_thickness_);
  const Surface& surface = generation_.surface;
  if (!surface.from_catalog || density::density_unavailable(surface)) return std::nullopt;
  const double rho = density::DensityModel(density::surface_constants(surface)).sheet_density(uniform_thickness_);
  return std::isfinite(rho) ? std::optional<double>(rho) : std::nullopt;
}

void WallField::walls(size_t n, const double* x, const double* y, const double* z, double* w, Worker& worker) const {
  if (network_) {
    worker.h_plus.resize(n);
    for (size_t i = 0; i < n; ++i) worker.h_plus[i] = thickness_at(x[i], y[i], z[i], worker);
    offset_n_(n, x, y, z, worker.h_plus.data(), w);
    for (size_t i = 0; i < n; ++i) w[i] *= distance_scale_;
    return;
  }
  worker.h_plus.resize(n);
  worker.h_minus.resize(n);
  worker.plus.resize(n);
  worker.minus.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double half = 0.5 * thickness_at(x[i], y[i], z[i], worker);
    worker.h_plus[i] = half;
    worker.h_minus[i] = -half;
  }
  offset_n_(n, x, y, z, worker.h_plus.data(), worker.plus.data());
  offset_n_(n, x, y, z, worker.h_minus.data(), worker.minus.data());
  for (size_t i = 0; i < n; ++i) w[i] = std::max(worker.plus[i], -worker.minus[i]) * distance_scale_;
}

}  // namespace offsetgen::wall
