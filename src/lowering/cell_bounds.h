// Bounds of the field's derivatives over one cell [0,1]^d (natural units), found numerically at
// generation time: grid search, then compass refinement, with a relative margin.
#pragma once

#include "offset/atom_table.h"
#include "offset/field_atoms.h"
#include "offset/method.h"
#include "surfaces/surface.h"

namespace offsetgen {

// M >= max |grad F| and, when `field` has second derivatives, H >= max ||Hess F||_2 (else 0).
CellBounds cell_bounds(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);

double max_gradient_norm(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);
double max_hessian_norm(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);

}  // namespace offsetgen
