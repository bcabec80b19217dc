// A point in space, x, y, z: in millimetres or in cell units, as the code using it says. The one Point
// of the project (an evaluation's input with its offset h is run::Sample).
#pragma once

#include <array>

namespace offsetgen {

using Point = std::array<double, 3>;

}  // namespace offsetgen
