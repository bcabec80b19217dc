// Method "richardson": the paper's construction (Geier & Alihussein, Algorithms 2021). Recursive
// first-order offsets phi_1 = F - h |grad F| combined by extended Richardson extrapolation:
//   phi^(m) = F - h G,  G = sum_j (w_j / j) sum_k |grad psi_k^(j)|   (offset_model.h),
// with the safeguard clamp on G (SafeguardBounds).
#include "offset/richardson_method.h"

#include "lowering/cell_bounds.h"
#include "lowering/field_lowering.h"
#include "offset/field_reference.h"
#include "offset/offset_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>

namespace offsetgen {
namespace {

// Read by cmake/Install.cmake too (offsetgen_generate() checks METHOD and ORDERS at configure time).
constexpr const char* kMethodName = "richardson";
constexpr int kMethodMaxOrder = 12;
constexpr bool kMethodEvenOrdersOnly = false;

MethodFacts describe(int order, const CellBounds& b) {
  MethodFacts f;
  f.method = kMethodName;
  f.requested_order = f.order = order;
  // h is read at the evaluation point p: each wall sits where h(wall point) is reached, first order;
  // the first-order parts of the two walls cancel in the total (paper section 6).
  f.graded_order = std::min(order, 2);
  f.graded_wall_order = 1;
  f.graded_paper_order = std::min(order, 2);
  f.summary = fmt::format(
      "extended Richardson extrapolation of order {}: recursive first-order offsets F - h |grad F| "
      "combined so that the error terms below h^{} cancel.",
      order, order + 1);
  f.citation =
      "Geier & Alihussein, \"Computation of Implicit Representation of Volumetric Shells with Predefined "
      "Thickness\", Algorithms 14(4):125 (2021).";
  f.accuracy = fmt::format(
      "the zero set of _offset lies within O(h^{}) of the exact offset surface, so the relative thickness "
      "error falls as (h/L)^{}.",
      order + 1, order);
  f.variable_thickness =
      "pass the local t(p) to _shell (or use --thickness for a _graded function). The derivation assumes a "
      "constant h, so a varying thickness is accurate to second order at best, whatever the order of this file.";
  f.safety = fmt::format(
      "where grad F vanishes the raw formulas divide by zero, and next to saddles of F the high-order terms "
      "blow up. Here phi = F - h G with G clamped to [max(|grad F| - 1.5 H |h|, -M), min(|grad F| + 0.5 H |h|, "
      "M)], where M = {:.17g} >= max |grad F| and H = {:.17g} >= max ||Hess F|| over the cell (2*pi/L scaled "
      "coordinates, h in them too; at order 1 only the M clamp). Every function returns a finite value for "
      "finite input (do not compile with -ffinite-math-only); phi has the sign of F wherever |F| > |h| M, and "
      "|phi - (F - h |grad F|)| <= 1.5 H h^2, so no phantom walls appear. On the offset surface itself G = F/h "
      "lies inside the interval, so accuracy is untouched.",
      b.gradient, b.hessian);
  f.normal =
      "unit normal (direction of +grad phi) of the offset surface at distance h, derived analytically; "
      "zero where the gradient vanishes.";
  return f;
}

class Richardson final : public OffsetConstruction {
 public:
  Richardson(const Surface& surface, int order, std::optional<CellBounds> bounds)
      : model_(build_offset_model(surface, order, /*with_gradient=*/true)),
        bounds_(bounds ? *bounds : cell_bounds(surface, model_.atoms, model_.field_atoms)),
        facts_(describe(order, bounds_)) {}

  const MethodFacts& facts() const override { return facts_; }
  const AtomTable& atoms() const override { return model_.atoms; }
  const FieldAtoms& field() const override { return model_.field_atoms; }
  const CellBounds& bounds() const override { return bounds_; }

  NodeId lower_offset(FieldLowering& at, NodeId h) const override {
    Program& program = at.program();
    NodeId g = chain_sum(at, model_.weighted_norms, h);
    return program.sub(at.field(at.base()), program.mul(h, clamp(at, g, h)));
  }

