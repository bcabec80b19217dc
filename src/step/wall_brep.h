// The wall of a block of Schwarz P cells as an OpenCASCADE solid: the two fitted symmetry patches
// (one per offset surface) copied by the 48 cell symmetries into every cell as untrimmed bicubic
// B-spline faces, planar caps where the block's faces cut the wall, sewn into one closed shell.
#pragma once

#include "step/bspline_fit.h"

#include <TopoDS_Shape.hxx>

#include <array>
#include <string>

namespace offsetgen::step {

struct WallBrep {
  TopoDS_Shape solid;  // one TopoDS_Solid
  int bspline_faces = 0, planar_faces = 0;
  long control_points = 0;  // over all B-spline faces
  double sewing_tolerance = 0;
  int free_edges = 0;  // after sewing: 0 for a closed shell
};

// `plus` and `minus` are the patches of the offset surfaces at +t/2 and -t/2 (cell units); the block
// spans [0, cells[a] * cell_size] in millimetres. Throws std::runtime_error if sewing leaves the shell
// open or the solid is not valid.
WallBrep build_schwarzp_wall(const CubicPatch& plus, const CubicPatch& minus, const std::array<int, 3>& cells,
                             double cell_size);

// Whether BRepCheck_Analyzer finds the shape valid, and the count of its solids and shells.
struct ShapeCheck {
  bool valid = false;
  int solids = 0, shells = 0, faces = 0;
  bool closed = false;  // every shell closed (BRep_Tool::IsClosed)
  double volume = 0;    // BRepGProp, mm^3
};
ShapeCheck check_shape(const TopoDS_Shape& shape);

}  // namespace offsetgen::step
