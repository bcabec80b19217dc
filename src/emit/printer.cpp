#include "emit/printer.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace offsetgen {
namespace {

constexpr int kMaxInlineDepth = 64;

// Binding strength, for parentheses: select < comparison < sum < product < unary < atom.
enum Precedence { kSelect = 0, kCompare = 1, kSum = 2, kProduct = 3, kUnary = 4, kAtom = 5 };

Precedence precedence_of(Op op) {
  switch (op) {
    case Op::Select:
      return kSelect;
    case Op::LessEq:
    case Op::Greater:
      return kCompare;
    case Op::Add:
    case Op::Sub:
      return kSum;
    case Op::Mul:
    case Op::Div:
      return kProduct;
    case Op::Neg:
      return kUnary;
    default:
      return kAtom;
  }
}

class BodyPrinter {
 public:
  BodyPrinter(const Program& program, const Dialect& dialect, const std::vector<std::string>& input_names)
      : program_(program), dialect_(dialect), input_names_(input_names), names_(program.nodes().size()) {}

  PrintedBody print() {
    auto order = schedule(program_);
    std::vector<int> uses(program_.nodes().size(), 0);
    for (NodeId id : order) {
      const Node& n = program_.node(id);
      for (int operand : {n.a, n.b, n.c})
        if (operand >= 0) ++uses[static_cast<size_t>(operand)];
    }
    for (const auto& output : program_.outputs()) ++uses[static_cast<size_t>(output.second)];

    PrintedBody body;
    int counter = 0;
    // How deep each node's inlined expression nests. Long chains of single-use nodes (a sum of
    // thousands of terms) get a temporary every kMaxInlineDepth levels, so printing never recurses
    // deeper than that and no compiler meets more than that many nested parentheses.
    std::vector<int> depth(program_.nodes().size(), 0);
    for (NodeId id : order) {
      const Node& n = program_.node(id);
      if (n.op == Op::Input || n.op == Op::Const) continue;
      int d = 0;
      for (int operand : {n.a, n.b, n.c})
        if (operand >= 0 && names_[static_cast<size_t>(operand)].empty())
          d = std::max(d, depth[static_cast<size_t>(operand)]);
      depth[static_cast<size_t>(id)] = d + 1;
      if (uses[static_cast<size_t>(id)] < 2 && depth[static_cast<size_t>(id)] < kMaxInlineDepth) continue;
      std::string expression = expression_of(id, kSelect);
      names_[static_cast<size_t>(id)] = fmt::format("_t{}", counter++);
      const std::string decl = n.boolean ? dialect_.bool_decl() : dialect_.local_decl();  // "" in Python
      body.temporaries.push_back(
          fmt::format("{}{} = {};", decl.empty() ? "" : decl + " ", names_[static_cast<size_t>(id)], expression));
    }
    for (const auto& output : program_.outputs()) body.outputs.push_back(text(output.second, kSelect));
    return body;
  }

 private:
  // The node as an operand: its temporary's name, or its expression, parenthesised if it binds
  // less tightly than `context` requires.
  std::string text(NodeId id, Precedence context) {
    const std::string& name = names_[static_cast<size_t>(id)];
    if (!name.empty()) return name;
    const Node& n = program_.node(id);
    std::string e = expression_of(id, context);
    return precedence_of(n.op) < context ? "(" + e + ")" : e;
  }

  std::string expression_of(NodeId id, Precedence /*context*/) {
    const Node& n = program_.node(id);
    switch (n.op) {
      case Op::Input:
        return input_names_.at(static_cast<size_t>(n.input));
      case Op::Const:
        return dialect_.literal(n.value);
      case Op::Add:
        return text(n.a, kSum) + " + " + text(n.b, kProduct);  // left-associative
      case Op::Sub:
        return text(n.a, kSum) + " - " + text(n.b, kProduct);
      case Op::Mul:
        return text(n.a, kProduct) + " * " + text(n.b, kUnary);
      case Op::Div:
        return text(n.a, kProduct) + " / " + text(n.b, kUnary);
      case Op::Neg:
        return "-" + text(n.a, kAtom);
      case Op::Sqrt:
        return dialect_.sqrt_name() + "(" + text(n.a, kSelect) + ")";
      case Op::Abs:
        return dialect_.abs_name() + "(" + text(n.a, kSelect) + ")";
      case Op::Call:
        return dialect_.function(n.fn) + "(" + text(n.a, kSelect) + ")";
      case Op::Pow:
        return dialect_.pow_name() + "(" + text(n.a, kSelect) + ", " + text(n.b, kSelect) + ")";
      case Op::Atan2:
        return dialect_.atan2_name() + "(" + text(n.a, kSelect) + ", " + text(n.b, kSelect) + ")";
      case Op::LessEq:
        return text(n.a, kSum) + " <= " + text(n.b, kSum);
      case Op::Greater:
        return text(n.a, kSum) + " > " + text(n.b, kSum);
      case Op::Select:
        return dialect_.backend->select(text(n.a, kCompare), text(n.b, kCompare), text(n.c, kCompare));
    }
    throw std::logic_error("print: unknown op");
  }

  const Program& program_;
  const Dialect& dialect_;
  const std::vector<std::string>& input_names_;
  std::vector<std::string> names_;
};

}  // namespace

PrintedBody print_program(const Program& program, const Dialect& dialect, const std::vector<std::string>& input_names) {
  return BodyPrinter(program, dialect, input_names).print();
}

}  // namespace offsetgen
