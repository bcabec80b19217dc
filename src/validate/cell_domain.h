// Numeric checks over the unit cell, before any offset is built: F and its gradient must be real
// and finite there (isolated poles aside), and a graded wall's thickness must be positive.
#pragma once

#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <string>

namespace offsetgen {

// Throws InputError when F or grad F is NaN at a sample of the cell [0,1]^d (log or sqrt of a
// negative number, asin beyond [-1, 1], a negative base to a varying power, inf - inf ...), naming
// the point and the operation; or when F is not finite at any sample.
void require_defined_on_cell(const Surface& surface);

// Throws InputError when the thickness t(x) (cell units) is not a finite positive number at every
// sample of the cell, naming the point and the value. `text` is t as the user wrote it.
void require_positive_thickness(const GiNaC::ex& thickness, int dims, const std::string& text);

}  // namespace offsetgen
