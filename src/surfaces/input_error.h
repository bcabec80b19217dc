// The errors a user can act on, on their own so that stages without GiNaC (body files, meshing) can
// throw them: bad input (exit 2) and a run out of memory or disk (exit 3).
#pragma once

#include <stdexcept>

namespace offsetgen {

// Bad user input (unknown surface, unparsable expression, an open body, ...): the message names it.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run that ran out of memory or disk: not the user's input and not a bug. The message names the
// stage and how to need less; the CLI maps it to exit 3 and has removed any partial output.
class ResourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A result that failed its own check before it was kept (a part whose mesh is not closed): not the
// user's input; the CLI maps it to exit 3, and the output was not written.
class UnsoundPartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace offsetgen
