#include "lowering/field_lowering.h"

#include <algorithm>

namespace offsetgen {
namespace {

double numeric_value(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

}  // namespace

FieldLowering::FieldLowering(Program& program, const Surface& surface, const AtomTable& atoms, const FieldAtoms& field)
    : program_(program), field_(field), lowerer_(program, atoms), scale_(numeric_value(surface.scale)) {
  Environment& env = add_environment(-1);
  NodeId k = program_.constant(scale_);
  for (int i = 0; i < surface.dims; ++i) {
    point_.push_back(program_.mul(k, program_.input(i)));
    env.bindings.emplace_back(Symbols::get().natural(i), point_.back());
    // X_i = k x_i = pi (k / pi) x_i: trig of multiples of X_i can be evaluated in half-turns of x_i.
    env.half_turns.push_back({Symbols::get().natural(i), i, surface.scale / GiNaC::Pi});
  }
  points_.push_back({point_, &env});
}

Environment& FieldLowering::add_environment(int shared_id) {
  Environment env;
  env.id = next_id_++;
  env.shared_id = shared_id < 0 ? env.id : shared_id;
  environments_.push_back(env);
  return environments_.back();
}

NodeId FieldLowering::natural(NodeId cell_value) { return program_.mul(program_.constant(scale_), cell_value); }

const Environment& FieldLowering::at(const std::vector<NodeId>& natural_point) {
  for (const auto& [point, env] : points_)
    if (point == natural_point) return *env;
  Environment& env = add_environment(-1);
  for (int i = 0; i < dims(); ++i)
    env.bindings.emplace_back(Symbols::get().natural(i), natural_point[static_cast<size_t>(i)]);
  points_.push_back({natural_point, &env});
  return env;
}

FieldLowering::Displaced FieldLowering::displaced(const std::vector<NodeId>& d, const std::vector<NodeId>& d_squared) {
  std::vector<NodeId> q;
  for (size_t i = 0; i < d.size(); ++i) q.push_back(program_.sub(point_[i], d[i]));
  if (!angle_addition_) return {&at(q), q};
  for (const auto& [key, env] : displacements_)
    if (key == d) return {env, q};
  Environment& env = add_environment(-1);
  env.displaced_from = &base();
  for (int i = 0; i < dims(); ++i) {
    env.bindings.emplace_back(Symbols::get().natural(i), q[static_cast<size_t>(i)]);
    const size_t k = static_cast<size_t>(i);
    env.displacement.push_back(
        {Symbols::get().natural(i), d[k], d_squared.empty() ? program_.mul(d[k], d[k]) : d_squared[k]});
  }
  displacements_.push_back({d, &env});
  return {&env, q};
}

const Environment& FieldLowering::with(const Environment& from, const GiNaC::symbol& symbol, NodeId value) {
  for (const auto& env : environments_) {
    if (env.shared_id != from.shared_id || env.bindings.size() != from.bindings.size() + 1) continue;
    const auto& last = env.bindings.back();
    if (last.first.is_equal(symbol) && last.second == value &&
        std::equal(from.bindings.begin(), from.bindings.end(), env.bindings.begin(),
                   [](const auto& a, const auto& b) { return a.first.is_equal(b.first) && a.second == b.second; }))
      return env;
  }
  Environment& env = add_environment(from.shared_id);
  env.bindings = from.bindings;
  env.half_turns = from.half_turns;
  env.bindings.emplace_back(symbol, value);
  return env;
}

std::vector<NodeId> FieldLowering::gradient(const Environment& env) {
  std::vector<NodeId> g;
  for (int i = 0; i < dims(); ++i) g.push_back(lower(field_.gradient(i), env));
  return g;
}

NodeId FieldLowering::cell_expression(const GiNaC::ex& e, const std::vector<NodeId>& natural_point) {
  const Environment* found = nullptr;
  for (const auto& [point, env] : cell_points_)
    if (point == natural_point) found = env;
  if (!found) {
    Environment& env = add_environment(-1);
    NodeId inverse = program_.constant(1 / scale_);
    for (int i = 0; i < dims(); ++i) {
      // At p itself the cell coordinates are the inputs: no round trip through k x / k.
      NodeId cell =
          natural_point == point_ ? program_.input(i) : program_.mul(inverse, natural_point[static_cast<size_t>(i)]);
      env.bindings.emplace_back(Symbols::get().cell(i), cell);
      if (natural_point == point_) env.half_turns.push_back({Symbols::get().cell(i), i, 1 / GiNaC::Pi});
    }
    cell_points_.push_back({natural_point, &env});
    found = &env;
  }
  return lower(e, *found);
}

}  // namespace offsetgen
