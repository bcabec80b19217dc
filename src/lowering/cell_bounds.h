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

// Lower bounds of |grad F| over the level-set bands {q : |F(q)| <= levels[i]} of one cell (natural
// units), one per level; 0 where the band may hold a critical point of F. Rigorous given M and H:
// within r of a point c, |F| and |grad F| differ from their values at c by at most M r and H r.
std::vector<double> min_gradient_in_bands(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field,
                                          const CellBounds& bounds, const std::vector<double>& levels);

}  // namespace offsetgen
