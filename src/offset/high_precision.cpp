#include "offset/high_precision.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace offsetgen {
namespace {

// GiNaC's precision is a global; hold it for the duration of one evaluation.
class DigitsGuard {
 public:
  explicit DigitsGuard(int digits) : saved_(GiNaC::Digits) { GiNaC::Digits = static_cast<long>(digits); }
  ~DigitsGuard() { GiNaC::Digits = saved_; }
  DigitsGuard(const DigitsGuard&) = delete;
  DigitsGuard& operator=(const DigitsGuard&) = delete;

 private:
  long saved_;
};

GiNaC::numeric as_numeric(const GiNaC::ex& e) {
  GiNaC::ex v = GiNaC::is_a<GiNaC::numeric>(e) ? e : GiNaC::evalf(e);
  if (!GiNaC::is_a<GiNaC::numeric>(v)) throw std::runtime_error("high-precision evaluation did not give a number");
  return GiNaC::ex_to<GiNaC::numeric>(v);
}

bool numeric_less(const GiNaC::numeric& a, const GiNaC::numeric& b) { return a < b; }

}  // namespace

HighPrecisionEvaluator::HighPrecisionEvaluator(const Surface& surface, const OffsetModel& model, SafeguardBounds bounds,
                                               int digits)
    : surface_(surface),
      model_(model),
      bound_(bounds.gradient),
      hessian_bound_(bounds.hessian),
      clamp_(bounds.gradient > 0),
      digits_(digits) {
  DigitsGuard guard(digits_);
  scale_ = as_numeric(surface.scale);
}

HighPrecisionEvaluator::Scope HighPrecisionEvaluator::coordinates(const std::vector<GiNaC::numeric>& x_cell) {
  Scope scope;
  for (int i = 0; i < surface_.dims; ++i)
    scope.bindings.emplace_back(Symbols::get().natural(i), scale_ * x_cell.at(static_cast<size_t>(i)));
  return scope;
}

GiNaC::numeric HighPrecisionEvaluator::eval(const GiNaC::ex& e, Scope& scope, Scope& shared) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e);
  if (GiNaC::is_a<GiNaC::constant>(e)) return as_numeric(e);
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (const auto& [symbol, value] : scope.bindings)
      if (symbol.is_equal(e)) return value;
    const Atom* atom = model_.atoms.find(e);
    if (!atom) throw std::runtime_error("unbound symbol " + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    Scope& home = atom->level == 0 ? shared : scope;
    if (auto it = home.memo.find(e); it != home.memo.end()) return it->second;
    GiNaC::numeric value = eval(atom->definition, scope, shared);
    home.memo.emplace(e, value);
    return value;
  }
  if (auto it = scope.memo.find(e); it != scope.memo.end()) return it->second;
  GiNaC::numeric result;
  if (GiNaC::is_a<GiNaC::add>(e)) {
    result = 0;
    for (size_t i = 0; i < e.nops(); ++i) result += eval(e.op(i), scope, shared);
  } else if (GiNaC::is_a<GiNaC::mul>(e)) {
    result = 1;
    for (size_t i = 0; i < e.nops(); ++i) result *= eval(e.op(i), scope, shared);
  } else if (GiNaC::is_a<GiNaC::power>(e)) {
    GiNaC::numeric base = eval(e.op(0), scope, shared);
    GiNaC::numeric exponent = eval(e.op(1), scope, shared);
    result = exponent.is_integer() ? base.power(exponent) : as_numeric(GiNaC::pow(base, exponent));
  } else if (GiNaC::is_a<GiNaC::function>(e)) {
    GiNaC::exvector args;
    for (size_t i = 0; i < e.nops(); ++i) args.push_back(eval(e.op(i), scope, shared));
    result = as_numeric(GiNaC::function(GiNaC::ex_to<GiNaC::function>(e).get_serial(), args));
  } else {
    throw std::runtime_error("cannot evaluate expression class " + std::string(GiNaC::ex_to<GiNaC::basic>(e).class_name()));
  }
  scope.memo.emplace(e, result);
  return result;
}

GiNaC::numeric HighPrecisionEvaluator::field(const std::vector<GiNaC::numeric>& x_cell) {
  DigitsGuard guard(digits_);
  Scope scope = coordinates(x_cell);
  return eval(model_.field, scope, scope);
}

std::vector<GiNaC::numeric> HighPrecisionEvaluator::field_gradient(const std::vector<GiNaC::numeric>& x_cell) {
  DigitsGuard guard(digits_);
  Scope scope = coordinates(x_cell);
  std::vector<GiNaC::numeric> gradient;
  for (const auto& g : model_.field_gradient) gradient.push_back(scale_ * eval(g, scope, scope));
  return gradient;
}

GiNaC::numeric HighPrecisionEvaluator::eval_sum(const ChainSum& sum, const std::vector<GiNaC::numeric>& x_cell,
                                                const GiNaC::numeric& h_natural) {
  Scope shared = coordinates(x_cell);
  std::map<int, Scope> chains;
  GiNaC::numeric total = 0;
  for (const auto& term : sum) {
    auto [it, fresh] = chains.try_emplace(term.chain);
    if (fresh) {
      it->second = coordinates(x_cell);
      it->second.bindings.emplace_back(Symbols::get().s, h_natural / term.chain);
    }
    total += term.coeff * eval(term.value, it->second, shared);
  }
  return total;
}

GiNaC::numeric HighPrecisionEvaluator::weighted_norms(const std::vector<GiNaC::numeric>& x_cell,
                                                      const GiNaC::numeric& h_cell) {
  DigitsGuard guard(digits_);
  return eval_sum(model_.weighted_norms, x_cell, scale_ * h_cell);
}

GiNaC::numeric HighPrecisionEvaluator::offset(const std::vector<GiNaC::numeric>& x_cell, const GiNaC::numeric& h_cell) {
  DigitsGuard guard(digits_);
  const GiNaC::numeric h = scale_ * h_cell;
  GiNaC::numeric g = eval_sum(model_.weighted_norms, x_cell, h);
  Scope scope = coordinates(x_cell);
  if (clamp_) {
    GiNaC::numeric lo = -bound_, hi = bound_;
    if (model_.order > 1 && hessian_bound_ > 0) {
      const GiNaC::numeric norm = eval(model_.field_gradient_norm, scope, scope);
      const GiNaC::numeric spread = hessian_bound_ * GiNaC::abs(h);
      lo = std::max(lo, norm - GiNaC::numeric(kSafeguardBelow) * spread, numeric_less);
      hi = std::min(hi, norm + GiNaC::numeric(kSafeguardAbove) * spread, numeric_less);
    }
    // In the order the emitted selects test it (lowering/surface_programs.cpp).
    if (!(g <= hi)) {
      g = hi;
    } else if (!(lo <= g)) {
      g = lo;
    }
  }
  return eval(model_.field, scope, scope) - h * g;
}

GiNaC::numeric HighPrecisionEvaluator::shell(const std::vector<GiNaC::numeric>& x_cell, const GiNaC::numeric& t_cell) {
  return offset(x_cell, t_cell / 2) * offset(x_cell, -t_cell / 2);
}

}  // namespace offsetgen
