// Memoised symbolic differentiation over GiNaC's expression DAG.
#pragma once

#include "field/multi_index.h"

#include <ginac/ginac.h>

#include <map>
#include <unordered_map>
#include <vector>

namespace offsetgen {

// GiNaC's own diff() walks trees, so nested derivatives re-derive every shared subtree (12 s for the
// gyroid at order 6). This caches d/dv per node, and D^alpha per expression, so each distinct
// subexpression is differentiated once per variable.
class MemoDiff {
 public:
  explicit MemoDiff(std::vector<GiNaC::symbol> variables);

  GiNaC::ex diff(const GiNaC::ex& e, int variable);
  // D^alpha e, built from D^(alpha - e_last) e so mixed partials are derived once.
  GiNaC::ex partial(const GiNaC::ex& e, const MultiIndex& alpha);

 private:
  GiNaC::ex diff_uncached(const GiNaC::ex& e, int variable);
  GiNaC::ex function_derivative(const GiNaC::ex& f, size_t argument);

  std::vector<GiNaC::symbol> variables_;
  std::vector<std::unordered_map<GiNaC::ex, GiNaC::ex>> cache_;  // one per variable
  std::map<std::pair<GiNaC::ex, MultiIndex>, GiNaC::ex,
           bool (*)(const std::pair<GiNaC::ex, MultiIndex>&, const std::pair<GiNaC::ex, MultiIndex>&)>
      partials_;
};

}  // namespace offsetgen
