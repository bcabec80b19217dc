// The paper's construction (Geier & Alihussein 2021), for tests that need it with chosen bounds.
#pragma once

#include "offset/method.h"

#include <memory>
#include <optional>

namespace offsetgen {

const OffsetMethod& richardson_method();

// `bounds` replaces the computed safeguard bounds; CellBounds{} (M = 0) gives the raw formulas.
std::unique_ptr<OffsetConstruction> build_richardson(const Surface& surface, int order,
                                                     std::optional<CellBounds> bounds = std::nullopt);

}  // namespace offsetgen
