// Bounds of the field's derivatives over one cell [0,1]^d (natural units), found numerically at
// generation time: grid search, then compass refinement, with a relative margin.
#pragma once

#include "field/atom_table.h"
#include "field/field_atoms.h"
#include "surfaces/surface.h"

#include <array>
#include <vector>

namespace offsetgen {

// Bounds over one cell [0,1]^d in natural units: M >= max |grad F|, H >= max ||Hess F||_2.
struct CellBounds {
  double gradient = 0;
  double hessian = 0;
};

// M >= max |grad F| and, when `field` has second derivatives, H >= max ||Hess F||_2 (else 0). An
// unmapped catalog surface's come from its table (catalog_sweeps.h), every other surface is swept.
CellBounds cell_bounds(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);
// The same by the sweep, whatever the surface: what the catalog table is made of.
CellBounds swept_cell_bounds(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);

double max_gradient_norm(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);
double max_hessian_norm(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field);

// Lower bounds of |grad F| over the level-set bands {q : |F(q)| <= levels[i]} of one cell (natural
// units), one per level; 0 where the band may hold a critical point of F. Rigorous given M and H:
// within r of a point c, |F| and |grad F| differ from their values at c by at most M r and H r.
std::vector<double> min_gradient_in_bands(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field,
                                          const CellBounds& bounds, const std::vector<double>& levels);

// The half thicknesses (cell units) at which projection states a Lipschitz bound: walls of 0.01 to
// 0.1 cell. Its bands are |F| <= 2 M k h (natural units, k the surface's scale).
inline constexpr std::array<double, 4> kLipschitzHalfThicknesses = {0.005, 0.01, 0.025, 0.05};
std::vector<double> lipschitz_band_levels(const CellBounds& bounds, double scale);

// min_gradient_in_bands at lipschitz_band_levels(bounds, k): from the catalog table where it holds
// the surface with these bounds, else by the search.
std::vector<double> lipschitz_band_minima(const Surface& surface, const AtomTable& atoms, const FieldAtoms& field,
                                          const CellBounds& bounds);

}  // namespace offsetgen
