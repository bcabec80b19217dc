#include "field/atom_table.h"

namespace offsetgen {

GiNaC::ex AtomTable::define(const std::string& name, const GiNaC::ex& definition, int level) {
  if (GiNaC::is_a<GiNaC::numeric>(definition) || GiNaC::is_a<GiNaC::symbol>(definition)) return definition;
  Atom atom{GiNaC::symbol(name), definition, level};
  GiNaC::ex symbol = atom.symbol;
  index_.emplace(symbol, atoms_.size());
  atoms_.push_back(std::move(atom));
  return symbol;
}

const Atom* AtomTable::find(const GiNaC::ex& e) const {
  if (!GiNaC::is_a<GiNaC::symbol>(e)) return nullptr;
  auto it = index_.find(e);
  return it == index_.end() ? nullptr : &atoms_[it->second];
}

}  // namespace offsetgen
