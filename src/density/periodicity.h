// A symbolic proof that a field is periodic with period 1 in a cell coordinate: F(x + 1) = F(x)
// structurally, without sampling. sin and cos whose argument moves by a whole multiple of pi under
// x -> x + 1 flip or keep their sign; sums, products, powers and smooth functions of periodic parts
// are periodic; anything else (x itself outside such a function, sin(x) with period 2 pi) is not.
// The proof is sufficient, not necessary: a field periodic only through a cancellation it cannot
// see is refused, and the message names the part it could not prove.
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>

namespace offsetgen::density {

// nullopt when e(var + 1) = e(var) is proven; otherwise why not, naming the sub-expression.
std::optional<std::string> periodicity_problem(const GiNaC::ex& e, const GiNaC::symbol& var);

}  // namespace offsetgen::density
