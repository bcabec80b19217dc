// The emitted functions (field, offset, shell, normal, graded) as straight-line programs in cell
// coordinates, lowered from an offset construction. Every target is printed from these same
// programs, so the targets cannot drift apart.
#pragma once

#include "lowering/program.h"
#include "offset/method.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <optional>

namespace offsetgen {

struct SurfacePrograms {
  Program field;                  // F(x)                       inputs x, y[, z]
  Program offset;                 // phi(x, h)                  inputs x, y[, z], h
  Program shell;                  // phi(x, t/2) * phi(x, -t/2) inputs x, y[, z], t
  Program normal;                 // unit normal of the offset  inputs x, y[, z], h; outputs n0, n1[, n2]
  std::optional<Program> graded;  // the shell of the wall t = thickness(.)   inputs x, y[, z]
  std::optional<Program> wall;    // the shell at a fixed thickness           inputs x, y[, z]
};

struct LoweringOptions {
  std::optional<GiNaC::ex> thickness;    // t(x, y, z) in cell units, for `graded`
  std::optional<double> wall_thickness;  // total thickness in cell units, for `wall` (--density)
};

// Cell units outside, natural units (X = k x, h k) inside the construction.
SurfacePrograms lower_surface(const Surface& surface, const OffsetConstruction& construction,
                              const LoweringOptions& options);

// One wall of a graded shell as a program of (x, y[, z], s): the method's graded offset with the
// half thickness h(q) = s t(q) / 2 wherever the method reads it (s = +-lambda). `check` sweeps s to
// measure the graded walls' convergence with the construction the emitted _graded comes from.
Program lower_graded_wall(const Surface& surface, const OffsetConstruction& construction, const GiNaC::ex& thickness);

// The wall thickness t(x, y[, z]) itself (cell units in and out), for a mesher that reads the local
// thickness at each sample.
Program lower_thickness(const Surface& surface, const OffsetConstruction& construction, const GiNaC::ex& thickness);

}  // namespace offsetgen
