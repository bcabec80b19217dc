#include "density/field_sampler.h"

#include "lowering/cell_bounds.h"
#include "lowering/lower.h"

#include <stdexcept>

namespace offsetgen::density {
namespace {

double numeric_value(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

// Expressions of the natural coordinates X, Y, Z as one program over them, one output each.
Program natural_program(const AtomTable& atoms, const std::vector<GiNaC::ex>& outputs) {
  Program program({"X", "Y", "Z"});
  Lowerer lowerer(program, atoms);
  Environment env;
  const Symbols& sym = Symbols::get();
  for (int i = 0; i < 3; ++i) env.bindings.emplace_back(sym.natural(i), program.input(i));
  for (size_t k = 0; k < outputs.size(); ++k)
    program.add_output("o" + std::to_string(k), lowerer.lower(outputs[k], env));
  return program;
}

}  // namespace

FieldSampler::FieldSampler(const Surface& surface) : scale_(numeric_value(surface.scale)) {
  if (surface.dims != 3) throw std::logic_error("FieldSampler: the density stage needs a 3D surface");
  field_ = define_field_atoms(surface, 2, atoms_);
  value_program_ = natural_program(atoms_, {field_.field()});
  std::vector<GiNaC::ex> jet = {field_.field()};
  for (int i = 0; i < 3; ++i) jet.push_back(field_.gradient(i));
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) jet.push_back(field_.hessian(i, j));
  jet_program_ = natural_program(atoms_, jet);
  for (int i = 0; i < 3; ++i)
    column_programs_[static_cast<size_t>(i)] = natural_program(atoms_, {field_.field(), field_.gradient(i)});
  value_ = std::make_unique<Evaluator>(value_program_);
  jet_ = std::make_unique<Evaluator>(jet_program_);
  for (size_t i = 0; i < 3; ++i) {
    columns_[i] = std::make_unique<ColumnEvaluator>(column_programs_[i], static_cast<int>(i));
    column_jets_[i] = std::make_unique<ColumnEvaluator>(jet_program_, static_cast<int>(i));
  }
  const CellBounds bounds = cell_bounds(surface, atoms_, field_);
  gradient_bound_ = bounds.gradient * scale_;
  hessian_bound_ = bounds.hessian * scale_ * scale_;
}

double FieldSampler::value(const std::array<double, 3>& p) {
  for (size_t i = 0; i < 3; ++i) inputs_[i] = scale_ * p[i];
  return (*value_)(inputs_)[0];
}

FieldJet FieldSampler::jet(const std::array<double, 3>& p) {
  for (size_t i = 0; i < 3; ++i) inputs_[i] = scale_ * p[i];
  return to_jet((*jet_)(inputs_));
}

FieldJet FieldSampler::to_jet(const std::vector<double>& o) const {
  FieldJet j;
  j.value = o[0];
  for (size_t i = 0; i < 3; ++i) j.gradient[i] = scale_ * o[1 + i];
  size_t next = 4;
  for (size_t i = 0; i < 3; ++i)
    for (size_t k = i; k < 3; ++k) j.hessian[i][k] = j.hessian[k][i] = scale_ * scale_ * o[next++];
  return j;
}

void FieldSampler::start_column(int axis, const std::array<double, 3>& p) {
  axis_ = axis;
  for (size_t i = 0; i < 3; ++i) inputs_[i] = scale_ * p[i];
  columns_[static_cast<size_t>(axis)]->fix(inputs_);
  column_jets_[static_cast<size_t>(axis)]->fix(inputs_);
}

ColumnValue FieldSampler::column(double t) {
  const std::vector<double>& o = columns_[static_cast<size_t>(axis_)]->at(scale_ * t);
  return {o[0], scale_ * o[1]};
}

FieldJet FieldSampler::column_jet(double t) { return to_jet(column_jets_[static_cast<size_t>(axis_)]->at(scale_ * t)); }

}  // namespace offsetgen::density
