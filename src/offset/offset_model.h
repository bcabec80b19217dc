// The offset function phi^(m) of a surface, as symbolic definitions (paper sections 2-3).
#pragma once

#include "offset/atom_table.h"
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
  GiNaC::ex field;                          // F
  std::vector<GiNaC::ex> field_gradient;    // dF/dX_i
  ChainSum weighted_norms;                  // G
  std::vector<ChainSum> weighted_norms_gradient;  // dG/dX_i, only when built with_gradient
  AtomTable atoms;
};

// Builds the chains with jets: for psi_k the partial derivatives P_k[a], U_k[a] = D^a |grad psi_k|^2
// (Leibniz) and N_k[a] = D^a |grad psi_k| from N*N = U, so N_k[a] = (U_k[a]/2 - 1/2 sum C(a,b) N_k[b]
// N_k[a-b]) / N_k[0]; then P_{k+1}[a] = P_k[a] - s N_k[a]. Mathematically identical to nested
// differentiation of the chain, with work polynomial in the order instead of exponential.
OffsetModel build_offset_model(const Surface& surface, int order, bool with_gradient);

}  // namespace offsetgen
