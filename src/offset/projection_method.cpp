// Method "projection": offsets by foot-point projection (docs/projection.md). With
// n = grad F / |grad F| (0 where grad F = 0):
//   q_0 = p - h n(p),  q_{j+1} = p - h n(q_j)  (j < K),  phi(p, h) = F(q_K).
// K projections give order 2(K+1). |q_K - p| = |h|, so |F(q_K) - F(p)| <= M |h| without any clamp.
// For K >= 1 on periodic trig polynomials (the catalog), phi is F's second-order Taylor polynomial
// at q_(K-1) evaluated at q_K: the step q_K - q_(K-1) is O(h^(K+1)), so the remainder is of the
// method's own order, and q_K needs no trig of its own. phi is kept within F(p) -+ M |h|, which
// holds F(q_K), so |phi - F(p)| <= M |h| still.
// Graded walls read the half thickness at the foot-point estimate: h_0 = h(p), h_{j+1} = h(q_j),
// q_{j+1} = p - h_{j+1} n(q_j), which gains one order per projection.
#include "lowering/cell_bounds.h"
#include "lowering/field_lowering.h"
#include "lowering/lower.h"
#include "offset/field_reference.h"
#include "offset/method.h"

#include <fmt/format.h>

namespace offsetgen {
namespace {

// Read by cmake/Install.cmake too (offsetgen_generate() checks METHOD and ORDERS at configure time).
constexpr const char* kMethodName = "projection";
constexpr int kMethodMaxOrder = 16;
constexpr bool kMethodEvenOrdersOnly = true;  // order 2(K+1): an odd order rounds up

// |grad F|^2 at or below FLT_MIN counts as zero on the angle-addition path (see foot_point).
constexpr double kTinyLength2 = 1.1754943508222875e-38;

constexpr int projections_for(int order) { return (order + 1) / 2 - 1; }  // K = ceil(m/2) - 1
static_assert(kMethodEvenOrdersOnly && 2 * (projections_for(3) + 1) == 4, "odd orders round up");

MethodFacts describe(int requested, int k, const CellBounds& b, bool angle_addition, bool taylor_last_step) {
  MethodFacts f;
  f.method = kMethodName;
  f.requested_order = requested;
  f.order = 2 * (k + 1);
  // Each thickness update gains one order against the thickness at the foot point (the wall);
  // the two walls' leading errors cancel in the total at even orders. Measured: K = 0..3 give
  // walls of order 1, 2, 3, 4 and totals of order 2, 2, 4, 4 (docs/projection.md).
  f.graded_wall_order = k + 1;
  f.graded_order = (k + 2) / 2 * 2;
  // The paper's measure reads t at the wall point, not at the foot point: first order once t is read
  // at an estimate of the foot point (K >= 1), second at K = 0, where it is read at p.
  f.graded_paper_order = k == 0 ? 2 : 1;
  f.summary = fmt::format(
      "foot-point projection with K = {} projection step{}: q_0 = p - h n(p), q_(j+1) = p - h n(q_j), "
      "phi = F(q_K), where n = grad F / |grad F| (0 where grad F = 0). K projections give order 2(K+1) = {}{}.{}",
      k, k == 1 ? "" : "s", f.order,
      requested != f.order
          ? fmt::format(" (order {} was asked for; odd orders round up to the next even one)", requested)
          : "",
      taylor_last_step
          ? " F(q_K) is taken as F's second-order Taylor polynomial at q_(K-1), evaluated at q_K (q_K - q_(K-1) = "
            "O(h^(K+1)): the remainder is of the method's own order, and q_K needs no trig of its own)."
          : "");
  f.citation = "offsetgen, docs/projection.md (foot-point projection).";
  f.accuracy = fmt::format(
      "the zero set of _offset lies within O(h^{}) of the exact offset surface, so the relative thickness "
      "error falls as (h/L)^{}.",
      f.order + 1, f.order);
  f.variable_thickness = fmt::format(
      "the _graded function (--thickness) reads the half thickness at each foot-point estimate and updates it "
      "at every projection: each wall converges at order {} = K + 1 to the distance t(p0)/2 from its foot point "
      "p0, and the total wall thickness at order {}. Passing a local t(p) to _shell reads it at p instead: "
      "second order at best.",
      f.graded_wall_order, f.graded_order);
  f.safety = fmt::format(
      "no clamp is needed. |q_K - p| = |h| exactly, so |F(q_K) - F(p)| <= M |h| with M = {:.17g} >= max |grad "
      "F| over the cell (2*pi/L scaled coordinates, h in them too){}: phi has the sign of F wherever |F| > M |h|, "
      "so no phantom walls appear. n := 0 where grad F = 0, so every function returns a finite value for finite "
      "input (do not compile with -ffinite-math-only).{}",
      b.gradient,
      taylor_last_step ? ", and phi, the Taylor value, is kept within F(p) -+ M |h|, the interval that holds F(q_K) "
                         "(so this never moves it away from F(q_K))"
                       : ", and phi = F(q_K)",
      angle_addition
          ? fmt::format(" sin and cos at the foot-point estimates come from their values at p by angle addition, "
                        "which is exact while |h| <= {:g} (natural units: |h| <= {:.3g} cell on a 2*pi-periodic "
                        "surface, walls up to {:.3g} cell thick); a larger |h| is clamped to {:g}, so thicker walls "
                        "stop growing there, and |q_K - p| <= |h| keeps the bound above. n := 0 also where |grad "
                        "F|^2 <= 2^-126 (FLT_MIN), which keeps 1/|grad F|^2 finite in float.",
                        kSmallAngleMax, kSmallAngleMax / (2 * 3.14159265358979323846),
                        kSmallAngleMax / 3.14159265358979323846, kSmallAngleMax)
          : "");
  f.normal =
      "unit normal grad F/|grad F| at the last foot-point estimate q_K (on the zero set: the offset "
      "surface's normal); zero where grad F = 0.";
  f.metadata["projections"] = k;
  f.metadata["foot_point_trig"] = angle_addition ? "angle addition" : "direct";
  f.metadata["last_estimate"] = taylor_last_step ? "taylor" : "field";
  return f;
}

class Projection final : public OffsetConstruction {
 public:
  Projection(const Surface& surface, int requested_order)
      : projections_(projections_for(requested_order)),
        angle_addition_(is_trigonometric_polynomial(surface.field)),
        taylor_last_step_(projections_ >= 1 && angle_addition_ && surface.scale.is_equal(2 * GiNaC::Pi)) {
    field_ = define_field_atoms(surface, 2, atoms_);  // second derivatives for the cell bounds
    bounds_ = cell_bounds(surface, atoms_, field_);
    facts_ = describe(requested_order, projections_, bounds_, angle_addition_, taylor_last_step_);
    add_lipschitz_bounds(surface);
  }

