// Every check a generation request passes, in two steps around the expensive build, so that bad
// input is refused with a clear message (exit 2) before work is spent, and no output that would not
// compile is ever produced. The pipeline driver calls these two functions; each check lives in its
// own file of this folder.
#pragma once

#include "emit/backend.h"
#include "offset/method.h"
#include "offset/surface_programs.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <functional>
#include <optional>
#include <string>

namespace offsetgen {

struct RequestFacts {
  const Surface* surface = nullptr;
  std::string prefix;
  int order = 1;
  // The offset method: where its cost grows geometrically with the order (Richardson: ~5x per
  // order; OffsetMethod::cost_grows_geometrically), a high order's cost is extrapolated from its own
  // orders 1-2 before the build.
  const OffsetMethod* method = nullptr;
  std::vector<const Backend*> languages;                // the requested targets
  bool float_precision = false;                         // some requested file holds float functions
  const std::optional<GiNaC::ex>* thickness = nullptr;  // parsed --thickness, if any
  std::string thickness_text;
  std::function<void(const std::string&)> notice;  // announces long runs; may be empty
};

// Names, size and nesting limits, F defined on the cell, thickness positive, estimated cost.
void check_before_build(const RequestFacts& facts);

// The built programs: op counts within the limit, every constant printable in each precision.
void check_after_build(const RequestFacts& facts, const OffsetConstruction& construction,
                       const SurfacePrograms& programs);

}  // namespace offsetgen
