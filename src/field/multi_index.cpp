#include "field/multi_index.h"

namespace offsetgen {

std::vector<MultiIndex> sub_indices(const MultiIndex& alpha) {
  std::vector<MultiIndex> result;
  for (int a = 0; a <= alpha[0]; ++a)
    for (int b = 0; b <= alpha[1]; ++b)
      for (int c = 0; c <= alpha[2]; ++c) result.push_back({a, b, c});
  return result;
}

std::vector<MultiIndex> indices_up_to(int dims, int max_order) {
  std::vector<MultiIndex> result;
  for (int order = 0; order <= max_order; ++order)
    for (int a = order; a >= 0; --a)
      for (int b = order - a; b >= 0; --b) {
        int c = order - a - b;
        if (dims == 2 && c != 0) continue;
        result.push_back({a, b, c});
      }
  return result;
}

long multi_binomial(const MultiIndex& alpha, const MultiIndex& beta) {
  long result = 1;
  for (size_t i = 0; i < 3; ++i) {
    long c = 1;
    for (int k = 1; k <= beta[i]; ++k) c = c * (alpha[i] - beta[i] + k) / k;
    result *= c;
  }
  return result;
}

std::string index_label(const MultiIndex& alpha) {
  std::string label;
  const char axes[3] = {'x', 'y', 'z'};
  for (size_t i = 0; i < 3; ++i) label.append(static_cast<size_t>(alpha[i]), axes[i]);
  return label;
}

}  // namespace offsetgen