  // grad phi = grad F - h grad G, or grad F where the clamp is active (G is constant there).
  // Where that gradient is not a finite, positive length (derivatives of |grad F| are 0/0 at
  // critical points of F) the normal falls back to grad F / |grad F|, and to 0 where that vanishes.
  std::vector<NodeId> lower_normal(FieldLowering& at, NodeId h) const override {
    Program& program = at.program();
    const std::vector<NodeId> field_gradient = at.gradient(at.base());
    NodeId g = chain_sum(at, model_.weighted_norms, h);
    const Limits l = limits(at, h);
    NodeId below_hi = program.less_eq(g, l.hi), above_lo = program.less_eq(l.lo, g);
    std::vector<NodeId> gradient, field_squares, squares;
    for (int i = 0; i < model_.dims; ++i) {
      const NodeId dF = field_gradient[static_cast<size_t>(i)];
      NodeId g_i = chain_sum(at, model_.weighted_norms_gradient[static_cast<size_t>(i)], h);
      NodeId full = program.sub(dF, program.mul(h, g_i));
      // Clamped to an interval limit |grad F| + c|h|, G varies like |grad F|; clamped to -M or M it is constant.
      NodeId at_lo = dF, at_hi = dF;
      if (l.hi_moves) {
        NodeId d_norm = at.lower(model_.field_gradient_norm_gradient[static_cast<size_t>(i)], at.base());
        NodeId moving = program.sub(dF, program.mul(h, d_norm));
        at_lo = program.select(*l.lo_moves, moving, at_lo);
        at_hi = program.select(*l.hi_moves, moving, at_hi);
      }
      gradient.push_back(program.select(below_hi, program.select(above_lo, full, at_lo), at_hi));
      squares.push_back(program.mul(gradient.back(), gradient.back()));
      field_squares.push_back(program.mul(dF, dF));
    }
    NodeId zero = program.constant(0);
    NodeId length2 = program.sum(squares);
    NodeId field_length2 = program.sum(field_squares);
    NodeId field_inverse = program.select(program.greater(field_length2, zero),
                                          program.div(program.constant(1), program.sqrt(field_length2)), zero);
    NodeId inverse = program.div(program.constant(1), program.sqrt(length2));
    NodeId positive = program.greater(length2, zero);                   // false for NaN too
    NodeId bounded = program.less_eq(length2, program.constant(1e30));  // false for inf and NaN
    std::vector<NodeId> normal;
    for (int i = 0; i < model_.dims; ++i) {
      NodeId fallback = program.mul(field_gradient[static_cast<size_t>(i)], field_inverse);
      NodeId unit = program.mul(gradient[static_cast<size_t>(i)], inverse);
      normal.push_back(program.select(positive, program.select(bounded, unit, fallback), fallback));
    }
    return normal;
  }

  // The paper's section 6: the model assumes a constant h, so h(p) is read at p only.
  NodeId lower_graded_offset(FieldLowering& at, const LoweredHalfThickness& h) const override {
    return lower_offset(at, h(at.point()));
  }

  GiNaC::numeric offset(FieldReference& at, const GiNaC::numeric& h) const override {
    GiNaC::numeric g = chain_sum(at, model_.weighted_norms, h);
    if (bounds_.gradient > 0) {
      GiNaC::numeric lo = -GiNaC::numeric(bounds_.gradient), hi = GiNaC::numeric(bounds_.gradient);
      if (model_.order > 1 && bounds_.hessian > 0) {
        const GiNaC::numeric norm = at.eval(model_.field_gradient_norm, at.base());
        const GiNaC::numeric spread = GiNaC::numeric(bounds_.hessian) * GiNaC::abs(h);
        lo = std::max(lo, norm - GiNaC::numeric(kSafeguardBelow) * spread, numeric_less);
        hi = std::min(hi, norm + GiNaC::numeric(kSafeguardAbove) * spread, numeric_less);
      }
      // In the order the emitted selects test it (lower_offset).
      if (!(g <= hi)) {
        g = hi;
      } else if (!(lo <= g)) {
        g = lo;
      }
    }
    return at.field(at.base()) - h * g;
  }

  // The unit gradient of phi(., h) at p by central differences at the reference's precision.
  std::vector<GiNaC::numeric> normal(FieldReference& at, const GiNaC::numeric& h) const override {
    const GiNaC::numeric step = GiNaC::numeric(1, 1000000000000L);  // O(1e-24) truncation at 40 digits
    std::vector<GiNaC::numeric> d;
    GiNaC::numeric length2 = 0;
    for (int i = 0; i < at.dims(); ++i) {
      auto plus = at.point(), minus = at.point();
      plus[static_cast<size_t>(i)] += step;
      minus[static_cast<size_t>(i)] -= step;
      FieldReference ap = at.moved(plus), am = at.moved(minus);
      d.push_back((offset(ap, h) - offset(am, h)) / (2 * step));
      length2 += d.back() * d.back();
    }
    if (!(length2 > 0)) return d;
    const GiNaC::numeric length = numeric_of(GiNaC::sqrt(length2));
    for (auto& c : d) c /= length;
    return d;
  }

  GiNaC::numeric graded_offset(FieldReference& at, const ReferenceHalfThickness& h) const override {
    return offset(at, h(at.point()));
  }

