#include "lowering/surface_programs.h"

#include "lowering/lower.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace offsetgen {
namespace {

std::vector<std::string> coordinate_names(int dims) {
  std::vector<std::string> names = {"x", "y"};
  if (dims == 3) names.push_back("z");
  return names;
}

std::vector<std::string> with(std::vector<std::string> names, const std::string& extra) {
  names.push_back(extra);
  return names;
}

double numeric_value(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

// Lowers one surface's functions into a program: binds natural coordinates X = k x and hands out
// one environment per (offset distance, chain) pair.
class FunctionBuilder {
 public:
  FunctionBuilder(Program& program, const Surface& surface, const OffsetModel& model, SafeguardBounds bounds)
      : program_(program), model_(model), lowerer_(program, model.atoms), bounds_(bounds) {
    const Symbols& sym = Symbols::get();
    NodeId scale = program_.constant(numeric_value(surface.scale));
    scale_ = numeric_value(surface.scale);
    for (int i = 0; i < surface.dims; ++i) {
      NodeId natural = program_.mul(scale, program_.input(i));
      base_.bindings.emplace_back(sym.natural(i), natural);
      cell_.bindings.emplace_back(sym.cell(i), program_.input(i));
    }
    base_.id = base_.shared_id = 0;
    cell_.id = cell_.shared_id = next_id_++;
  }

  NodeId field() { return lowerer_.lower(model_.field, base_); }
  NodeId field_gradient(int i) { return lowerer_.lower(model_.field_gradient[static_cast<size_t>(i)], base_); }
  NodeId cell_expression(const GiNaC::ex& e) { return lowerer_.lower(e, cell_); }

  // h in cell units -> h in natural units
  NodeId natural_distance(NodeId h) { return program_.mul(program_.constant(scale_), h); }

  // sum_j c_j sum_k N_k^(j), each chain j in its own environment (s = h/j).
  NodeId chain_sum(const ChainSum& terms, NodeId h_natural) {
    std::vector<std::pair<GiNaC::numeric, std::vector<NodeId>>> by_chain;
    for (const auto& term : terms) {
      NodeId value = lowerer_.lower(term.value, chain_environment(h_natural, term.chain));
      auto it = std::find_if(by_chain.begin(), by_chain.end(), [&](const auto& c) { return c.first == term.coeff; });
      if (it == by_chain.end()) {
        by_chain.push_back({term.coeff, {value}});
      } else {
        it->second.push_back(value);
      }
    }
    std::vector<NodeId> weighted;
    for (auto& [coeff, values] : by_chain) {
      weighted.push_back(program_.mul(program_.constant(coeff.to_double()), program_.sum(values)));
    }
    return program_.sum(weighted);
  }

  // The safeguard's limits [lo, hi] on G at the distance h (natural units); see SafeguardBounds.
  // lo_moves / hi_moves: whether the limit is the interval's (it varies with p) rather than -M / M;
  // absent at order 1, where only the M clamp applies.
  struct Limits {
    NodeId lo, hi;
    std::optional<NodeId> lo_moves, hi_moves;
  };
  Limits limits(NodeId h) {
    NodeId m = program_.constant(bounds_.gradient);
    Limits l{program_.neg(m), m, std::nullopt, std::nullopt};
    if (model_.order > 1 && bounds_.hessian > 0) {
      NodeId norm = lowerer_.lower(model_.field_gradient_norm, base_);
      NodeId distance = program_.abs(h);
      NodeId below = program_.sub(norm, program_.mul(program_.constant(kSafeguardBelow * bounds_.hessian), distance));
      NodeId above = program_.add(norm, program_.mul(program_.constant(kSafeguardAbove * bounds_.hessian), distance));
      l.lo_moves = program_.less_eq(l.lo, below);
      l.hi_moves = program_.less_eq(above, l.hi);
      l.lo = program_.select(*l.lo_moves, below, l.lo);
      l.hi = program_.select(*l.hi_moves, above, l.hi);
    }
    return l;
  }

  // G inside its limits: <= hi first, so NaN (0/0 at critical points of F) maps to hi, finite.
  NodeId clamp(NodeId g, NodeId h) {
    const Limits l = limits(h);
    return program_.select(program_.less_eq(g, l.hi), program_.select(program_.less_eq(l.lo, g), g, l.lo), l.hi);
  }

  // phi^(m) = F - h G in the cancellation-free form, with the safeguard clamp on G.
  NodeId offset(NodeId h_cell) {
    NodeId h = natural_distance(h_cell);
    NodeId g = chain_sum(model_.weighted_norms, h);
    return program_.sub(field(), program_.mul(h, clamp(g, h)));
  }

  NodeId shell(NodeId t_cell) {
    NodeId half = program_.mul(program_.constant(0.5), t_cell);
    return program_.mul(offset(half), offset(program_.neg(half)));
  }

  // grad phi = grad F - h grad G, or grad F where the clamp is active (G is constant there).
  // Where that gradient is not a finite, positive length (derivatives of |grad F| are 0/0 at
  // critical points of F) the normal falls back to grad F / |grad F|, and to 0 where that vanishes.
  std::vector<NodeId> unit_normal(NodeId h_cell) {
    NodeId h = natural_distance(h_cell);
    NodeId g = chain_sum(model_.weighted_norms, h);
    const Limits l = limits(h);
    NodeId below_hi = program_.less_eq(g, l.hi), above_lo = program_.less_eq(l.lo, g);
    std::vector<NodeId> gradient, field_squares, squares;
    for (int i = 0; i < model_.dims; ++i) {
      NodeId g_i = chain_sum(model_.weighted_norms_gradient[static_cast<size_t>(i)], h);
      NodeId full = program_.sub(field_gradient(i), program_.mul(h, g_i));
      // Clamped to an interval limit |grad F| + c|h|, G varies like |grad F|; clamped to -M or M it is constant.
      NodeId at_lo = field_gradient(i), at_hi = field_gradient(i);
      if (l.hi_moves) {
        NodeId d_norm = lowerer_.lower(model_.field_gradient_norm_gradient[static_cast<size_t>(i)], base_);
        NodeId moving = program_.sub(field_gradient(i), program_.mul(h, d_norm));
        at_lo = program_.select(*l.lo_moves, moving, at_lo);
        at_hi = program_.select(*l.hi_moves, moving, at_hi);
      }
      gradient.push_back(program_.select(below_hi, program_.select(above_lo, full, at_lo), at_hi));
      squares.push_back(program_.mul(gradient.back(), gradient.back()));
      field_squares.push_back(program_.mul(field_gradient(i), field_gradient(i)));
    }
    NodeId zero = program_.constant(0);
    NodeId length2 = program_.sum(squares);
    NodeId field_length2 = program_.sum(field_squares);
    NodeId field_inverse = program_.select(program_.greater(field_length2, zero),
                                           program_.div(program_.constant(1), program_.sqrt(field_length2)), zero);
    NodeId inverse = program_.div(program_.constant(1), program_.sqrt(length2));
    NodeId positive = program_.greater(length2, zero);                   // false for NaN too
    NodeId bounded = program_.less_eq(length2, program_.constant(1e30));  // false for inf and NaN
    std::vector<NodeId> normal;
    for (int i = 0; i < model_.dims; ++i) {
      NodeId fallback = program_.mul(field_gradient(i), field_inverse);
      NodeId unit = program_.mul(gradient[static_cast<size_t>(i)], inverse);
      normal.push_back(program_.select(positive, program_.select(bounded, unit, fallback), fallback));
    }
    return normal;
  }

 private:
  const Environment& chain_environment(NodeId h_natural, int chain) {
    for (const auto& [key, env] : environments_)
      if (key.first == h_natural && key.second == chain) return env;
    Environment env = base_;
    env.id = next_id_++;
    env.shared_id = base_.shared_id;
    NodeId step = program_.mul(h_natural, program_.constant(1.0 / chain));
    env.bindings.emplace_back(Symbols::get().s, step);
    environments_.push_back({{h_natural, chain}, env});
    return environments_.back().second;
  }

  Program& program_;
  const OffsetModel& model_;
  Lowerer lowerer_;
  SafeguardBounds bounds_;
  double scale_ = 1;
  Environment base_, cell_;
  int next_id_ = 1;
  std::vector<std::pair<std::pair<NodeId, int>, Environment>> environments_;
};

}  // namespace

namespace {

// Per start of the compass search; a smooth maximum needs a few hundred.
constexpr int kMaxSearchEvaluations = 20000;

// The maximum of f over one cell [0, extent]^dims: a grid, then compass refinement from the 8 best
// samples. Non-finite values (poles of log, 1/x, ...) are skipped and the refinement is capped, so
// a pole cannot stall it.
double maximum_over_cell(int dims, double extent, const std::function<double(const std::vector<double>&)>& f,
                         const char* what) {
  const int n = dims == 3 ? 24 : 96;
  std::vector<std::pair<double, std::vector<double>>> best;
  std::vector<double> p(static_cast<size_t>(dims));
  const int total = dims == 3 ? n * n * n : n * n;
  for (int index = 0; index < total; ++index) {
    int rest = index;
    for (int i = 0; i < dims; ++i) {
      p[static_cast<size_t>(i)] = extent * (rest % n + 0.5) / n;
      rest /= n;
    }
    const double value = f(p);
    if (std::isfinite(value)) best.push_back({value, p});
  }
  if (best.empty())
    throw std::runtime_error(std::string(what) + " is not finite anywhere on the sampled cell, so the safeguard has "
                             "no bound");
  const size_t starts = std::min<size_t>(8, best.size());
  std::partial_sort(best.begin(), best.begin() + static_cast<long>(starts), best.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });

