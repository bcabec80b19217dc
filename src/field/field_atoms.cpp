#include "field/field_atoms.h"

#include "field/symbolic_diff.h"

namespace offsetgen {

std::vector<GiNaC::ex> FieldAtoms::gradient() const {
  std::vector<GiNaC::ex> g;
  for (int i = 0; i < dims; ++i) g.push_back(gradient(i));
  return g;
}

FieldAtoms define_field_atoms(const Surface& surface, int depth, AtomTable& atoms) {
  const Symbols& sym = Symbols::get();
  std::vector<GiNaC::symbol> vars;
  for (int i = 0; i < surface.dims; ++i) vars.push_back(sym.natural(i));
  MemoDiff differ(vars);
  FieldAtoms f;
  f.dims = surface.dims;
  for (const auto& alpha : indices_up_to(surface.dims, depth))
    f.jet[alpha] = atoms.define("F" + index_label(alpha), differ.partial(surface.field, alpha), 0);
  return f;
}

}  // namespace offsetgen