  const MethodFacts& facts() const override { return facts_; }
  const AtomTable& atoms() const override { return atoms_; }
  const FieldAtoms& field() const override { return field_; }
  const CellBounds& bounds() const override { return bounds_; }

  NodeId lower_offset(FieldLowering& at, NodeId h) const override {
    return value_at_foot_point(at, [h](const std::vector<NodeId>&) { return h; });
  }

  std::vector<NodeId> lower_normal(FieldLowering& at, NodeId h) const override {
    return unit(at.program(), at.gradient(foot_point(at, [h](const std::vector<NodeId>&) { return h; })));
  }

  NodeId lower_graded_offset(FieldLowering& at, const LoweredHalfThickness& h) const override {
    return value_at_foot_point(at, h);
  }

  GiNaC::numeric offset(FieldReference& at, const GiNaC::numeric& h) const override {
    return value_at_foot_point(at, [&h](const FieldReference::Point&) { return h; });
  }

  std::vector<GiNaC::numeric> normal(FieldReference& at, const GiNaC::numeric& h) const override {
    auto scope = at.at(foot_point(at, [&h](const FieldReference::Point&) { return h; }));
    return unit(at.gradient(scope));
  }

  GiNaC::numeric graded_offset(FieldReference& at, const ReferenceHalfThickness& h) const override {
    return value_at_foot_point(at, h);
  }

