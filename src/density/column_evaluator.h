// Evaluates a Program along a column: all inputs fixed but one. The nodes that do not depend on the
// varying input are computed once per column (fix()); each point of the column (at()) recomputes
// only the others. For a catalog field along z that skips the sin and cos of x and y.
#pragma once

#include "lowering/program.h"

#include <vector>

namespace offsetgen::density {

class ColumnEvaluator {
 public:
  ColumnEvaluator(const Program& program, int varying_input);
  ColumnEvaluator(const ColumnEvaluator&) = delete;
  ColumnEvaluator& operator=(const ColumnEvaluator&) = delete;

  // Every node at `inputs` (the varying one included); returns the outputs.
  const std::vector<double>& fix(const std::vector<double>& inputs);
  // The outputs with the varying input set to `value` and the others as last fixed.
  const std::vector<double>& at(double value);

 private:
  // One node as a compact instruction: operands and result are indices into values_.
  struct Instruction {
    Op op;
    Fn fn;
    int input;
    int a, b, c;
    int result;
    double value;
  };
  void run(const std::vector<Instruction>& code);
  const std::vector<double>& collect();

  const Program& program_;
  int varying_;
  std::vector<Instruction> all_, dependent_;  // every node, and those depending on the varying input
  std::vector<double> values_, inputs_, outputs_;
};

}  // namespace offsetgen::density
