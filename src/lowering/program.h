// A straight-line program: a hash-consed DAG of scalar operations with named outputs.
// Hash-consing is the common-subexpression elimination: building the same operation on the same
// operands twice returns the same node, across every output of the program.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace offsetgen {

enum class Op : uint8_t {
  Input,
  Const,
  Add,
  Sub,
  Mul,
  Div,
  Neg,
  Sqrt,
  Abs,
  Call,
  Pow,
  LessEq,
  Greater,
  Select,  // comparisons yield booleans; Select(c, a, b) = c ? a : b
  // Last: an op's number enters the structural hash, which orders sums and products (and so the
  // emitted bytes), so new ops go at the end.
  Atan2,  // Atan2(a, b) = atan2(a, b): the angle of the point (b, a), in (-pi, pi]
};

// SinPi(a) = sin(pi a) and CosPi(a) = cos(pi a): the half-turn forms (see in_half_turns below).
enum class Fn : uint8_t { None, Sin, Cos, Tan, Exp, Log, Sinh, Cosh, Tanh, Atan, Asin, Acos, SinPi, CosPi };

const char* function_name(Fn fn);  // C/GLSL spelling of the double-precision name, e.g. "sin"
// fn(value) in double; SinPi and CosPi reduce their argument exactly.
double apply_function(Fn fn, double value);

struct Node {
  Op op = Op::Const;
  Fn fn = Fn::None;
  int a = -1, b = -1, c = -1;  // operands (node indices)
  double value = 0;            // Const
  int input = -1;              // Input: index into Program::inputs
  uint64_t shape = 0;          // structural hash: equal for equal subtrees, independent of build order
  bool boolean = false;
};

using NodeId = int;

class Program {
 public:
  Program() = default;
  explicit Program(std::vector<std::string> inputs);

  NodeId input(int index);
  NodeId constant(double value);
  NodeId add(NodeId a, NodeId b);
  NodeId sub(NodeId a, NodeId b);
  NodeId mul(NodeId a, NodeId b);
  NodeId div(NodeId a, NodeId b);
  NodeId neg(NodeId a);
  NodeId sqrt(NodeId a);
  NodeId abs(NodeId a);
  NodeId call(Fn fn, NodeId a);
  NodeId pow(NodeId a, NodeId b);
  NodeId atan2(NodeId y, NodeId x);
  NodeId less_eq(NodeId a, NodeId b);
  NodeId greater(NodeId a, NodeId b);
  NodeId select(NodeId condition, NodeId if_true, NodeId if_false);

  // Sums and products of many operands, folded in a canonical (shape) order so the result does
  // not depend on the order the operands arrive in.
  NodeId sum(std::vector<NodeId> terms);
  NodeId product(std::vector<NodeId> factors);
  // x^n for an integer n >= 1, by repeated squaring (shared with every other power of x).
  NodeId integer_power(NodeId base, int exponent);

  void add_output(const std::string& name, NodeId node);

  // A sin or cos node whose argument is pi * coefficient * input(input), with `coefficient` exact
  // (m k / pi for sin(m X) with X = k x and k a rational multiple of pi). Where a target has sinpi and
  // cospi, in_half_turns() evaluates it as sinpi(coefficient * x): no rounded 2 pi x ever exists, and
  // the argument reduction is exact (docs/neovius_o4_float.md).
  struct HalfTurns {
    double coefficient = 0;
    int input = -1;
  };
  void note_half_turns(NodeId call, HalfTurns form);
  const std::vector<std::pair<NodeId, HalfTurns>>& half_turns() const { return half_turns_; }

  const Node& node(NodeId id) const { return nodes_[static_cast<size_t>(id)]; }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<std::string>& inputs() const { return inputs_; }
  const std::vector<std::pair<std::string, NodeId>>& outputs() const { return outputs_; }

  bool is_const(NodeId id, double value) const;
  bool is_const(NodeId id) const { return node(id).op == Op::Const; }

 private:
  NodeId intern(Node node);
  NodeId comparison(Op op, NodeId a, NodeId b);

  std::vector<std::string> inputs_;
  std::vector<Node> nodes_;
  // Hash-consing index: open addressing on Node::shape, one NodeId per slot (-1 empty), at most
  // half full. A flat table, not a map of buckets: a generation interns tens of thousands of nodes,
  // and a heap block per node made their page faults a visible share of a CLI run.
  std::vector<NodeId> slots_;
  void grow_slots();
  std::vector<std::pair<std::string, NodeId>> outputs_;
  std::vector<std::pair<NodeId, HalfTurns>> half_turns_;  // in the order noted, one entry per node
};

// `program` with every noted sin/cos node (Program::note_half_turns) rebuilt as SinPi/CosPi of
// coefficient * input, for targets with sinpi and cospi (Backend::half_turn_trig). Same outputs.
Program in_half_turns(const Program& program);

// Nodes reachable from the outputs, in a deterministic evaluation order (operands first).
std::vector<NodeId> schedule(const Program& program);

// Evaluates the outputs in double precision (for bounds, tests and the check stage). The schedule is
// computed once, so repeated calls are cheap.
class Evaluator {
 public:
  explicit Evaluator(const Program& program);
  const std::vector<double>& operator()(const std::vector<double>& inputs);
  // Every node's value from the last call (indexed by NodeId), e.g. to find where a NaN arose.
  const std::vector<double>& node_values() const { return values_; }

 private:
  const Program& program_;
  std::vector<NodeId> order_;
  std::vector<double> values_;
  std::vector<double> outputs_;
};

std::vector<double> evaluate(const Program& program, const std::vector<double>& inputs);

// Operation count of the scheduled program, by the rules of count_ops (op_count.cpp).
int count_ops(const Program& program);

}  // namespace offsetgen
