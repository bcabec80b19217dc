// Every constant of the emitted code must be printable as a finite literal of each requested
// precision: `inf` or `inff` would not compile, and a constant beyond the type's range means the
// functions cannot be evaluated in that type anyway.
#pragma once

#include "offset/method.h"
#include "offset/surface_programs.h"

namespace offsetgen {

// Throws InputError naming the function and the constant when a constant is not finite in double,
// or beyond the float range when `need_float` (--precision float, or GLSL).
void require_representable_constants(const SurfacePrograms& programs, const OffsetConstruction& construction, int dims,
                                     bool need_float);

}  // namespace offsetgen
