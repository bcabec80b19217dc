// Extended Richardson weights (paper eq. 10), exact for any order.
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace offsetgen {

// w_1..w_m (index j-1) solving sum_j w_j = 1 and sum_j w_j / j^i = 0 for i = 1..m-1.
// Closed form w_j = (-1)^(m-j) j^(m-1) / ((j-1)! (m-j)!), in CLN rationals.
std::vector<GiNaC::numeric> richardson_weights(int order);

}  // namespace offsetgen
