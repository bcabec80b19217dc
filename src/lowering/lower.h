// Lowering GiNaC expressions (with atoms) into a straight-line Program.
#pragma once

#include "lowering/program.h"
#include "offset/atom_table.h"

#include <ginac/ginac.h>

#include <unordered_map>
#include <vector>

namespace offsetgen {

// What the free symbols of an expression stand for in one evaluation: the coordinates, the
// offset h, and the step s = h/j of chain j. Atoms of level >= 1 depend on s, so each environment
// lowers its own copy; level-0 atoms are shared through `shared_id`.
struct Environment {
  int id = 0;         // memo key; distinct per binding of s and h
  int shared_id = 0;  // memo key for step-independent atoms (same coordinates, any s)
  std::vector<std::pair<GiNaC::ex, NodeId>> bindings;
};

class Lowerer {
 public:
  Lowerer(Program& program, const AtomTable& atoms) : program_(program), atoms_(atoms) {}

  NodeId lower(const GiNaC::ex& e, const Environment& env);

 private:
  NodeId lower_uncached(const GiNaC::ex& e, const Environment& env);
  NodeId lower_add(const GiNaC::ex& e, const Environment& env);
  NodeId lower_mul(const GiNaC::ex& e, const Environment& env);
  NodeId lower_function(const GiNaC::ex& e, const Environment& env);
  NodeId lower_numeric(const GiNaC::ex& e);
  // base^(p/2) for odd p, through one shared 1/sqrt(base).
  NodeId half_power(NodeId base, int numerator);

  Program& program_;
  const AtomTable& atoms_;
  std::unordered_map<int, std::unordered_map<GiNaC::ex, NodeId>> memo_;  // per environment id
};

}  // namespace offsetgen