 private:
  // grad F / |grad F|, or 0 where grad F = 0 (also where |grad F|^2 is NaN: comparisons are false).
  static std::vector<NodeId> unit(Program& program, const std::vector<NodeId>& g) {
    std::vector<NodeId> squares;
    for (NodeId c : g) squares.push_back(program.mul(c, c));
    NodeId length2 = program.sum(squares);
    NodeId zero = program.constant(0);
    NodeId inverse =
        program.select(program.greater(length2, zero), program.div(program.constant(1), program.sqrt(length2)), zero);
    std::vector<NodeId> n;
    for (NodeId c : g) n.push_back(program.mul(c, inverse));
    return n;
  }

  static std::vector<GiNaC::numeric> unit(std::vector<GiNaC::numeric> g, const GiNaC::numeric& tiny = 0) {
    GiNaC::numeric length2 = 0;
    for (const auto& c : g) length2 += c * c;
    if (!(length2 > tiny)) return std::vector<GiNaC::numeric>(g.size(), 0);
    const GiNaC::numeric inverse = 1 / numeric_of(GiNaC::sqrt(length2));
    for (auto& c : g) c *= inverse;
    return g;
  }

  // One foot-point estimate q_j = p - d, reached with the (clamped) half thickness `step`.
  struct Estimate {
    const Environment* env;
    std::vector<NodeId> d;
    NodeId step;
  };
  struct ReferenceEstimate {
    FieldReference::Point q;
    GiNaC::numeric step;
  };

  // phi = F(q_K). For K >= 1 on periodic trig polynomials (taylor_last_step_), through F, grad F and
  // Hess F at q_(K-1), with delta = q_K - q_(K-1):
  //   T = F + grad F . delta + delta^T (Hess F) delta / 2,
  // all from the trig at q_(K-1), which grad F there needs anyway. T is kept within F(p) -+ M |h_K|,
  // the interval that holds F(q_K) exactly, so keeping it there never moves it away from F(q_K).
  // Near the walls delta is small and the interval is never reached; far from them, where n turns
  // fast, delta is not small, and the interval is what keeps phi's sign that of F.
  NodeId value_at_foot_point(FieldLowering& at, const LoweredHalfThickness& h) const {
    std::vector<Estimate> walk;
    const Environment& last_env = foot_point(at, h, &walk);
    if (!taylor_last_step_) return at.field(last_env);
    Program& program = at.program();
    const Estimate& last = walk[walk.size() - 1];
    const Estimate& before = walk[walk.size() - 2];
    const std::vector<NodeId> g = at.gradient(*before.env);
    std::vector<NodeId> delta;  // q_K - q_(K-1) = d_(K-1) - d_K
    for (size_t i = 0; i < g.size(); ++i) delta.push_back(program.sub(before.d[i], last.d[i]));
    std::vector<NodeId> terms = {at.field(*before.env)};
    for (size_t i = 0; i < delta.size(); ++i) {
      // delta_i (g_i + H_ii delta_i / 2 + sum_(j > i) H_ij delta_j)
      std::vector<NodeId> row = {g[i], program.mul(program.constant(0.5),
                                                   program.mul(hessian(at, *before.env, i, i), delta[i]))};
      for (size_t j = i + 1; j < delta.size(); ++j)
        row.push_back(program.mul(hessian(at, *before.env, i, j), delta[j]));
      terms.push_back(program.mul(delta[i], program.sum(row)));
    }
    const NodeId taylor = program.sum(terms);
    const NodeId f_p = at.field(at.base());
    const NodeId reach = program.mul(program.constant(bounds_.gradient), program.abs(last.step));
    const NodeId low = program.sub(f_p, reach), high = program.add(f_p, reach);
    return program.select(program.less_eq(taylor, high), program.select(program.less_eq(low, taylor), taylor, low),
                          high);
  }

