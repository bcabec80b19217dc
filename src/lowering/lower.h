// Lowering GiNaC expressions (with atoms) into a straight-line Program.
#pragma once

#include "field/atom_table.h"
#include "lowering/program.h"

#include <ginac/ginac.h>

#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace offsetgen {

// What the free symbols of an expression stand for in one evaluation: the coordinates, the
// offset h, and the step s = h/j of chain j. Atoms of level >= 1 depend on s, so each environment
// lowers its own copy; level-0 atoms are shared through `shared_id`.
struct Environment {
  int id = 0;         // memo key; distinct per binding of s and h
  int shared_id = 0;  // memo key for step-independent atoms (same coordinates, any s)
  std::vector<std::pair<GiNaC::ex, NodeId>> bindings;
  // A point q = p - d given by its displacement from the point of `displaced_from`: sin and cos of
  // an integer multiple of one natural coordinate are then rebuilt from their values at p by angle
  // addition, with short polynomials in the small angle d_i (cheaper than reducing a new argument).
  // The caller guarantees |d_i| <= kSmallAngleMax.
  const Environment* displaced_from = nullptr;
  struct Displacement {
    GiNaC::ex coordinate;  // a natural coordinate symbol
    NodeId d;              // q_i = p_i - d
    NodeId d_squared;      // d^2, possibly computed on a shorter path than d * d
  };
  std::vector<Displacement> displacement;
  // Coordinates bound to pi * per_half_turn * input(input), per_half_turn exact (k/pi for X = k x at
  // the base point): sin and cos of c * coordinate with c * per_half_turn rational are noted in
  // half-turns (Program::note_half_turns).
  struct HalfTurnCoordinate {
    GiNaC::ex coordinate;
    int input = -1;
    GiNaC::ex per_half_turn;
  };
  std::vector<HalfTurnCoordinate> half_turns;
};

// The largest |d| the small-angle polynomials of displaced environments are exact for (within
// 1.1e-17 of sin d and cos d; tools/small_angle_fit.py).
inline constexpr double kSmallAngleMax = 1.0;

// Whether the natural coordinates occur in `e` only inside sin and cos of integer multiples of one
// coordinate (the catalog TPMS): then displaced environments never evaluate trig of a new argument.
bool is_trigonometric_polynomial(const GiNaC::ex& e);

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
  // sin and cos of a * X at a displaced point (Environment::displacement); nullopt when the argument
  // is not an integer multiple of one displaced coordinate.
  std::optional<std::pair<NodeId, NodeId>> displaced_sincos(const GiNaC::ex& argument, const Environment& env);
  std::pair<NodeId, NodeId> small_angle_sincos(NodeId d, NodeId d_squared);
  // Notes the sin/cos node `result` of `argument` in half-turns where env allows (Environment::half_turns).
  void note_half_turns(NodeId result, const GiNaC::ex& argument, NodeId argument_node, const Environment& env);

  Program& program_;
  const AtomTable& atoms_;
  std::unordered_map<int, std::unordered_map<GiNaC::ex, NodeId>> memo_;  // per environment id
};

}  // namespace offsetgen
