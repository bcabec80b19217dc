#include "lowering/lower.h"

#include "surfaces/surface.h"

#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

namespace offsetgen {
namespace {

Fn function_of(const std::string& name) {
  static const std::map<std::string, Fn> table = {{"sin", Fn::Sin},   {"cos", Fn::Cos},   {"tan", Fn::Tan},
                                                  {"exp", Fn::Exp},   {"log", Fn::Log},   {"sinh", Fn::Sinh},
                                                  {"cosh", Fn::Cosh}, {"tanh", Fn::Tanh}, {"atan", Fn::Atan},
                                                  {"asin", Fn::Asin}, {"acos", Fn::Acos}};
  auto it = table.find(name);
  if (it == table.end()) throw std::invalid_argument("cannot lower function '" + name + "'");
  return it->second;
}

bool is_integer(const GiNaC::ex& e) {
  return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_integer();
}

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
  if (f.get_name() == "atan2" && e.nops() == 2) return program_.atan2(lower(e.op(0), env), lower(e.op(1), env));
  if (e.nops() != 1) throw std::invalid_argument("cannot lower function '" + f.get_name() + "' of several arguments");
  if (env.displaced_from && (f.get_name() == "sin" || f.get_name() == "cos")) {
    if (auto sc = displaced_sincos(e.op(0), env)) return f.get_name() == "sin" ? sc->first : sc->second;
  }
  NodeId argument = lower(e.op(0), env);
  if (f.get_name() == "abs") return program_.abs(argument);
  const NodeId result = program_.call(function_of(f.get_name()), argument);
  if (!env.half_turns.empty() && (f.get_name() == "sin" || f.get_name() == "cos"))
    note_half_turns(result, e.op(0), argument, env);
  return result;
}

namespace {

// Whether `e` is a number: no symbols, only numerics and constants such as Pi.
bool is_constant_expression(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return true;
  if (!GiNaC::is_a<GiNaC::add>(e) && !GiNaC::is_a<GiNaC::mul>(e) && !GiNaC::is_a<GiNaC::power>(e)) return false;
  for (size_t i = 0; i < e.nops(); ++i)
    if (!is_constant_expression(e.op(i))) return false;
  return true;
}

}  // namespace

void Lowerer::note_half_turns(NodeId result, const GiNaC::ex& argument, NodeId argument_node, const Environment& env) {
  for (const auto& coordinate : env.half_turns) {
    if (!argument.has(coordinate.coordinate)) continue;
    // argument = c * coordinate with c constant: in half-turns of the input, c * per_half_turn.
    const GiNaC::ex c = (argument / coordinate.coordinate).normal();
    if (!is_constant_expression(c)) return;
    const GiNaC::ex turns = c * coordinate.per_half_turn;
    if (!GiNaC::is_a<GiNaC::numeric>(turns) || !GiNaC::ex_to<GiNaC::numeric>(turns).is_rational()) return;
    double coefficient = GiNaC::ex_to<GiNaC::numeric>(turns).to_double();
    // Program::call takes a negated argument's sign out (sin(-a) = -sin(a), cos(-a) = cos(a)): the
    // call node then has the negation's operand, -c * coordinate.
    NodeId operand = argument_node;
    if (program_.node(operand).op == Op::Neg) {
      operand = program_.node(operand).a;
      coefficient = -coefficient;
    }
    const NodeId call = program_.node(result).op == Op::Neg ? program_.node(result).a : result;
    if (program_.node(call).op == Op::Call && program_.node(call).a == operand)
      program_.note_half_turns(call, {coefficient, coordinate.input});
    return;
  }
}

namespace {

constexpr long kMaxAngleMultiple = 8;  // sin(a X) at a displaced point: a - 1 angle additions

bool is_natural_coordinate(const GiNaC::ex& e) {
  const Symbols& sym = Symbols::get();
  return e.is_equal(sym.X) || e.is_equal(sym.Y) || e.is_equal(sym.Z);
}

bool is_coordinate_multiple(const GiNaC::ex& e) {
  if (is_natural_coordinate(e)) return true;
  if (!GiNaC::is_a<GiNaC::mul>(e) || e.nops() != 2) return false;
  for (size_t i = 0; i < 2; ++i) {
    if (is_integer(e.op(i)) && is_natural_coordinate(e.op(1 - i)))
      return std::labs(GiNaC::ex_to<GiNaC::numeric>(e.op(i)).to_long()) <= kMaxAngleMultiple;
  }
  return false;
}

}  // namespace

bool is_trigonometric_polynomial(const GiNaC::ex& e) {
  if (is_natural_coordinate(e)) return false;
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if ((name == "sin" || name == "cos") && is_coordinate_multiple(e.op(0))) return true;
  }
  for (size_t i = 0; i < e.nops(); ++i)
    if (!is_trigonometric_polynomial(e.op(i))) return false;
  return true;
}

