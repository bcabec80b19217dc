#include "field/symbolic_diff.h"

#include <stdexcept>

namespace offsetgen {
namespace {

bool partial_key_less(const std::pair<GiNaC::ex, MultiIndex>& a, const std::pair<GiNaC::ex, MultiIndex>& b) {
  if (a.second != b.second) return a.second < b.second;
  return a.first.compare(b.first) < 0;
}

}  // namespace

MemoDiff::MemoDiff(std::vector<GiNaC::symbol> variables)
    : variables_(std::move(variables)), cache_(variables_.size()), partials_(partial_key_less) {}

GiNaC::ex MemoDiff::diff(const GiNaC::ex& e, int variable) {
  if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return 0;
  if (GiNaC::is_a<GiNaC::symbol>(e)) return e.is_equal(variables_[static_cast<size_t>(variable)]) ? 1 : 0;
  auto& cache = cache_[static_cast<size_t>(variable)];
  if (auto it = cache.find(e); it != cache.end()) return it->second;
  GiNaC::ex result = diff_uncached(e, variable);
  cache.emplace(e, result);
  return result;
}

GiNaC::ex MemoDiff::diff_uncached(const GiNaC::ex& e, int variable) {
  if (GiNaC::is_a<GiNaC::add>(e)) {
    GiNaC::exvector terms;
    terms.reserve(e.nops());
    for (size_t i = 0; i < e.nops(); ++i) terms.push_back(diff(e.op(i), variable));
    return GiNaC::add(terms);
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    GiNaC::exvector terms;
    for (size_t i = 0; i < e.nops(); ++i) {
      GiNaC::ex d = diff(e.op(i), variable);
      if (d.is_zero()) continue;
      GiNaC::exvector factors;
      factors.reserve(e.nops());
      for (size_t k = 0; k < e.nops(); ++k) factors.push_back(k == i ? d : e.op(k));
      terms.push_back(GiNaC::mul(factors));
    }
    return GiNaC::add(terms);
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const GiNaC::ex base = e.op(0);
    const GiNaC::ex exponent = e.op(1);
    GiNaC::ex db = diff(base, variable);
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
      if (db.is_zero()) return 0;
      return exponent * GiNaC::pow(base, exponent - 1) * db;
    }
    GiNaC::ex de = diff(exponent, variable);
    return e * (de * GiNaC::log(base) + exponent * db / base);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    GiNaC::exvector terms;
    for (size_t i = 0; i < e.nops(); ++i) {
      GiNaC::ex da = diff(e.op(i), variable);
      if (da.is_zero()) continue;
      terms.push_back(function_derivative(e, i) * da);
    }
    return GiNaC::add(terms);
  }
  throw std::invalid_argument("cannot differentiate expression of class " +
                              std::string(GiNaC::ex_to<GiNaC::basic>(e).class_name()));
}

// Outer derivative of f with respect to one argument: differentiate f(t) by a fresh symbol t, then
// put the argument back. Works for every GiNaC function that knows its derivative.
GiNaC::ex MemoDiff::function_derivative(const GiNaC::ex& f, size_t argument) {
  GiNaC::symbol t("t_arg");
  GiNaC::ex arg = f.op(argument);
  if (f.nops() == 1) return f.subs(arg == t).diff(t).subs(t == arg);
  // Several arguments (atan2): put t in this argument's place only; subs would also replace any
  // occurrence of `arg` inside the other arguments.
  GiNaC::exvector args(f.begin(), f.end());
  args[argument] = t;
  const GiNaC::ex with_symbol = GiNaC::function(GiNaC::ex_to<GiNaC::function>(f).get_serial(), args);
  return with_symbol.diff(t).subs(t == arg);
}

GiNaC::ex MemoDiff::partial(const GiNaC::ex& e, const MultiIndex& alpha) {
  if (total_order(alpha) == 0) return e;
  auto key = std::make_pair(e, alpha);
  if (auto it = partials_.find(key); it != partials_.end()) return it->second;
  int last = alpha[2] > 0 ? 2 : (alpha[1] > 0 ? 1 : 0);
  GiNaC::ex result = diff(partial(e, alpha - unit_index(last)), last);
  partials_.emplace(key, result);
  return result;
}

}  // namespace offsetgen