  GiNaC::numeric value_at_foot_point(FieldReference& at, const ReferenceHalfThickness& h) const {
    const std::vector<ReferenceEstimate> walk = foot_point_walk(at, h);
    if (!taylor_last_step_) {
      auto scope = at.at(walk.back().q);
      return at.field(scope);
    }
    const ReferenceEstimate& last = walk[walk.size() - 1];
    const ReferenceEstimate& before = walk[walk.size() - 2];
    auto scope = at.at(before.q);
    const auto g = at.gradient(scope);
    GiNaC::numeric taylor = at.field(scope);
    for (size_t i = 0; i < g.size(); ++i) {
      GiNaC::numeric row = g[i] + GiNaC::numeric(1, 2) * hessian(at, scope, i, i) * (last.q[i] - before.q[i]);
      for (size_t j = i + 1; j < g.size(); ++j) row += hessian(at, scope, i, j) * (last.q[j] - before.q[j]);
      taylor += (last.q[i] - before.q[i]) * row;
    }
    const GiNaC::numeric f_p = at.field(at.base());
    const GiNaC::numeric reach = GiNaC::numeric(bounds_.gradient) * GiNaC::abs(last.step);
    if (taylor > f_p + reach) return f_p + reach;
    if (taylor < f_p - reach) return f_p - reach;
    return taylor;
  }

  NodeId hessian(FieldLowering& at, const Environment& env, size_t i, size_t j) const {
    return at.lower(field_.hessian(static_cast<int>(i), static_cast<int>(j)), env);
  }
  GiNaC::numeric hessian(FieldReference& at, FieldReference::Scope& scope, size_t i, size_t j) const {
    return at.eval(field_.hessian(static_cast<int>(i), static_cast<int>(j)), scope);
  }

  // The environment of q_K, with the half thickness read at p first and at each foot-point estimate
  // after; `walk` (optional) receives q_0 .. q_K. With angle addition the displacement d = h n is
  // clamped to |d_i| <= kSmallAngleMax.
  const Environment& foot_point(FieldLowering& at, const LoweredHalfThickness& h,
                                std::vector<Estimate>* walk = nullptr) const {
    Program& program = at.program();
    at.use_angle_addition(angle_addition_);
    const Environment* estimate = &at.base();
    std::vector<NodeId> point = at.point();
    static_assert(kSmallAngleMax == 1.0, "the clamp below compares h with 1");
    for (int j = 0; j <= projections_; ++j) {
      const std::vector<NodeId> g = at.gradient(*estimate);
      NodeId step = h(point);
      if (!angle_addition_) {
        std::vector<NodeId> d;
        for (NodeId n_i : unit(program, g)) d.push_back(program.mul(step, n_i));
        const auto q = at.displaced(d);
        estimate = q.env;
        point = q.point;
        if (walk) walk->push_back({estimate, d, step});
        continue;
      }
      // |d_i| <= |h| with d = h n, so clamping h to [-1, 1] once keeps every d_i within the
      // small-angle polynomials' range; NaN maps to 1, which keeps F(q) finite.
      NodeId zero = program.constant(0), one = program.constant(1), minus_one = program.constant(-1);
      step = program.select(program.less_eq(step, one),
                            program.select(program.less_eq(minus_one, step), step, minus_one), one);
      // d_i = g_i (h / |g|) and d_i^2 = g_i^2 (h^2 / |g|^2): the polynomials start from d^2, which
      // needs the division but no square root, and 1/|g| = sqrt(|g|^2) / |g|^2 runs the square root
      // beside the division instead of after it. Below FLT_MIN, |g|^2 counts as zero (n = 0), which
      // keeps 1/|g|^2 finite in float and double alike.
      std::vector<NodeId> squares;
      for (NodeId c : g) squares.push_back(program.mul(c, c));
      NodeId length2 = program.sum(squares);
      NodeId w = program.select(program.greater(length2, program.constant(kTinyLength2)),
                                program.div(one, length2), zero);
      NodeId h_inverse = program.mul(step, program.mul(program.sqrt(length2), w));
      NodeId step2 = program.mul(step, step);
      std::vector<NodeId> d, d2;
      for (size_t i = 0; i < g.size(); ++i) {
        d.push_back(program.mul(g[i], h_inverse));
        d2.push_back(program.mul(program.mul(squares[i], step2), w));
      }
      const auto q = at.displaced(d, d2);
      estimate = q.env;
      point = q.point;
      if (walk) walk->push_back({estimate, d, step});
    }
    return *estimate;
  }

  std::vector<GiNaC::numeric> foot_point(FieldReference& at, const ReferenceHalfThickness& h) const {
    return foot_point_walk(at, h).back().q;
  }

