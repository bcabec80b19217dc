// The error for bad user input, on its own so that stages without GiNaC (body files, meshing) can
// throw it. The CLI maps it to exit 2.
#pragma once

#include <stdexcept>

namespace offsetgen {

// Bad user input (unknown surface, unparsable expression, an open body, ...): the message names it.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace offsetgen
