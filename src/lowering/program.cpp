#include "lowering/program.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

namespace offsetgen {
namespace {

uint64_t mix(uint64_t h, uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 33);
}

uint64_t double_bits(double v) {
  uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

bool commutative(Op op) { return op == Op::Add || op == Op::Mul; }

bool same_node(const Node& x, const Node& y) {
  return x.op == y.op && x.fn == y.fn && x.a == y.a && x.b == y.b && x.c == y.c && x.input == y.input &&
         double_bits(x.value) == double_bits(y.value);
}

// sin(pi (a + n/2)) for the quadrant n = rint(2a): a - n/2 is exact (Sterbenz), |pi r| <= pi/4.
double sin_half_turns(double a, int shift) {
  const double n = std::nearbyint(2 * a);
  const double t = 3.14159265358979323846 * (a - n / 2);
  switch ((static_cast<long long>(std::fmod(n, 4.0)) + shift + 8) % 4) {
    case 0:
      return std::sin(t);
    case 1:
      return std::cos(t);
    case 2:
      return -std::sin(t);
    default:
      return -std::cos(t);
  }
}

}  // namespace

double apply_function(Fn fn, double v) {
  switch (fn) {
    case Fn::Sin:
      return std::sin(v);
    case Fn::Cos:
      return std::cos(v);
    case Fn::Tan:
      return std::tan(v);
    case Fn::Exp:
      return std::exp(v);
    case Fn::Log:
      return std::log(v);
    case Fn::Sinh:
      return std::sinh(v);
    case Fn::Cosh:
      return std::cosh(v);
    case Fn::Tanh:
      return std::tanh(v);
    case Fn::Atan:
      return std::atan(v);
    case Fn::Asin:
      return std::asin(v);
    case Fn::Acos:
      return std::acos(v);
    case Fn::SinPi:
      return sin_half_turns(v, 0);
    case Fn::CosPi:
      return sin_half_turns(v, 1);  // cos(pi a) = sin(pi a + pi/2)
    case Fn::None:
      break;
  }
  throw std::logic_error("apply: no function");
}

const char* function_name(Fn fn) {
  switch (fn) {
    case Fn::Sin:
      return "sin";
    case Fn::Cos:
      return "cos";
    case Fn::Tan:
      return "tan";
    case Fn::Exp:
      return "exp";
    case Fn::Log:
      return "log";
    case Fn::Sinh:
      return "sinh";
    case Fn::Cosh:
      return "cosh";
    case Fn::Tanh:
      return "tanh";
    case Fn::Atan:
      return "atan";
    case Fn::Asin:
      return "asin";
    case Fn::Acos:
      return "acos";
    case Fn::SinPi:
      return "sinpi";
    case Fn::CosPi:
      return "cospi";
    case Fn::None:
      break;
  }
  return "?";
}

Program::Program(std::vector<std::string> inputs) : inputs_(std::move(inputs)) {}

NodeId Program::intern(Node n) {
  if (commutative(n.op) && node(n.a).shape > node(n.b).shape) std::swap(n.a, n.b);
  uint64_t h = mix(static_cast<uint64_t>(n.op) + 1, static_cast<uint64_t>(n.fn));
  for (int operand : {n.a, n.b, n.c}) h = mix(h, operand < 0 ? 7 : node(operand).shape);
  h = mix(h, static_cast<uint64_t>(n.input + 2));
  h = mix(h, double_bits(n.value));
  n.shape = h;
  if (2 * (nodes_.size() + 1) > slots_.size()) grow_slots();
  const size_t mask = slots_.size() - 1;
  size_t slot = static_cast<size_t>(h) & mask;
  for (; slots_[slot] >= 0; slot = (slot + 1) & mask) {
    const Node& existing = nodes_[static_cast<size_t>(slots_[slot])];
    if (existing.shape == h && same_node(existing, n)) return slots_[slot];
  }
  nodes_.push_back(n);
  const auto id = static_cast<NodeId>(nodes_.size() - 1);
  slots_[slot] = id;
  return id;
}

void Program::grow_slots() {
  const size_t size = std::max<size_t>(64, 2 * slots_.size());
  slots_.assign(size, -1);
  const size_t mask = size - 1;
  for (size_t id = 0; id < nodes_.size(); ++id) {
    size_t slot = static_cast<size_t>(nodes_[id].shape) & mask;
    while (slots_[slot] >= 0) slot = (slot + 1) & mask;
    slots_[slot] = static_cast<NodeId>(id);
  }
}

bool Program::is_const(NodeId id, double value) const {
  const Node& n = node(id);
  return n.op == Op::Const && n.value == value;
}

NodeId Program::input(int index) {
  Node n;
  n.op = Op::Input;
  n.input = index;
  return intern(n);
}

NodeId Program::constant(double value) {
  Node n;
  n.op = Op::Const;
  n.value = value == 0 ? 0.0 : value;  // one zero, not two
  return intern(n);
}

NodeId Program::neg(NodeId a) {
  const Node& x = node(a);
  if (x.op == Op::Const) return constant(-x.value);
  if (x.op == Op::Neg) return x.a;
  // No -(a - b) -> b - a: it would change which node stands for a sum's magnitude (see sum()).
  Node n;
  n.op = Op::Neg;
  n.a = a;
  return intern(n);
}

NodeId Program::add(NodeId a, NodeId b) {
  if (is_const(a) && is_const(b)) return constant(node(a).value + node(b).value);
  if (is_const(a, 0)) return b;
  if (is_const(b, 0)) return a;
  if (node(b).op == Op::Neg) return sub(a, node(b).a);
  if (node(a).op == Op::Neg) return sub(b, node(a).a);
  if (node(b).op == Op::Const && node(b).value < 0) return sub(a, constant(-node(b).value));
  if (node(a).op == Op::Const && node(a).value < 0) return sub(b, constant(-node(a).value));
  Node n;
  n.op = Op::Add;
  n.a = a;
  n.b = b;
  return intern(n);
}

NodeId Program::sub(NodeId a, NodeId b) {
  if (is_const(a) && is_const(b)) return constant(node(a).value - node(b).value);
  if (a == b) return constant(0);
  if (is_const(b, 0)) return a;
  if (is_const(a, 0)) return neg(b);
  if (node(b).op == Op::Neg) return add(a, node(b).a);
  if (node(a).op == Op::Neg) return neg(add(node(a).a, b));
  Node n;
  n.op = Op::Sub;
  n.a = a;
  n.b = b;
  return intern(n);
}

NodeId Program::mul(NodeId a, NodeId b) {
  if (is_const(a) && is_const(b)) return constant(node(a).value * node(b).value);
  if (is_const(a, 0) || is_const(b, 0)) return constant(0);
  if (is_const(a, 1)) return b;
  if (is_const(b, 1)) return a;
  if (is_const(a, -1)) return neg(b);
  if (is_const(b, -1)) return neg(a);
  // Signs move outwards, so -a*b and a*-b are one node.
  if (node(a).op == Op::Neg) return neg(mul(node(a).a, b));
  if (node(b).op == Op::Neg) return neg(mul(a, node(b).a));
  if (node(a).op == Op::Const && node(a).value < 0) return neg(mul(constant(-node(a).value), b));
  if (node(b).op == Op::Const && node(b).value < 0) return neg(mul(a, constant(-node(b).value)));
  Node n;
  n.op = Op::Mul;
  n.a = a;
  n.b = b;
  return intern(n);
}

NodeId Program::div(NodeId a, NodeId b) {
  if (is_const(a) && is_const(b)) return constant(node(a).value / node(b).value);
  if (is_const(b, 1)) return a;
  if (is_const(a, 0)) return constant(0);
  if (node(a).op == Op::Neg) return neg(div(node(a).a, b));
  if (node(b).op == Op::Neg) return neg(div(a, node(b).a));
  // A multiply is cheaper than a divide; it costs at most one extra rounding.
  if (is_const(b)) return mul(a, constant(1.0 / node(b).value));
  Node n;
  n.op = Op::Div;
  n.a = a;
  n.b = b;
  return intern(n);
}

NodeId Program::sqrt(NodeId a) {
  if (is_const(a)) return constant(std::sqrt(node(a).value));
  Node n;
  n.op = Op::Sqrt;
  n.a = a;
  return intern(n);
}

NodeId Program::abs(NodeId a) {
  if (is_const(a)) return constant(std::fabs(node(a).value));
  Node n;
  n.op = Op::Abs;
  n.a = node(a).op == Op::Neg ? node(a).a : a;
  return intern(n);
}

NodeId Program::call(Fn fn, NodeId a) {
  if (is_const(a)) return constant(apply_function(fn, node(a).value));
  if (node(a).op == Op::Neg) {  // odd and even symmetry keeps one argument per sin/cos pair
    if (fn == Fn::Cos || fn == Fn::Cosh || fn == Fn::CosPi) return call(fn, node(a).a);
    if (fn == Fn::Sin || fn == Fn::SinPi || fn == Fn::Tan || fn == Fn::Sinh || fn == Fn::Tanh || fn == Fn::Atan ||
        fn == Fn::Asin)
      return neg(call(fn, node(a).a));
  }
  Node n;
  n.op = Op::Call;
  n.fn = fn;
  n.a = a;
  return intern(n);
}

NodeId Program::atan2(NodeId y, NodeId x) {
  if (is_const(y) && is_const(x)) return constant(std::atan2(node(y).value, node(x).value));
  if (node(y).op == Op::Neg) return neg(atan2(node(y).a, x));  // odd in y (away from the cut)
  Node n;
  n.op = Op::Atan2;
  n.a = y;
  n.b = x;
  return intern(n);
}

NodeId Program::pow(NodeId a, NodeId b) {
  if (is_const(a) && is_const(b)) return constant(std::pow(node(a).value, node(b).value));
  Node n;
  n.op = Op::Pow;
  n.a = a;
  n.b = b;
  return intern(n);
}

NodeId Program::comparison(Op op, NodeId a, NodeId b) {
  // Constant operands fold to 1 or 0 (IEEE: a NaN compares false), so 3.0 > 0.0 is never printed.
  if (is_const(a) && is_const(b)) {
    const double x = node(a).value, y = node(b).value;
    return constant((op == Op::LessEq ? x <= y : x > y) ? 1.0 : 0.0);
  }
  Node n;
  n.op = op;
  n.a = a;
  n.b = b;
  n.boolean = true;
  return intern(n);
}

NodeId Program::less_eq(NodeId a, NodeId b) { return comparison(Op::LessEq, a, b); }
NodeId Program::greater(NodeId a, NodeId b) { return comparison(Op::Greater, a, b); }

NodeId Program::select(NodeId condition, NodeId if_true, NodeId if_false) {
  if (if_true == if_false) return if_true;
  if (is_const(condition)) return node(condition).value != 0.0 ? if_true : if_false;
  Node n;
  n.op = Op::Select;
  n.a = condition;
  n.b = if_true;
  n.c = if_false;
  return intern(n);
}

NodeId Program::sum(std::vector<NodeId> terms) {
  if (terms.empty()) return constant(0);
  // GiNaC may hand us a sum or its negation (it normalises signs by hash order, which varies
  // between runs). Orient every sum canonically, so a - b and -(b - a) lower to one node and the
  // output does not depend on that choice: the term with the smallest shape is made positive.
  struct Term {
    NodeId magnitude;
    bool negative;
  };
  std::vector<Term> split;
  for (NodeId t : terms) {
    const Node& n = node(t);
    if (n.op == Op::Neg) {
      split.push_back({n.a, true});
    } else if (n.op == Op::Const && n.value < 0) {
      split.push_back({constant(-n.value), true});
    } else {
      split.push_back({t, false});
    }
  }
  std::stable_sort(split.begin(), split.end(),
                   [this](const Term& x, const Term& y) { return node(x.magnitude).shape < node(y.magnitude).shape; });
  const bool flip = split.front().negative;
  // Positive terms first, so a chain starts with an addition rather than a negation.
  std::stable_partition(split.begin(), split.end(), [flip](const Term& t) { return t.negative == flip; });
  NodeId acc = -1;
  for (const Term& t : split) {
    bool negative = t.negative != flip;
    if (acc < 0) {
      acc = negative ? neg(t.magnitude) : t.magnitude;
    } else {
      acc = negative ? sub(acc, t.magnitude) : add(acc, t.magnitude);
    }
  }
  return flip ? neg(acc) : acc;
}

NodeId Program::product(std::vector<NodeId> factors) {
  if (factors.empty()) return constant(1);
  // Signs are pulled out before sorting, so the grouping does not depend on which factors arrive
  // negated (see sum()).
  bool negative = false;
  for (NodeId& f : factors) {
    const Node& n = node(f);
    if (n.op == Op::Neg) {
      negative = !negative;
      f = n.a;
    } else if (n.op == Op::Const && n.value < 0) {
      negative = !negative;
      f = constant(-n.value);
    }
  }
  std::stable_sort(factors.begin(), factors.end(),
                   [this](NodeId x, NodeId y) { return node(x).shape < node(y).shape; });
  NodeId acc = factors.front();
  for (size_t i = 1; i < factors.size(); ++i) acc = mul(acc, factors[i]);
  return negative ? neg(acc) : acc;
}

NodeId Program::integer_power(NodeId base, int exponent) {
  if (exponent < 1) throw std::invalid_argument("integer_power needs exponent >= 1");
  if (exponent == 1) return base;
  NodeId half = integer_power(base, exponent / 2);
  NodeId square = mul(half, half);
  return exponent % 2 ? mul(square, base) : square;
}

void Program::add_output(const std::string& name, NodeId node) { outputs_.emplace_back(name, node); }

void Program::note_half_turns(NodeId call, HalfTurns form) {
  const Node& n = node(call);
  if (n.op != Op::Call || (n.fn != Fn::Sin && n.fn != Fn::Cos))
    throw std::logic_error("note_half_turns: not a sin or cos node");
  for (const auto& [id, noted] : half_turns_)
    if (id == call) return;  // the same node reached again (hash-consing): the same value
  half_turns_.emplace_back(call, form);
}

Program in_half_turns(const Program& program) {
  Program out(program.inputs());
  std::vector<NodeId> map(program.nodes().size(), -1);
  std::unordered_map<NodeId, Program::HalfTurns> forms(program.half_turns().begin(), program.half_turns().end());
  auto at = [&map](int operand) { return map[static_cast<size_t>(operand)]; };
  // Nodes are interned operands first, so index order is an evaluation order.
  for (size_t id = 0; id < program.nodes().size(); ++id) {
    const Node& n = program.node(static_cast<NodeId>(id));
    NodeId r = -1;
    switch (n.op) {
      case Op::Input:
        r = out.input(n.input);
        break;
      case Op::Const:
        r = out.constant(n.value);
        break;
      case Op::Add:
        r = out.add(at(n.a), at(n.b));
        break;
      case Op::Sub:
        r = out.sub(at(n.a), at(n.b));
        break;
      case Op::Mul:
        r = out.mul(at(n.a), at(n.b));
        break;
      case Op::Div:
        r = out.div(at(n.a), at(n.b));
        break;
      case Op::Neg:
        r = out.neg(at(n.a));
        break;
      case Op::Sqrt:
        r = out.sqrt(at(n.a));
        break;
      case Op::Abs:
        r = out.abs(at(n.a));
        break;
      case Op::Call: {
        auto form = forms.find(static_cast<NodeId>(id));
        if (form == forms.end()) {
          r = out.call(n.fn, at(n.a));
        } else {
          const NodeId turns = out.mul(out.constant(form->second.coefficient), out.input(form->second.input));
          r = out.call(n.fn == Fn::Sin ? Fn::SinPi : Fn::CosPi, turns);
        }
        break;
      }
      case Op::Pow:
        r = out.pow(at(n.a), at(n.b));
        break;
      case Op::Atan2:
        r = out.atan2(at(n.a), at(n.b));
        break;
      case Op::LessEq:
        r = out.less_eq(at(n.a), at(n.b));
        break;
      case Op::Greater:
        r = out.greater(at(n.a), at(n.b));
        break;
      case Op::Select:
        r = out.select(at(n.a), at(n.b), at(n.c));
        break;
    }
    map[id] = r;
  }
  for (const auto& [name, node] : program.outputs()) out.add_output(name, at(node));
  return out;
}

std::vector<NodeId> schedule(const Program& program) {
  std::vector<NodeId> order;
  std::vector<char> state(program.nodes().size(), 0);  // 0 new, 1 visiting, 2 done
  std::vector<std::pair<NodeId, int>> stack;
  for (const auto& output : program.outputs()) {
    stack.push_back({output.second, 0});
    while (!stack.empty()) {
      auto& [id, step] = stack.back();
      const Node& n = program.node(id);
      if (state[static_cast<size_t>(id)] == 2) {
        stack.pop_back();
        continue;
      }
      state[static_cast<size_t>(id)] = 1;
      int operands[3] = {n.a, n.b, n.c};
      if (step < 3) {
        int next = operands[step++];
        if (next >= 0 && state[static_cast<size_t>(next)] == 0) stack.push_back({next, 0});
        continue;
      }
      state[static_cast<size_t>(id)] = 2;
      order.push_back(id);
      stack.pop_back();
    }
  }
  return order;
}

Evaluator::Evaluator(const Program& program)
    : program_(program), order_(schedule(program)), values_(program.nodes().size(), 0.0) {}

const std::vector<double>& Evaluator::operator()(const std::vector<double>& inputs) {
  auto& v = values_;
  for (NodeId id : order_) {
    const Node& n = program_.node(id);
    auto A = [&] { return v[static_cast<size_t>(n.a)]; };
    auto B = [&] { return v[static_cast<size_t>(n.b)]; };
    double r = 0;
    switch (n.op) {
      case Op::Input:
        r = inputs.at(static_cast<size_t>(n.input));
        break;
      case Op::Const:
        r = n.value;
        break;
      case Op::Add:
        r = A() + B();
        break;
      case Op::Sub:
        r = A() - B();
        break;
      case Op::Mul:
        r = A() * B();
        break;
      case Op::Div:
        r = A() / B();
        break;
      case Op::Neg:
        r = -A();
        break;
      case Op::Sqrt:
        r = std::sqrt(A());
        break;
      case Op::Abs:
        r = std::fabs(A());
        break;
      case Op::Call:
        r = apply_function(n.fn, A());
        break;
      case Op::Pow:
        r = std::pow(A(), B());
        break;
      case Op::Atan2:
        r = std::atan2(A(), B());
        break;
      case Op::LessEq:
        r = A() <= B() ? 1.0 : 0.0;
        break;
      case Op::Greater:
        r = A() > B() ? 1.0 : 0.0;
        break;
      case Op::Select:
        r = A() != 0.0 ? B() : v[static_cast<size_t>(n.c)];
        break;
    }
    v[static_cast<size_t>(id)] = r;
  }
  outputs_.clear();
  for (const auto& output : program_.outputs()) outputs_.push_back(v[static_cast<size_t>(output.second)]);
  return outputs_;
}

std::vector<double> evaluate(const Program& program, const std::vector<double>& inputs) {
  Evaluator evaluator(program);
  return evaluator(inputs);
}

// Counting rules (pinned by tests/test_op_count.cpp): every arithmetic operation (+, -, *, /, unary -),
// every function call (sin, cos, sqrt, fabs, pow, ...), every comparison and every select counts 1.
// Inputs and constants count 0. Each node counts once, however often it is used.
int count_ops(const Program& program) {
  int ops = 0;
  for (NodeId id : schedule(program)) {
    Op op = program.node(id).op;
    if (op != Op::Input && op != Op::Const) ++ops;
  }
  return ops;
}

}  // namespace offsetgen
