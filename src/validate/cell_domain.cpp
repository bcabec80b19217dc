#include "validate/cell_domain.h"

#include "field/atom_table.h"
#include "lowering/lower.h"
#include "lowering/point_program.h"
#include "lowering/sample_region.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <vector>

namespace offsetgen {
namespace {

// Entries of the Hessian above this everywhere leave the safeguard without a bound.
constexpr double kMaxHessianEntry = 1e100;

// Centred samples of the region (cell coordinates), as dense as the safeguard's bound search: 24^3
// in 3D, 96^2 in 2D. They avoid the box's faces, where log(x) or 1/x have their poles. A mapped
// surface's region (lowering/sample_region.h) skips points near the map's singular set.
std::vector<std::vector<double>> region_samples(SampleRegion& region, double scale) {
  const int dims = region.dims();
  const int n = dims == 3 ? 24 : 96;
  const int total = dims == 3 ? n * n * n : n * n;
  std::vector<std::vector<double>> points;
  points.reserve(static_cast<size_t>(total));
  std::vector<double> natural(static_cast<size_t>(dims));
  for (int index = 0; index < total; ++index) {
    std::vector<double> p(static_cast<size_t>(dims));
    int rest = index;
    for (int i = 0; i < dims; ++i) {
      const double lo = region.lo(i) / scale, hi = region.hi(i) / scale;
      p[static_cast<size_t>(i)] = lo + (hi - lo) * (rest % n + 0.5) / n;
      natural[static_cast<size_t>(i)] = scale * p[static_cast<size_t>(i)];
      rest /= n;
    }
    if (region.contains(natural)) points.push_back(p);
  }
  return points;
}

// The first operation (in evaluation order) that turned finite or infinite operands into NaN.
std::string nan_cause(const Program& program, const std::vector<NodeId>& order, const std::vector<double>& v) {
  for (NodeId id : order) {
    const Node& n = program.node(id);
    if (!std::isnan(v[static_cast<size_t>(id)])) continue;
    const double a = n.a >= 0 ? v[static_cast<size_t>(n.a)] : 0, b = n.b >= 0 ? v[static_cast<size_t>(n.b)] : 0;
    if (std::isnan(a) || std::isnan(b)) continue;
    switch (n.op) {
      case Op::Sqrt:
        return fmt::format("sqrt({:.6g}), the square root of a negative number", a);
      case Op::Pow:
        return fmt::format("{:.6g}^{:.6g}, a negative number to a fractional power", a, b);
      case Op::Call:
        if (n.fn == Fn::Log) return fmt::format("log({:.6g}), the logarithm of a negative number", a);
        if (n.fn == Fn::Asin || n.fn == Fn::Acos)
          return fmt::format("{}({:.6g}), outside [-1, 1]", function_name(n.fn), a);
        return fmt::format("{}({:.6g}), which overflows", function_name(n.fn), a);
      case Op::Atan2:
        return "atan2 of an infinite or undefined argument";
      case Op::Add:
      case Op::Sub:
        return "inf - inf: the value overflows double precision there";
      case Op::Mul:
        return "0 * inf: a pole or an overflow";
      case Op::Div:
        return "0/0 or inf/inf: a pole or an overflow";
      default:
        return "an operation without a real value";
    }
  }
  return "a value that is not a real number";
}

// Evaluates `outputs` (expressions of the symbols bound to the inputs) at every cell sample and calls
// `judge(point, values)`; on NaN, throws InputError built from `what` and the NaN's cause.
template <typename Judge>
void sample(const std::vector<GiNaC::ex>& outputs, const std::vector<std::string>& output_names,
            const std::vector<GiNaC::ex>& symbols, double scale, SampleRegion& region, double region_scale,
            Judge judge) {
  const int dims = region.dims();
  const Program program = point_program(dims, outputs, AtomTable(), symbols, scale);
  Evaluator evaluate(program);
  const std::vector<NodeId> order = schedule(program);
  for (const auto& p : region_samples(region, region_scale)) {
    const std::vector<double>& values = evaluate(p);
    for (size_t k = 0; k < values.size(); ++k) {
      if (std::isnan(values[k]))
        throw InputError(fmt::format("{} is not defined everywhere in {}: at {} it takes {}", output_names[k],
                                     region.describe(), point_text(p),
                                     nan_cause(program, order, evaluate.node_values())));
    }
    judge(p, values);
  }
}

}  // namespace

void require_defined_on_cell(const Surface& surface) {
  // F, its gradient and its Hessian: the model needs all three (the safeguard bounds the last two).
  const Symbols& sym = Symbols::get();
  const int d = surface.dims;
  std::vector<GiNaC::ex> symbols, outputs = {surface.field};
  std::vector<std::string> names = {"F"};
  for (int i = 0; i < d; ++i) {
    symbols.push_back(sym.natural(i));
    outputs.push_back(surface.field.diff(sym.natural(i)));
    names.push_back(std::string("the derivative dF/d") + "xyz"[i] + " of F");
  }
  for (int i = 0; i < d; ++i) {
    for (int j = i; j < d; ++j) {
      outputs.push_back(outputs[static_cast<size_t>(1 + i)].diff(sym.natural(j)));
      names.push_back(fmt::format("the second derivative d2F/d{}d{} of F", "xyz"[i], "xyz"[j]));
    }
  }
  const double scale = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
  bool value = false, gradient = false, hessian = false;  // finite somewhere
  // The safeguard's bound search (and the emitted normal) sums squares: |grad F|^2 and the Hessian's
  // squared entries must not overflow either (a gradient of 1e211 has a finite value but an infinite
  // square: a fuzz finding).
  auto all_finite = [](const std::vector<double>& v, size_t from, size_t to) {
    double squares = 0;
    for (size_t k = from; k < to; ++k) squares += v[k] * v[k];
    return std::isfinite(squares);
  };
  const size_t n_gradient = 1 + static_cast<size_t>(d);
  // The bound of the Hessian's spectral norm is computed in closed form, which cubes its entries.
  auto tame = [](const std::vector<double>& v, size_t from, size_t to) {
    for (size_t k = from; k < to; ++k)
      if (!(std::fabs(v[k]) <= kMaxHessianEntry)) return false;
    return true;
  };
  SampleRegion region(surface);
  sample(outputs, names, symbols, scale, region, scale, [&](const std::vector<double>&, const std::vector<double>& v) {
    value = value || std::isfinite(v[0]);
    gradient = gradient || all_finite(v, 1, n_gradient);
    hessian = hessian || tame(v, n_gradient, v.size());
  });
  const char* what = !value ? "F" : (!gradient ? "the gradient of F" : (!hessian ? "the Hessian of F" : nullptr));
  if (what)
    throw InputError(
        fmt::format("{} is infinite at every sample of {}, or so large that {}: it "
                    "overflows double precision",
                    what, region.describe(),
                    what == std::string("the Hessian of F") ? "an entry exceeds 1e100 (its cube overflows)"
                                                            : "its square overflows"));
}

void require_positive_thickness(const Surface& surface, const GiNaC::ex& thickness, const std::string& text) {
  const Symbols& sym = Symbols::get();
  const std::vector<GiNaC::ex> symbols = {sym.x, sym.y, sym.z};
  const std::string what = fmt::format("the thickness '{}'", text);
  SampleRegion region(surface);
  const double scale = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
  sample({thickness}, {what}, symbols, 1.0, region, scale,
         [&](const std::vector<double>& p, const std::vector<double>& v) {
           if (!(v[0] > 0) || !std::isfinite(v[0]))
             throw InputError(
                 fmt::format("{} must be a finite wall thickness > 0 ({}) everywhere in {}, but at {} it is {:.6g}",
                             what, surface.mapped() ? "physical units" : "cell units",
                             surface.mapped() ? region.describe() : "the cell", point_text(p), v[0]));
         });
}

void require_positive_thickness(const GiNaC::ex& thickness, int dims, const std::string& text) {
  Surface cell;
  cell.dims = dims;
  cell.scale = 1;
  require_positive_thickness(cell, thickness, text);
}

}  // namespace offsetgen
