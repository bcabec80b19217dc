// Evaluates F, its derivatives and a method's expressions with CLN numbers at any point, without
// lowering: the ground truth the emitted code is checked against. Exact rationals stay exact (sqrt
// of a perfect square included); everything else carries `digits` significant digits.
#pragma once

#include "field/atom_table.h"
#include "field/field_atoms.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <unordered_map>
#include <utility>
#include <vector>

namespace offsetgen {

// GiNaC's precision is a global; this holds it for one evaluation.
class DigitsGuard {
 public:
  explicit DigitsGuard(int digits) : saved_(GiNaC::Digits) { GiNaC::Digits = static_cast<long>(digits); }
  ~DigitsGuard() { GiNaC::Digits = saved_; }
  DigitsGuard(const DigitsGuard&) = delete;
  DigitsGuard& operator=(const DigitsGuard&) = delete;

 private:
  long saved_;
};

class FieldReference {
 public:
  using Point = std::vector<GiNaC::numeric>;  // natural coordinates

  // Values bound to symbols, and a memo. Level-0 atoms (F and its derivatives) are memoised in the
  // scope of their point; atoms of higher level in the scope that binds their step.
  struct Scope {
    std::vector<std::pair<GiNaC::ex, GiNaC::numeric>> bindings;
    std::unordered_map<GiNaC::ex, GiNaC::numeric> memo;
  };

  // `p_natural` is the base point p.
  FieldReference(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field, const Point& p_natural);

  int dims() const { return field_.dims; }
  const Point& point() const { return point_; }
  const GiNaC::numeric& scale() const { return scale_; }
  Scope& base() { return base_; }
  Scope at(const Point& natural_point) const;  // a fresh scope for another point
  FieldReference moved(const Point& p_natural) const { return {surface_, atoms_, field_, p_natural}; }

  GiNaC::numeric eval(const GiNaC::ex& e, Scope& scope, Scope& shared);
  GiNaC::numeric eval(const GiNaC::ex& e, Scope& scope) { return eval(e, scope, scope); }
  GiNaC::numeric field(Scope& scope) { return eval(field_.field(), scope); }
  std::vector<GiNaC::numeric> gradient(Scope& scope);
  // An expression of the cell coordinates x, y, z at a point in natural coordinates.
  GiNaC::numeric cell_expression(const GiNaC::ex& e, const Point& natural_point) const;

 private:
  const Surface& surface_;
  const AtomTable& atoms_;
  const FieldAtoms& field_;
  GiNaC::numeric scale_;
  Point point_;
  Scope base_;
};

// The numeric value of an expression that should be a number (throws otherwise).
GiNaC::numeric numeric_of(const GiNaC::ex& e);

}  // namespace offsetgen