  double maximum = best.front().first;
  for (size_t s = 0; s < starts; ++s) {
    auto [value, point] = best[s];
    int evaluations = 0;
    for (double step = extent / n; step > extent * 1e-13 && evaluations < kMaxSearchEvaluations;) {
      bool improved = false;
      for (int i = 0; i < dims && !improved; ++i) {
        for (double direction : {1.0, -1.0}) {
          auto trial = point;
          trial[static_cast<size_t>(i)] = std::clamp(trial[static_cast<size_t>(i)] + direction * step, 0.0, extent);
          const double v = f(trial);
          ++evaluations;
          if (std::isfinite(v) && v > value) {
            value = v;
            point = trial;
            improved = true;
            break;
          }
        }
      }
      if (!improved) step *= 0.5;
    }
    maximum = std::max(maximum, value);
  }
  return maximum;
}

// Largest |eigenvalue| of a symmetric 2x2 or 3x3 matrix (row-major), in closed form.
double symmetric_spectral_norm(const std::vector<double>& a, int dims) {
  if (dims == 2) {
    const double mean = (a[0] + a[3]) / 2, radius = std::hypot((a[0] - a[3]) / 2, a[1]);
    return std::fabs(mean) + radius;
  }
  const double off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
  const double q = (a[0] + a[4] + a[8]) / 3;
  const double d0 = a[0] - q, d1 = a[4] - q, d2 = a[8] - q;
  const double p = std::sqrt((d0 * d0 + d1 * d1 + d2 * d2 + 2 * off) / 6);
  if (!(p > 0)) return std::fabs(q);
  // Eigenvalues q + 2p cos(theta + 2 pi k / 3), theta = acos(det((A - q I) / p) / 2) / 3.
  const double det = d0 * (d1 * d2 - a[5] * a[5]) - a[1] * (a[1] * d2 - a[5] * a[2]) + a[2] * (a[1] * a[5] - d1 * a[2]);
  const double r = std::clamp(det / (2 * p * p * p), -1.0, 1.0);
  const double theta = std::acos(r) / 3;
  const double largest = q + 2 * p * std::cos(theta);
  const double smallest = q + 2 * p * std::cos(theta + 2.0943951023931957);
  return std::max(std::fabs(largest), std::fabs(smallest));
}

// Lowers expressions of the natural coordinates into one program with one output each.
Program natural_program(const OffsetModel& model, int dims, const std::vector<GiNaC::ex>& outputs) {
  Program program(coordinate_names(dims));
  Lowerer lowerer(program, model.atoms);
  Environment env;
  const Symbols& sym = Symbols::get();
  for (int i = 0; i < dims; ++i) env.bindings.emplace_back(sym.natural(i), program.input(i));
  for (size_t k = 0; k < outputs.size(); ++k) program.add_output("o" + std::to_string(k), lowerer.lower(outputs[k], env));
  return program;
}

}  // namespace

