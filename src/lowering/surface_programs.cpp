#include "lowering/surface_programs.h"

#include "lowering/lower.h"

#include <algorithm>
#include <cmath>
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
  FunctionBuilder(Program& program, const Surface& surface, const OffsetModel& model, double bound)
      : program_(program), model_(model), lowerer_(program, model.atoms), bound_(bound) {
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

  NodeId inside_bound(NodeId g) { return program_.less_eq(program_.abs(g), program_.constant(bound_)); }

  NodeId clamp_to_bound(NodeId g) {
    NodeId limit = program_.constant(bound_);
    NodeId saturated = program_.select(program_.greater(g, program_.constant(0)), limit, program_.neg(limit));
    return program_.select(inside_bound(g), g, saturated);
  }

  // phi^(m) = F - h G in the cancellation-free form, with the safeguard clamp on G.
  NodeId offset(NodeId h_cell) {
    NodeId h = natural_distance(h_cell);
    NodeId g = chain_sum(model_.weighted_norms, h);
    return program_.sub(field(), program_.mul(h, clamp_to_bound(g)));
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
    NodeId inside = inside_bound(chain_sum(model_.weighted_norms, h));
    std::vector<NodeId> gradient, field_squares, squares;
    for (int i = 0; i < model_.dims; ++i) {
      NodeId g_i = chain_sum(model_.weighted_norms_gradient[static_cast<size_t>(i)], h);
      NodeId full = program_.sub(field_gradient(i), program_.mul(h, g_i));
      gradient.push_back(program_.select(inside, full, field_gradient(i)));
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
  double bound_;
  double scale_ = 1;
  Environment base_, cell_;
  int next_id_ = 1;
  std::vector<std::pair<std::pair<NodeId, int>, Environment>> environments_;
};

}  // namespace

// Per start of the compass search; a smooth maximum needs a few hundred.
constexpr int kMaxSearchEvaluations = 20000;

double max_gradient_norm(const Surface& surface, const OffsetModel& model) {
  const int dims = surface.dims;
  Program program(coordinate_names(dims));
  Lowerer lowerer(program, model.atoms);
  Environment env;
  const Symbols& sym = Symbols::get();
  for (int i = 0; i < dims; ++i) env.bindings.emplace_back(sym.natural(i), program.input(i));
  std::vector<NodeId> squares;
  for (const auto& g : model.field_gradient) {
    NodeId d = lowerer.lower(g, env);
    squares.push_back(program.mul(d, d));
  }
  program.add_output("grad2", program.sum(squares));
  Evaluator grad2(program);

  const double extent = numeric_value(surface.scale);  // one cell in natural units
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
    const double value = grad2(p)[0];
    if (std::isfinite(value)) best.push_back({value, p});  // poles (log, 1/x) cannot be the bound
  }
  if (best.empty())
    throw std::runtime_error("the gradient of F is not finite anywhere on the sampled cell, so no bound M "
                             "for the safeguard exists");
  const size_t starts = std::min<size_t>(8, best.size());
  std::partial_sort(best.begin(), best.begin() + static_cast<long>(starts), best.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });

  double maximum = best.front().first;
  for (size_t s = 0; s < starts; ++s) {
    auto [value, point] = best[s];
    // Capped: near a pole the search would otherwise creep towards it one tiny step at a time.
    int evaluations = 0;
    for (double step = extent / n; step > extent * 1e-13 && evaluations < kMaxSearchEvaluations;) {
      bool improved = false;
      for (int i = 0; i < dims && !improved; ++i) {
        for (double direction : {1.0, -1.0}) {
          auto trial = point;
          trial[static_cast<size_t>(i)] = std::clamp(trial[static_cast<size_t>(i)] + direction * step, 0.0, extent);
          const double v = grad2(trial)[0];
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
  // A relative margin well above the refinement's resolution keeps M an upper bound, also after
  // rounding to float.
  return std::sqrt(maximum) * (1 + 1e-6);
}

SurfacePrograms lower_surface(const Surface& surface, const OffsetModel& model, const LoweringOptions& options) {
  SurfacePrograms out;
  out.gradient_bound = max_gradient_norm(surface, model);
  const auto coords = coordinate_names(surface.dims);
  const int n_coords = surface.dims;

  out.field = Program(coords);
  {
    FunctionBuilder b(out.field, surface, model, out.gradient_bound);
    out.field.add_output("F", b.field());
  }
  out.offset = Program(with(coords, "h"));
  {
    FunctionBuilder b(out.offset, surface, model, out.gradient_bound);
    out.offset.add_output("phi", b.offset(out.offset.input(n_coords)));
  }
  out.shell = Program(with(coords, "t"));
  {
    FunctionBuilder b(out.shell, surface, model, out.gradient_bound);
    out.shell.add_output("Phi", b.shell(out.shell.input(n_coords)));
  }
  if (!model.weighted_norms_gradient.empty()) {
    out.normal = Program(with(coords, "h"));
    FunctionBuilder b(out.normal, surface, model, out.gradient_bound);
    auto n = b.unit_normal(out.normal.input(n_coords));
    for (size_t i = 0; i < n.size(); ++i) out.normal.add_output("n" + std::to_string(i), n[i]);
  }
  if (options.thickness) {
    out.graded = Program(coords);
    FunctionBuilder b(*out.graded, surface, model, out.gradient_bound);
    out.graded->add_output("Phi", b.shell(b.cell_expression(*options.thickness)));
  }
  return out;
}

}  // namespace offsetgen
