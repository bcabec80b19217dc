// Named intermediate quantities ("atoms") of the offset construction, each a symbol with a
// small defining expression over earlier atoms. The layered definitions keep every GiNaC expression
// small; the lowering inlines them into one straight-line program.
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <unordered_map>
#include <vector>

namespace offsetgen {

struct Atom {
  GiNaC::symbol symbol;
  GiNaC::ex definition;
  int level = 0;  // chain level k; level 0 does not depend on the step s
};

class AtomTable {
 public:
  // A numeric or bare-symbol definition is returned as is: a zero derivative then cancels
  // terms symbolically instead of surviving as a named zero.
  GiNaC::ex define(const std::string& name, const GiNaC::ex& definition, int level);
  const Atom* find(const GiNaC::ex& e) const;
  const std::vector<Atom>& atoms() const { return atoms_; }

 private:
  std::vector<Atom> atoms_;
  std::unordered_map<GiNaC::ex, size_t> index_;
};

}  // namespace offsetgen
