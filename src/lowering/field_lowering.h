// Lowers F, its derivatives and a method's expressions at points of one program. The program's
// first dims inputs are the cell coordinates x; the base point p = k x is in natural coordinates.
#pragma once

#include "field/field_atoms.h"
#include "lowering/lower.h"
#include "surfaces/surface.h"

#include <deque>
#include <vector>

namespace offsetgen {

class FieldLowering {
 public:
  FieldLowering(Program& program, const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);
  FieldLowering(const FieldLowering&) = delete;
  FieldLowering& operator=(const FieldLowering&) = delete;

  Program& program() { return program_; }
  int dims() const { return field_.dims; }
  const std::vector<NodeId>& point() const { return point_; }  // p, natural coordinates
  const Environment& base() const { return environments_.front(); }
  NodeId natural(NodeId cell_value);  // k * value

  // The environment of another point. It has its own memo for level-0 atoms: sharing p's would
  // silently reuse F(p) for F(q).
  const Environment& at(const std::vector<NodeId>& natural_point);
  // The point p - d (natural units). With angle addition on, sin and cos of multiples of a
  // coordinate there come from their values at p (Environment::displacement); then every |d_i|
  // must be <= kSmallAngleMax.
  struct Displaced {
    const Environment* env;
    std::vector<NodeId> point;  // p - d
  };
  // `d_squared` (optional, empty: d * d) gives the squares on a path the caller chose.
  Displaced displaced(const std::vector<NodeId>& d, const std::vector<NodeId>& d_squared = {});
  void use_angle_addition(bool on) { angle_addition_ = on; }

  // `from` plus one binding (a Richardson chain's step s): the same point, so level-0 atoms are shared.
  const Environment& with(const Environment& from, const GiNaC::symbol& symbol, NodeId value);

  NodeId lower(const GiNaC::ex& e, const Environment& env) { return lowerer_.lower(e, env); }
  NodeId field(const Environment& env) { return lower(field_.field(), env); }
  std::vector<NodeId> gradient(const Environment& env);
  // An expression of the cell coordinates x, y, z (a thickness) at a point given in natural coordinates.
  NodeId cell_expression(const GiNaC::ex& e, const std::vector<NodeId>& natural_point);

 private:
  Environment& add_environment(int shared_id);

  Program& program_;
  const FieldAtoms& field_;
  Lowerer lowerer_;
  double scale_ = 1;
  std::vector<NodeId> point_;
  std::deque<Environment> environments_;  // references stay valid as it grows
  std::vector<std::pair<std::vector<NodeId>, const Environment*>> points_, cell_points_;
  int next_id_ = 0;
  bool angle_addition_ = false;
  std::vector<std::pair<std::vector<NodeId>, const Environment*>> displacements_;
};

}  // namespace offsetgen