  // q_0 .. q_K, each with the (clamped) half thickness that reached it.
  std::vector<ReferenceEstimate> foot_point_walk(FieldReference& at, const ReferenceHalfThickness& h) const {
    const auto& p = at.point();
    const GiNaC::numeric limit(kSmallAngleMax);
    std::vector<ReferenceEstimate> walk;
    std::vector<GiNaC::numeric> estimate = p;
    for (int j = 0; j <= projections_; ++j) {
      auto scope = at.at(estimate);
      const auto n = unit(at.gradient(scope), angle_addition_ ? GiNaC::numeric(kTinyLength2) : GiNaC::numeric(0));
      GiNaC::numeric step = h(estimate);
      // The same clamp as the lowering: |h| <= 1, so every |d_i| <= 1.
      if (angle_addition_ && step > limit) step = limit;
      if (angle_addition_ && step < -limit) step = -limit;
      std::vector<GiNaC::numeric> next;
      for (size_t i = 0; i < p.size(); ++i) next.push_back(p[i] - step * n[i]);
      estimate = std::move(next);
      walk.push_back({estimate, step});
    }
    return walk;
  }

  // In the band |F(p)| <= M|h| that holds the zero set, the estimates q_j lie within |h| of p, so
  // |F(q_j)| <= 2M|h|. With g <= |grad F| there, |Dn| <= H/g and |D q_K| <= 1/(1 - |h| H/g), so
  // |grad phi| <= M/(1 - |h| H/g). Outside the band phi has F's sign and |phi| >= |F| - M|h|.
  void add_lipschitz_bounds(const Surface& surface) {
    const double k = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(surface.scale)).to_double();
    const auto& hs = kLipschitzHalfThicknesses;
    const std::vector<double> g = lipschitz_band_minima(surface, atoms_, field_, bounds_);
    std::string table;
    nlohmann::ordered_json json = nlohmann::ordered_json::array();
    for (size_t i = 0; i < hs.size(); ++i) {
      const double r = k * hs[i] * bounds_.hessian / g[i];
      const double bound = g[i] > 0 && r < 1 ? k * bounds_.gradient / (1 - r) * (1 + 1e-9) : 0;
      facts_.lipschitz_bounds.push_back({hs[i], bound});
      table +=
          fmt::format("{}|h| <= {:g}: {}", i ? "; " : "", hs[i], bound > 0 ? fmt::format("{:.4g}", bound) : "none");
      json.push_back({{"h", hs[i]}, {"bound", bound > 0 ? nlohmann::ordered_json(bound) : nlohmann::ordered_json()}});
    }
    facts_.lipschitz = fmt::format(
        "away from the walls, wherever |F(p)| > M |h|, phi has the sign of F and the zero set is at least "
        "(|F(p)| - M |h|) / (k M) cell away (M as below, k = {:.17g} the scale of X = k x). Inside that band "
        "|grad phi| <= k M / (1 - |h| H / g), g the least |grad F| where |F| <= 2 M |h| (H = {:.6g} >= max ||Hess "
        "F||); in cell units: {} (none: the band may hold a critical point of F). `offsetgen check` measures it.",
        k, bounds_.hessian, table);
    facts_.metadata["lipschitz"] = json;
  }

  int projections_;
  bool angle_addition_;  // trig at the foot-point estimates from trig at p (catalog-like fields)
  // phi from F's Taylor polynomial at q_(K-1) (value_at_foot_point). Only where M bounds |grad F|
  // everywhere, not just in the cell: trig polynomials of period 1 cell.
  bool taylor_last_step_;
  AtomTable atoms_;
  FieldAtoms field_;
  CellBounds bounds_;
  MethodFacts facts_;
};

class ProjectionMethod final : public OffsetMethod {
 public:
  std::string name() const override { return kMethodName; }
  std::string description() const override {
    return "foot-point projection: F at the estimated foot point, order 2(K+1) from K projections (orders 2-16, "
           "odd orders round up)";
  }
  int max_order() const override { return kMethodMaxOrder; }
  int effective_order(int requested) const override { return 2 * (projections_for(requested) + 1); }
  std::unique_ptr<OffsetConstruction> build(const Surface& surface, int order) const override {
    return std::make_unique<Projection>(surface, order);
  }
};

}  // namespace

const OffsetMethod& projection_method() {
  static const ProjectionMethod method;
  return method;
}

}  // namespace offsetgen
