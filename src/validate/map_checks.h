// A mapped surface (--map) must be regular where its walls are built: no singular point of the map
// in its domain (outside the clearance a body leaves), and one value on both sides of atan2's
// branch cut wherever the domain meets it.
#pragma once

#include "surfaces/surface.h"

namespace offsetgen {

// Throws InputError naming the point and the reason; does nothing for an unmapped surface.
void require_regular_map(const Surface& surface);

}  // namespace offsetgen