// sin(d) = d S(d^2) and cos(d) = C(d^2) for |d| <= kSmallAngleMax = 1: near-minimax polynomials
// of degree 7 in z = d^2 (tools/small_angle_fit.py; max error 9e-18 and 1.1e-17), evaluated by
// Estrin's scheme for short dependency chains (the projection's steps are serial).
std::pair<NodeId, NodeId> Lowerer::small_angle_sincos(NodeId d, NodeId d_squared) {
  static const std::vector<double> kSin = {1.0,
                                           -0.16666666666666666,
                                           0.0083333333333333,
                                           -0.00019841269841216566,
                                           2.755731919201122e-06,
                                           -2.5052099244914114e-08,
                                           1.6057701922579786e-10,
                                           -7.549371704181243e-13};
  static const std::vector<double> kCos = {1.0,
                                           -0.5,
                                           0.0416666666666661,
                                           -0.0013888888888798428,
                                           2.4801587247292686e-05,
                                           -2.755730370192223e-07,
                                           2.0874477943664777e-09,
                                           -1.1304620460700782e-11};
  Program& p = program_;
  const NodeId z = d_squared;
  auto estrin = [&](const std::vector<double>& c) {
    // Pairs c0 + c1 z, then (.) + (.) z^2, (.) + (.) z^4, ...
    std::vector<NodeId> level;
    for (size_t i = 0; i < c.size(); i += 2) {
      NodeId term = p.constant(c[i]);
      if (i + 1 < c.size()) term = p.add(term, p.mul(p.constant(c[i + 1]), z));
      level.push_back(term);
    }
    NodeId power = z;
    while (level.size() > 1) {
      power = p.mul(power, power);
      std::vector<NodeId> next;
      for (size_t i = 0; i < level.size(); i += 2)
        next.push_back(i + 1 < level.size() ? p.add(level[i], p.mul(level[i + 1], power)) : level[i]);
      level = std::move(next);
    }
    return level.front();
  };
  return {p.mul(d, estrin(kSin)), estrin(kCos)};
}

std::optional<std::pair<NodeId, NodeId>> Lowerer::displaced_sincos(const GiNaC::ex& argument, const Environment& env) {
  // argument = a * X with a a nonzero integer and X a displaced coordinate
  GiNaC::ex symbol = argument;
  long multiple = 1;
  if (GiNaC::is_a<GiNaC::mul>(argument) && argument.nops() == 2) {
    for (size_t i = 0; i < 2; ++i) {
      if (is_integer(argument.op(i)) && GiNaC::is_a<GiNaC::symbol>(argument.op(1 - i))) {
        multiple = GiNaC::ex_to<GiNaC::numeric>(argument.op(i)).to_long();
        symbol = argument.op(1 - i);
      }
    }
  }
  if (!GiNaC::is_a<GiNaC::symbol>(symbol) || multiple == 0 || std::labs(multiple) > kMaxAngleMultiple)
    return std::nullopt;
  const Environment::Displacement* d = nullptr;
  for (const auto& entry : env.displacement)
    if (entry.coordinate.is_equal(symbol)) d = &entry;
  if (!d) return std::nullopt;

  // sin(X - d) = sin X cos d - cos X sin d, cos(X - d) = cos X cos d + sin X sin d, from p.
  const Environment& base = *env.displaced_from;
  NodeId sin_p = lower(GiNaC::sin(symbol), base), cos_p = lower(GiNaC::cos(symbol), base);
  auto [sin_d, cos_d] = small_angle_sincos(d->d, d->d_squared);
  Program& p = program_;
  NodeId s1 = p.sub(p.mul(sin_p, cos_d), p.mul(cos_p, sin_d));
  NodeId c1 = p.add(p.mul(cos_p, cos_d), p.mul(sin_p, sin_d));
  // Multiples by repeated angle addition; a double angle as 2 s c and c^2 - s^2.
  NodeId s = s1, c = c1;
  for (long k = 1; k < std::labs(multiple); ++k) {
    if (k == 1) {
      s = p.mul(p.constant(2), p.mul(s1, c1));
      c = p.sub(p.mul(c1, c1), p.mul(s1, s1));
    } else {
      NodeId next_s = p.add(p.mul(s, c1), p.mul(c, s1));
      c = p.sub(p.mul(c, c1), p.mul(s, s1));
      s = next_s;
    }
  }
  if (multiple < 0) s = p.neg(s);
  return std::make_pair(s, c);
}

}  // namespace offsetgen
