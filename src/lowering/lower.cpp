#include "lowering/lower.h"

#include <map>
#include <stdexcept>
#include <string>

namespace offsetgen {
namespace {

Fn function_of(const std::string& name) {
  static const std::map<std::string, Fn> table = {
      {"sin", Fn::Sin},   {"cos", Fn::Cos},   {"tan", Fn::Tan},   {"exp", Fn::Exp},
      {"log", Fn::Log},   {"sinh", Fn::Sinh}, {"cosh", Fn::Cosh}, {"tanh", Fn::Tanh},
      {"atan", Fn::Atan}, {"asin", Fn::Asin}, {"acos", Fn::Acos}};
  auto it = table.find(name);
  if (it == table.end()) throw std::invalid_argument("cannot lower function '" + name + "'");
  return it->second;
}

bool is_integer(const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_integer(); }

bool is_half_integer(const GiNaC::ex& e) {
  if (!GiNaC::is_a<GiNaC::numeric>(e)) return false;
  const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
  return n.is_rational() && n.denom() == 2;
}

}  // namespace

NodeId Lowerer::lower(const GiNaC::ex& e, const Environment& env) {
  if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return lower_numeric(e);
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (const auto& [symbol, node] : env.bindings)
      if (symbol.is_equal(e)) return node;
    const Atom* atom = atoms_.find(e);
    if (!atom) throw std::invalid_argument("unbound symbol in lowering: " + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    int memo_id = atom->level == 0 ? env.shared_id : env.id;
    auto& memo = memo_[memo_id];
    if (auto it = memo.find(e); it != memo.end()) return it->second;
    NodeId result = lower(atom->definition, env);
    memo_[memo_id].emplace(e, result);
    return result;
  }
  auto& memo = memo_[env.id];
  if (auto it = memo.find(e); it != memo.end()) return it->second;
  NodeId result = lower_uncached(e, env);
  memo_[env.id].emplace(e, result);
  return result;
}

NodeId Lowerer::lower_uncached(const GiNaC::ex& e, const Environment& env) {
  if (GiNaC::is_a<GiNaC::add>(e)) return lower_add(e, env);
  if (GiNaC::is_a<GiNaC::mul>(e) || GiNaC::is_a<GiNaC::power>(e)) return lower_mul(e, env);
  if (GiNaC::is_a<GiNaC::function>(e)) return lower_function(e, env);
  throw std::invalid_argument("cannot lower expression of class " +
                              std::string(GiNaC::ex_to<GiNaC::basic>(e).class_name()));
}

NodeId Lowerer::lower_numeric(const GiNaC::ex& e) {
  GiNaC::ex value = GiNaC::evalf(e);
  if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
    throw std::invalid_argument("non-real constant in expression");
  return program_.constant(GiNaC::ex_to<GiNaC::numeric>(value).to_double());
}

NodeId Lowerer::lower_add(const GiNaC::ex& e, const Environment& env) {
  std::vector<NodeId> terms;
  terms.reserve(e.nops());
  for (size_t i = 0; i < e.nops(); ++i) terms.push_back(lower(e.op(i), env));
  return program_.sum(std::move(terms));
}

// A product c * prod b_i^(n_i): positive integer powers multiply, negative ones form one
// denominator, half-integer powers share 1/sqrt(b), anything else becomes pow().
NodeId Lowerer::lower_mul(const GiNaC::ex& e, const Environment& env) {
  GiNaC::exvector factors;
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    for (size_t i = 0; i < e.nops(); ++i) factors.push_back(e.op(i));
  } else {
    factors.push_back(e);
  }
  double coeff = 1;
  std::vector<NodeId> numerator, denominator;
  for (const auto& f : factors) {
    if (GiNaC::is_a<GiNaC::numeric>(f) || GiNaC::is_a<GiNaC::constant>(f)) {
      coeff *= program_.node(lower_numeric(f)).value;
      continue;
    }
    if (!GiNaC::is_a<GiNaC::power>(f)) {
      numerator.push_back(lower(f, env));
      continue;
    }
    const GiNaC::ex exponent = f.op(1);
    NodeId base = lower(f.op(0), env);
    if (is_integer(exponent)) {
      int n = GiNaC::ex_to<GiNaC::numeric>(exponent).to_int();
      if (n > 0) numerator.push_back(program_.integer_power(base, n));
      if (n < 0) denominator.push_back(program_.integer_power(base, -n));
    } else if (is_half_integer(exponent)) {
      numerator.push_back(half_power(base, GiNaC::ex_to<GiNaC::numeric>(exponent).numer().to_int()));
    } else {
      numerator.push_back(program_.pow(base, lower(exponent, env)));
    }
  }
  NodeId result = program_.product(std::move(numerator));
  if (!denominator.empty()) result = program_.div(result, program_.product(std::move(denominator)));
  return program_.mul(program_.constant(coeff), result);
}

NodeId Lowerer::half_power(NodeId base, int numerator) {
  NodeId root = program_.sqrt(base);
  if (numerator == 1) return root;
  if (numerator > 0) return program_.mul(program_.integer_power(base, (numerator - 1) / 2), root);
  NodeId reciprocal_root = program_.div(program_.constant(1), root);
  return program_.integer_power(reciprocal_root, -numerator);
}

NodeId Lowerer::lower_function(const GiNaC::ex& e, const Environment& env) {
  const auto& f = GiNaC::ex_to<GiNaC::function>(e);
  if (e.nops() != 1) throw std::invalid_argument("cannot lower function '" + f.get_name() + "' of several arguments");
  NodeId argument = lower(e.op(0), env);
  if (f.get_name() == "abs") return program_.abs(argument);
  return program_.call(function_of(f.get_name()), argument);
}

}  // namespace offsetgen
