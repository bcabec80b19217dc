// F and its partial derivatives in natural coordinates, as named atoms of an AtomTable: what every
// offset construction evaluates, at the point p or at any other point.
#pragma once

#include "field/atom_table.h"
#include "field/multi_index.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <map>
#include <vector>

namespace offsetgen {

struct FieldAtoms {
  int dims = 3;
  std::map<MultiIndex, GiNaC::ex> jet;  // D^alpha F for |alpha| <= depth (atoms "F<alpha>", level 0)

  const GiNaC::ex& field() const { return jet.at({0, 0, 0}); }
  GiNaC::ex gradient(int i) const { return jet.at(unit_index(i)); }
  std::vector<GiNaC::ex> gradient() const;
  bool has_hessian() const { return jet.count(unit_index(0) + unit_index(0)) > 0; }
  GiNaC::ex hessian(int i, int j) const { return jet.at(unit_index(i) + unit_index(j)); }
};

// Defines D^alpha F for every |alpha| <= depth in `atoms`, by memoised symbolic differentiation.
FieldAtoms define_field_atoms(const Surface& surface, int depth, AtomTable& atoms);

}  // namespace offsetgen
