// The offset function phi^(m) of a surface, as symbolic definitions (paper sections 2-3).
#pragma once

#include "field/atom_table.h"
#include "field/field_atoms.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <vector>

namespace offsetgen {

// One term coeff * value, where `value` is evaluated with the step s = h / chain.
struct ChainTerm {
  GiNaC::numeric coeff;
  int chain = 1;
  GiNaC::ex value;
};
using ChainSum = std::vector<ChainTerm>;

// phi^(m)(X, h) = F(X) - h * G(X, h), the cancellation-free form of METHOD.md:
//   G = sum_j (w_j / j) sum_{k=0}^{j-1} |grad psi_k^(j)|, psi chains with step h/j,
// where for m >= 2 the k = 0 terms cancel exactly (sum_j w_j / j = 0) and are left out.
// Everything is in natural coordinates X = k x with h in natural units.
struct OffsetModel {
  int order = 1;
  int dims = 3;
  GiNaC::ex field;                                      // F
  std::vector<GiNaC::ex> field_gradient;                // dF/dX_i
  GiNaC::ex field_gradient_norm;                        // |grad F|, the chains' first norm (shared atom)
  std::vector<GiNaC::ex> field_gradient_norm_gradient;  // d|grad F|/dX_i, only when built with_gradient
  std::vector<std::vector<GiNaC::ex>> field_hessian;    // d2F/dX_i dX_j; empty at order 1 without gradient
  FieldAtoms field_atoms;                               // D^alpha F, |alpha| <= order (+1 with gradient)
  ChainSum weighted_norms;                              // G
  std::vector<ChainSum> weighted_norms_gradient;        // dG/dX_i, only when built with_gradient
  AtomTable atoms;
};

// The safeguard's bounds over one cell, natural units: M >= max |grad F| and H >= max ||Hess F||_2.
// phi = F - h * clamp(G, lo, hi) with
//   lo = max(|grad F| - kSafeguardBelow * H |h|, -M),  hi = min(|grad F| + kSafeguardAbove * H |h|, M).
// On the true offset surface, p = p0 + h n with F(p0) = 0, and
//   F(p)/h = integral_0^1 grad F(p0 + t h n) . n dt  lies in  [|grad F(p)| - 1.5 H|h|, |grad F(p)| + 0.5 H|h|],
// so neither limit moves a true zero set; elsewhere they keep phi's zero set next to the first-order
// offset F - h |grad F|, where high orders blow up (near critical points of F). At order 1 G is
// |grad F| itself and only the M clamp applies. H = 0 disables the interval (M alone).
struct SafeguardBounds {
  double gradient = 0;  // M; <= 0: no clamp at all (the raw formulas)
  double hessian = 0;   // H
};
inline constexpr double kSafeguardBelow = 1.5;
inline constexpr double kSafeguardAbove = 0.5;

// Builds the chains with jets: for psi_k the partial derivatives P_k[a], U_k[a] = D^a |grad psi_k|^2
// (Leibniz) and N_k[a] = D^a |grad psi_k| from N*N = U, so N_k[a] = (U_k[a]/2 - 1/2 sum C(a,b) N_k[b]
// N_k[a-b]) / N_k[0]; then P_{k+1}[a] = P_k[a] - s N_k[a]. Mathematically identical to nested
// differentiation of the chain, with work polynomial in the order instead of exponential.
OffsetModel build_offset_model(const Surface& surface, int order, bool with_gradient);

}  // namespace offsetgen
