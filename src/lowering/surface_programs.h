// The emitted functions (field, offset, shell, normal, graded) as straight-line programs in cell
// coordinates. C and GLSL are printed from these same programs, so the two cannot drift.
#pragma once

#include "lowering/program.h"
#include "offset/offset_model.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <optional>

namespace offsetgen {

struct SurfacePrograms {
  Program field;    // F(x)                       inputs x, y[, z]
  Program offset;   // phi^(m)(x, h)              inputs x, y[, z], h
  Program shell;    // phi(x, t/2) * phi(x, -t/2) inputs x, y[, z], t
  Program normal;   // unit normal of the offset  inputs x, y[, z], h; outputs n0, n1[, n2]
  std::optional<Program> graded;  // shell with t = thickness(x)   inputs x, y[, z]
  double gradient_bound = 0;      // M >= max |grad F| over the cell, natural units (see safeguard)
  double hessian_bound = 0;       // H >= max ||Hess F||_2 over the cell; 0 at order 1 (unused there)
};

struct LoweringOptions {
  std::optional<GiNaC::ex> thickness;  // t(x, y, z) in cell units, for `graded`
};

// The safeguard: phi = F - h * clamp(G, lo, hi) (SafeguardBounds in offset/offset_model.h). On the
// true offset surface G = F/h lies inside [lo, hi], so the clamp never moves a zero set; but wherever
// |F| > |h| M the sign of phi is the sign of F whatever G is, zero sets stay within O(H h^2) of the
// first-order offset, and G = NaN or inf (vanishing gradient) maps to a finite value. This rules
// out NaN and phantom walls at once.
SurfacePrograms lower_surface(const Surface& surface, const OffsetModel& model, const LoweringOptions& options);

// max |grad F| and max ||Hess F||_2 over one cell [0,1]^d (natural units), with a relative margin:
// grid search, then compass refinement. max_hessian_norm is 0 when the model has no Hessian.
double max_gradient_norm(const Surface& surface, const OffsetModel& model);
double max_hessian_norm(const Surface& surface, const OffsetModel& model);

}  // namespace offsetgen
