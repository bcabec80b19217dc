#include "offset/offset_model.h"

#include "field/multi_index.h"
#include "offset/richardson.h"

#include <fmt/format.h>

#include <map>
#include <stdexcept>

namespace offsetgen {
namespace {

using Jet = std::map<MultiIndex, GiNaC::ex>;

class ChainBuilder {
 public:
  ChainBuilder(const FieldAtoms& field, int depth, AtomTable& atoms) : dims_(field.dims), depth_(depth), atoms_(atoms) {
    derivatives_.push_back(field.jet);  // P_0 = D^alpha F
  }

  // |grad psi_k| and its derivatives up to the order the chain still needs at level k.
  const Jet& norms(int level) {
    while (static_cast<int>(norms_.size()) <= level) extend();
    return norms_[static_cast<size_t>(level)];
  }
  const Jet& derivatives(int level) {
    while (static_cast<int>(derivatives_.size()) <= level) extend();
    return derivatives_[static_cast<size_t>(level)];
  }

 private:
  void extend() {
    const int level = static_cast<int>(norms_.size());
    const int order = depth_ - level - 1;  // N_k needs one order less than P_k
    if (order < 0) throw std::logic_error("offset chain asked beyond its derivative depth");
    const Jet& p = derivatives_[static_cast<size_t>(level)];
    const auto indices = indices_up_to(dims_, order);

    // u[0] = |grad psi_k|^2; for a != 0, u[a] holds HALF of D^a |grad psi_k|^2, so the factor 2 of
    // the symmetric Leibniz pairs and the 1/2 of the sqrt recurrence cancel symbolically.
    Jet u;
    for (const auto& alpha : indices) {
      const bool root = total_order(alpha) == 0;
      GiNaC::ex sum = 0;
      for (int i = 0; i < dims_; ++i) {
        MultiIndex e = unit_index(i);
        for (const auto& beta : sub_indices(alpha)) {
          sum += multi_binomial(alpha, beta) * p.at(beta + e) * p.at(alpha - beta + e);
        }
      }
      u[alpha] = atoms_.define(fmt::format("U{}_{}", level, index_label(alpha)),
                               root ? sum : GiNaC::numeric(1, 2) * sum, level);
    }

    // N*N = U gives D^a N = (D^a U / 2 - 1/2 sum_{0<b<a} C(a,b) D^b N D^(a-b) N) / N.
    Jet n;
    const MultiIndex zero{0, 0, 0};
    n[zero] = atoms_.define(fmt::format("N{}", level), GiNaC::sqrt(u[zero]), level);
    GiNaC::ex reciprocal = GiNaC::pow(u[zero], GiNaC::numeric(-1, 2));
    for (const auto& alpha : indices) {
      if (total_order(alpha) == 0) continue;
      GiNaC::ex products = 0;
      for (const auto& beta : sub_indices(alpha)) {
        if (total_order(beta) == 0 || beta == alpha) continue;
        products += multi_binomial(alpha, beta) * n.at(beta) * n.at(alpha - beta);
      }
      n[alpha] = atoms_.define(fmt::format("N{}_{}", level, index_label(alpha)),
                               reciprocal * (u[alpha] - GiNaC::numeric(1, 2) * products), level);
    }
    norms_.push_back(n);

    if (order >= 1) {  // the next level needs derivatives of psi_{k+1} up to `order`
      const GiNaC::symbol& s = Symbols::get().s;
      Jet next;
      for (const auto& alpha : indices) {
        next[alpha] = atoms_.define(fmt::format("P{}_{}", level + 1, index_label(alpha)), p.at(alpha) - s * n.at(alpha),
                                    level + 1);
      }
      derivatives_.push_back(std::move(next));
    }
  }

  int dims_;
  int depth_;
  AtomTable& atoms_;
  std::vector<Jet> derivatives_;  // P_k
  std::vector<Jet> norms_;        // N_k
};

}  // namespace

OffsetModel build_offset_model(const Surface& surface, int order, bool with_gradient) {
  if (order < 1) throw std::invalid_argument("offset order must be >= 1");
  OffsetModel model;
  model.order = order;
  model.dims = surface.dims;
  model.field = surface.field;
  const int depth = order + (with_gradient ? 1 : 0);
  model.field_atoms = define_field_atoms(surface, depth, model.atoms);
  ChainBuilder chains(model.field_atoms, depth, model.atoms);

  for (int i = 0; i < surface.dims; ++i) model.field_gradient.push_back(chains.derivatives(0).at(unit_index(i)));
  model.field_gradient_norm = chains.norms(0).at({0, 0, 0});
  if (with_gradient)
    for (int i = 0; i < surface.dims; ++i)
      model.field_gradient_norm_gradient.push_back(chains.norms(0).at(unit_index(i)));
  if (depth >= 2) {
    model.field_hessian.assign(static_cast<size_t>(surface.dims), {});
    for (int i = 0; i < surface.dims; ++i)
      for (int j = 0; j < surface.dims; ++j)
        model.field_hessian[static_cast<size_t>(i)].push_back(chains.derivatives(0).at(unit_index(i) + unit_index(j)));
  }

  const auto weights = richardson_weights(order);
  auto add_terms = [&](const MultiIndex& alpha, ChainSum& sum) {
    if (order == 1) {
      sum.push_back({1, 1, chains.norms(0).at(alpha)});
      return;
    }
    for (int j = 2; j <= order; ++j) {
      GiNaC::numeric coeff = weights[static_cast<size_t>(j - 1)] / j;
      for (int k = 1; k < j; ++k) sum.push_back({coeff, j, chains.norms(k).at(alpha)});
    }
  };
  add_terms({0, 0, 0}, model.weighted_norms);
  if (with_gradient) {
    model.weighted_norms_gradient.resize(static_cast<size_t>(surface.dims));
    for (int i = 0; i < surface.dims; ++i)
      add_terms(unit_index(i), model.weighted_norms_gradient[static_cast<size_t>(i)]);
  }
  return model;
}

}  // namespace offsetgen
