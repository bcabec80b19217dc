// The wall of a block of cells as an OpenCASCADE solid: the two fitted symmetry patches (one per
// offset surface) copied by the layout's symmetries into every tetrahedron of its region as untrimmed
// bicubic B-spline faces, planar caps where the region's faces cut the wall, sewn into one closed
// shell; where the region is larger than the block, the block's box then cuts it (its faces across the
// box are split by it; the pieces of the box's faces inside the wall become caps).
#pragma once

#include "step/bspline_fit.h"
#include "step/symmetry_patch.h"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopoDS_Shape.hxx>

#include <array>
#include <functional>
#include <string>

namespace offsetgen::step {

struct WallBrep {
  TopoDS_Shape solid;  // a TopoDS_Solid, or a compound of them where the block cuts the wall into pieces
  int solids = 1;
  int bspline_faces = 0, planar_faces = 0;
  long control_points = 0;  // over all B-spline faces
  double sewing_tolerance = 0;
  int free_edges = 0;  // after sewing: 0 for a closed shell
};

// `plus` and `minus` are the patches of the offset surfaces at +t/2 and -t/2 (cell units); the block
// spans [0, cells[a] * cell_size] in millimetres. Throws std::runtime_error if sewing leaves the shell
// open or the solid is not valid.
// One patch per sheet for all images (a uniform wall), or one per image of region_images (a graded one).
// `plus_outward`: a direction out of the wall at the middle, (u, v) = (1/2, 1/2), of the first plus
// patch (the gradient of phi(p, +t/2) there), which orients the solid.
// `inside_wall` (a point in cell units): whether it lies inside the exact wall; needed only where the
// region is larger than the block, to tell which pieces of the box's faces close the solid.
WallBrep build_wall(const PatchLayout& layout, const std::vector<CubicPatch>& plus,
                    const std::vector<CubicPatch>& minus, const Point& plus_outward, const std::array<int, 3>& cells,
                    double cell_size, const std::function<bool(const Point&)>& inside_wall = {});

// The distinct knots and multiplicities of a clamped uniform cubic B-spline with n control points.
void knots_of(int n, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults);

// Whether BRepCheck_Analyzer finds the shape valid, and the count of its solids and shells.
struct ShapeCheck {
  bool valid = false;
  int solids = 0, shells = 0, faces = 0;
  bool closed = false;  // every shell closed (BRep_Tool::IsClosed)
  double volume = 0;    // BRepGProp, mm^3
};
ShapeCheck check_shape(const TopoDS_Shape& shape);

}  // namespace offsetgen::step
