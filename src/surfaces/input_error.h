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

// A tool that running generated code needs is not installed (no C compiler, no nvcc, no Dawn
// bindings): nothing is wrong with the input. `offsetgen check` then says "not checked" and exits 4;
// elsewhere (mesh's C compiler) it is an input error, exit 2. The message names the tool and how to get it.
class ToolMissing : public InputError {
 public:
  using InputError::InputError;
};

// A result that failed its own check before it was kept (a part whose mesh is not closed): not the
// user's input; the CLI maps it to exit 3, and the output was not written.
class UnsoundPartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace offsetgen