double max_gradient_norm(const Surface& surface, const OffsetModel& model) {
  const Program program = natural_program(model, surface.dims, model.field_gradient);
  Evaluator gradient(program);  // keeps a reference to the program
  auto norm2 = [&](const std::vector<double>& p) {
    double sum = 0;
    for (double g : gradient(p)) sum += g * g;
    return sum;
  };
  const double maximum = maximum_over_cell(surface.dims, numeric_value(surface.scale), norm2, "the gradient of F");
  // A relative margin well above the refinement's resolution keeps M an upper bound, also after
  // rounding to float.
  return std::sqrt(maximum) * (1 + 1e-6);
}

double max_hessian_norm(const Surface& surface, const OffsetModel& model) {
  if (model.field_hessian.empty()) return 0;
  std::vector<GiNaC::ex> entries;
  for (const auto& row : model.field_hessian) entries.insert(entries.end(), row.begin(), row.end());
  const Program program = natural_program(model, surface.dims, entries);
  Evaluator hessian(program);
  auto norm = [&](const std::vector<double>& p) { return symmetric_spectral_norm(hessian(p), surface.dims); };
  return maximum_over_cell(surface.dims, numeric_value(surface.scale), norm, "the Hessian of F") * (1 + 1e-6);
}

SurfacePrograms lower_surface(const Surface& surface, const OffsetModel& model, const LoweringOptions& options) {
  SurfacePrograms out;
  out.gradient_bound = max_gradient_norm(surface, model);
  out.hessian_bound = max_hessian_norm(surface, model);
  const SafeguardBounds bounds{out.gradient_bound, out.hessian_bound};
  const auto coords = coordinate_names(surface.dims);
  const int n_coords = surface.dims;

  out.field = Program(coords);
  {
    FunctionBuilder b(out.field, surface, model, bounds);
    out.field.add_output("F", b.field());
  }
  out.offset = Program(with(coords, "h"));
  {
    FunctionBuilder b(out.offset, surface, model, bounds);
    out.offset.add_output("phi", b.offset(out.offset.input(n_coords)));
  }
  out.shell = Program(with(coords, "t"));
  {
    FunctionBuilder b(out.shell, surface, model, bounds);
    out.shell.add_output("Phi", b.shell(out.shell.input(n_coords)));
  }
  if (!model.weighted_norms_gradient.empty()) {
    out.normal = Program(with(coords, "h"));
    FunctionBuilder b(out.normal, surface, model, bounds);
    auto n = b.unit_normal(out.normal.input(n_coords));
    for (size_t i = 0; i < n.size(); ++i) out.normal.add_output("n" + std::to_string(i), n[i]);
  }
  if (options.thickness) {
    out.graded = Program(coords);
    FunctionBuilder b(*out.graded, surface, model, bounds);
    out.graded->add_output("Phi", b.shell(b.cell_expression(*options.thickness)));
  }
  return out;
}

}  // namespace offsetgen
