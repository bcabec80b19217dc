#include "density/column_evaluator.h"

#include <cmath>
#include <stdexcept>

namespace offsetgen::density {

ColumnEvaluator::ColumnEvaluator(const Program& program, int varying_input)
    : program_(program), varying_(varying_input), values_(program.nodes().size(), 0.0) {
  std::vector<bool> depends(program.nodes().size(), false);
  for (NodeId id : schedule(program)) {
    const Node& n = program.node(id);
    bool d = n.op == Op::Input && n.input == varying_input;
    for (int operand : {n.a, n.b, n.c})
      if (operand >= 0) d = d || depends[static_cast<size_t>(operand)];
    depends[static_cast<size_t>(id)] = d;
    const Instruction instruction{n.op, n.fn, n.input, n.a, n.b, n.c, id, n.value};
    all_.push_back(instruction);
    if (d) dependent_.push_back(instruction);
  }
  outputs_.resize(program.outputs().size());
}

void ColumnEvaluator::run(const std::vector<Instruction>& code) {
  double* v = values_.data();
  const double* in = inputs_.data();
  for (const Instruction& n : code) {
    double r = 0;
    switch (n.op) {
      case Op::Input:
        r = in[n.input];
        break;
      case Op::Const:
        r = n.value;
        break;
      case Op::Add:
        r = v[n.a] + v[n.b];
        break;
      case Op::Sub:
        r = v[n.a] - v[n.b];
        break;
      case Op::Mul:
        r = v[n.a] * v[n.b];
        break;
      case Op::Div:
        r = v[n.a] / v[n.b];
        break;
      case Op::Neg:
        r = -v[n.a];
        break;
      case Op::Sqrt:
        r = std::sqrt(v[n.a]);
        break;
      case Op::Abs:
        r = std::fabs(v[n.a]);
        break;
      case Op::Call:
        r = apply_function(n.fn, v[n.a]);
        break;
      case Op::Pow:
        r = std::pow(v[n.a], v[n.b]);
        break;
      case Op::Atan2:
        r = std::atan2(v[n.a], v[n.b]);
        break;
      case Op::LessEq:
        r = v[n.a] <= v[n.b] ? 1.0 : 0.0;
        break;
      case Op::Greater:
        r = v[n.a] > v[n.b] ? 1.0 : 0.0;
        break;
      case Op::Select:
        r = v[n.a] != 0 ? v[n.b] : v[n.c];
        break;
    }
    v[n.result] = r;
  }
}

const std::vector<double>& ColumnEvaluator::collect() {
  const auto& outs = program_.outputs();
  for (size_t i = 0; i < outs.size(); ++i) outputs_[i] = values_[static_cast<size_t>(outs[i].second)];
  return outputs_;
}

const std::vector<double>& ColumnEvaluator::fix(const std::vector<double>& inputs) {
  inputs_ = inputs;
  run(all_);
  return collect();
}

const std::vector<double>& ColumnEvaluator::at(double value) {
  inputs_[static_cast<size_t>(varying_)] = value;
  run(dependent_);
  return collect();
}

}  // namespace offsetgen::density
