// F and its first and second derivatives in cell units, as compiled straight-line programs: what the
// density stage integrates over the surface. Columns (one coordinate varying, the others fixed) are
// evaluated incrementally: the nodes that do not depend on the varying coordinate are computed once
// per column.
#pragma once

#include "density/column_evaluator.h"
#include "field/atom_table.h"
#include "field/field_atoms.h"
#include "lowering/program.h"
#include "surfaces/surface.h"

#include <array>
#include <memory>
#include <vector>

namespace offsetgen::density {

// The second-order jet of F at one point, cell units (x in [0, 1)^3, F_cell(x) = F(k x)).
struct FieldJet {
  double value = 0;
  std::array<double, 3> gradient{};
  std::array<std::array<double, 3>, 3> hessian{};
};

// The value and one partial derivative along a column.
struct ColumnValue {
  double value = 0;
  double slope = 0;
};

class FieldSampler {
 public:
  explicit FieldSampler(const Surface& surface);  // 3D surfaces only
  FieldSampler(const FieldSampler&) = delete;
  FieldSampler& operator=(const FieldSampler&) = delete;

  double value(const std::array<double, 3>& p);
  FieldJet jet(const std::array<double, 3>& p);
  // Upper bounds over the cell (cell units): |grad F| <= gradient_bound(), ||Hess F||_2 <= hessian_bound().
  double gradient_bound() const { return gradient_bound_; }
  double hessian_bound() const { return hessian_bound_; }

  // Fixes the two coordinates other than `axis` (p[axis] is ignored) for column().
  void start_column(int axis, const std::array<double, 3>& p);
  ColumnValue column(double t);   // F and dF/dx_axis at p with p[axis] = t
  FieldJet column_jet(double t);  // the jet there

 private:
  double scale_ = 1;
  AtomTable atoms_;
  FieldAtoms field_;
  Program value_program_, jet_program_;
  std::array<Program, 3> column_programs_;  // outputs F, dF/dX_axis
  std::unique_ptr<Evaluator> value_, jet_;
  double gradient_bound_ = 0, hessian_bound_ = 0;

  std::array<std::unique_ptr<ColumnEvaluator>, 3> columns_, column_jets_;
  int axis_ = 0;
  FieldJet to_jet(const std::vector<double>& outputs) const;
  std::vector<double> inputs_ = std::vector<double>(3);
};

}  // namespace offsetgen::density
