#include "offset/richardson.h"

#include <stdexcept>

namespace offsetgen {

std::vector<GiNaC::numeric> richardson_weights(int order) {
  if (order < 1) throw std::invalid_argument("Richardson order must be >= 1");
  std::vector<GiNaC::numeric> weights;
  weights.reserve(static_cast<size_t>(order));
  for (int j = 1; j <= order; ++j) {
    GiNaC::numeric sign = ((order - j) % 2 == 0) ? 1 : -1;
    const GiNaC::numeric nj(j);
    GiNaC::numeric w = sign * nj.power(order - 1) /
                       (GiNaC::factorial(GiNaC::numeric(j - 1)) * GiNaC::factorial(GiNaC::numeric(order - j)));
    weights.push_back(w);
  }
  return weights;
}

}  // namespace offsetgen
