#include "offset/field_reference.h"

#include <stdexcept>
#include <string>

namespace offsetgen {

GiNaC::numeric numeric_of(const GiNaC::ex& e) {
  GiNaC::ex v = GiNaC::is_a<GiNaC::numeric>(e) ? e : GiNaC::evalf(e);
  if (!GiNaC::is_a<GiNaC::numeric>(v)) throw std::runtime_error("high-precision evaluation did not give a number");
  return GiNaC::ex_to<GiNaC::numeric>(v);
}

FieldReference::FieldReference(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field,
                               const Point& p_natural)
    : surface_(surface),
      atoms_(atoms),
      field_(field),
      scale_(numeric_of(surface.scale)),
      point_(p_natural),
      base_(at(p_natural)) {}

FieldReference::Scope FieldReference::at(const Point& natural_point) const {
  Scope scope;
  for (int i = 0; i < dims(); ++i)
    scope.bindings.emplace_back(Symbols::get().natural(i), natural_point.at(static_cast<size_t>(i)));
  return scope;
}

GiNaC::numeric FieldReference::eval(const GiNaC::ex& e, Scope& scope, Scope& shared) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e);
  if (GiNaC::is_a<GiNaC::constant>(e)) return numeric_of(e);
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (const auto& [symbol, value] : scope.bindings)
      if (symbol.is_equal(e)) return value;
    const Atom* atom = atoms_.find(e);
    if (!atom) throw std::runtime_error("unbound symbol " + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    Scope& home = atom->level == 0 ? shared : scope;
    if (auto it = home.memo.find(e); it != home.memo.end()) return it->second;
    GiNaC::numeric value = eval(atom->definition, scope, shared);
    home.memo.emplace(e, value);
    return value;
  }
  if (auto it = scope.memo.find(e); it != scope.memo.end()) return it->second;
  GiNaC::numeric result;
  if (GiNaC::is_a<GiNaC::add>(e)) {
    result = 0;
    for (size_t i = 0; i < e.nops(); ++i) result += eval(e.op(i), scope, shared);
  } else if (GiNaC::is_a<GiNaC::mul>(e)) {
    result = 1;
    for (size_t i = 0; i < e.nops(); ++i) result *= eval(e.op(i), scope, shared);
  } else if (GiNaC::is_a<GiNaC::power>(e)) {
    GiNaC::numeric base = eval(e.op(0), scope, shared);
    GiNaC::numeric exponent = eval(e.op(1), scope, shared);
    result = exponent.is_integer() ? base.power(exponent) : numeric_of(GiNaC::pow(base, exponent));
  } else if (GiNaC::is_a<GiNaC::function>(e)) {
    GiNaC::exvector args;
    for (size_t i = 0; i < e.nops(); ++i) args.push_back(eval(e.op(i), scope, shared));
    result = numeric_of(GiNaC::function(GiNaC::ex_to<GiNaC::function>(e).get_serial(), args));
  } else {
    throw std::runtime_error("cannot evaluate expression class " +
                             std::string(GiNaC::ex_to<GiNaC::basic>(e).class_name()));
  }
  scope.memo.emplace(e, result);
  return result;
}

std::vector<GiNaC::numeric> FieldReference::gradient(Scope& scope) {
  std::vector<GiNaC::numeric> g;
  for (int i = 0; i < dims(); ++i) g.push_back(eval(field_.gradient(i), scope));
  return g;
}

GiNaC::numeric FieldReference::cell_expression(const GiNaC::ex& e, const Point& natural_point) const {
  GiNaC::exmap cell;
  for (int i = 0; i < dims(); ++i) cell[Symbols::get().cell(i)] = natural_point.at(static_cast<size_t>(i)) / scale_;
  return numeric_of(e.subs(cell));
}

}  // namespace offsetgen
