// Multi-indices alpha = (a_x, a_y, a_z) naming partial derivatives D^alpha.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace offsetgen {

using MultiIndex = std::array<int, 3>;

inline int total_order(const MultiIndex& a) { return a[0] + a[1] + a[2]; }

inline MultiIndex unit_index(int axis) {
  MultiIndex e{0, 0, 0};
  e[static_cast<size_t>(axis)] = 1;
  return e;
}

inline MultiIndex operator+(MultiIndex a, const MultiIndex& b) {
  for (size_t i = 0; i < 3; ++i) a[i] += b[i];
  return a;
}

inline MultiIndex operator-(MultiIndex a, const MultiIndex& b) {
  for (size_t i = 0; i < 3; ++i) a[i] -= b[i];
  return a;
}

// Every beta <= alpha componentwise, alpha itself included.
std::vector<MultiIndex> sub_indices(const MultiIndex& alpha);

// All indices of total order <= max_order in `dims` dimensions, lowest order first.
std::vector<MultiIndex> indices_up_to(int dims, int max_order);

// prod_i C(alpha_i, beta_i)
long multi_binomial(const MultiIndex& alpha, const MultiIndex& beta);

// "xxy" style label for atom names; "" for the zero index.
std::string index_label(const MultiIndex& alpha);

}  // namespace offsetgen
