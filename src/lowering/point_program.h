// One program of a point's coordinates for expressions that are evaluated at many points (the cell
// sweeps, the definedness and map checks), not emitted.
#pragma once

#include "field/atom_table.h"
#include "lowering/program.h"

#include <ginac/ginac.h>

#include <vector>

namespace offsetgen {

// Inputs x, y[, z]; outputs o0, o1, ...: `outputs`, expressions of `coordinates` (one symbol per input;
// empty: the natural coordinates), each bound to scale * input, with the atoms of `atoms` inlined.
Program point_program(int dims, const std::vector<GiNaC::ex>& outputs, const AtomTable& atoms,
                      const std::vector<GiNaC::ex>& coordinates = {}, double scale = 1);

}  // namespace offsetgen