 private:
  static bool numeric_less(const GiNaC::numeric& a, const GiNaC::numeric& b) { return a < b; }

  // sum_j c_j sum_k N_k^(j), each chain j in its own environment (step s = h/j).
  NodeId chain_sum(FieldLowering& at, const ChainSum& terms, NodeId h) const {
    Program& program = at.program();
    std::vector<std::pair<GiNaC::numeric, std::vector<NodeId>>> by_coeff;
    for (const auto& term : terms) {
      NodeId step = program.mul(h, program.constant(1.0 / term.chain));
      NodeId value = at.lower(term.value, at.with(at.base(), Symbols::get().s, step));
      auto it = std::find_if(by_coeff.begin(), by_coeff.end(), [&](const auto& c) { return c.first == term.coeff; });
      if (it == by_coeff.end()) {
        by_coeff.push_back({term.coeff, {value}});
      } else {
        it->second.push_back(value);
      }
    }
    std::vector<NodeId> weighted;
    for (auto& [coeff, values] : by_coeff)
      weighted.push_back(program.mul(program.constant(coeff.to_double()), program.sum(values)));
    return program.sum(weighted);
  }

  GiNaC::numeric chain_sum(FieldReference& at, const ChainSum& terms, const GiNaC::numeric& h) const {
    std::map<int, FieldReference::Scope> chains;
    GiNaC::numeric total = 0;
    for (const auto& term : terms) {
      auto [it, fresh] = chains.try_emplace(term.chain);
      if (fresh) {
        it->second = at.at(at.point());
        it->second.bindings.emplace_back(Symbols::get().s, h / term.chain);
      }
      total += term.coeff * at.eval(term.value, it->second, at.base());
    }
    return total;
  }

  // The safeguard's limits [lo, hi] on G at the distance h (natural units); see SafeguardBounds.
  // lo_moves / hi_moves: whether the limit is the interval's (it varies with p) rather than -M / M;
  // absent at order 1, where only the M clamp applies.
  struct Limits {
    NodeId lo, hi;
    std::optional<NodeId> lo_moves, hi_moves;
  };
  Limits limits(FieldLowering& at, NodeId h) const {
    Program& program = at.program();
    NodeId m = program.constant(bounds_.gradient);
    Limits l{program.neg(m), m, std::nullopt, std::nullopt};
    if (model_.order > 1 && bounds_.hessian > 0) {
      NodeId norm = at.lower(model_.field_gradient_norm, at.base());
      NodeId distance = program.abs(h);
      NodeId below = program.sub(norm, program.mul(program.constant(kSafeguardBelow * bounds_.hessian), distance));
      NodeId above = program.add(norm, program.mul(program.constant(kSafeguardAbove * bounds_.hessian), distance));
      l.lo_moves = program.less_eq(l.lo, below);
      l.hi_moves = program.less_eq(above, l.hi);
      l.lo = program.select(*l.lo_moves, below, l.lo);
      l.hi = program.select(*l.hi_moves, above, l.hi);
    }
    return l;
  }

  // G inside its limits: <= hi first, so NaN (0/0 at critical points of F) maps to hi, finite.
  NodeId clamp(FieldLowering& at, NodeId g, NodeId h) const {
    Program& program = at.program();
    const Limits l = limits(at, h);
    return program.select(program.less_eq(g, l.hi), program.select(program.less_eq(l.lo, g), g, l.lo), l.hi);
  }

  OffsetModel model_;
  CellBounds bounds_;
  MethodFacts facts_;
};

class RichardsonMethod final : public OffsetMethod {
 public:
  std::string name() const override { return kMethodName; }
  std::string description() const override {
    return "extended Richardson extrapolation of recursive first-order offsets (Geier & Alihussein, Algorithms "
           "14(4):125, 2021; orders 1-12)";
  }
  int max_order() const override { return kMethodMaxOrder; }
  bool cost_grows_geometrically() const override { return true; }  // ~5x per order
  int effective_order(int requested) const override {
    static_assert(!kMethodEvenOrdersOnly, "every order is built as asked");
    return requested;
  }
  std::unique_ptr<OffsetConstruction> build(const Surface& surface, int order) const override {
    return std::make_unique<Richardson>(surface, order, std::nullopt);
  }
};

}  // namespace

const OffsetMethod& richardson_method() {
  static const RichardsonMethod method;
  return method;
}

std::unique_ptr<OffsetConstruction> build_richardson(const Surface& surface, int order,
                                                     std::optional<CellBounds> bounds) {
  return std::make_unique<Richardson>(surface, order, bounds);
}

}  // namespace offsetgen
