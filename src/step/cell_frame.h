// The block's frame. The exporter cuts, fits and measures in cell units, where the wall repeats with
// period 1 and the boxes are whole fractions of a cell; millimetres are cell units scaled along each
// axis by the cell's sides. A cube cell's wall functions take cell units, as they always have. A box
// cell's ("distorted cells", --cell-size X,Y,Z) take millimetres: they are the functions of the
// composed field G(x) = F(x/X, y/Y, z/Z), the map "x/X; y/Y; z/Z" of docs/maps.md, offset along the
// physical normal, so the wall is --thickness millimetres thick however the cell is stretched.
#pragma once

#include "step/step_request.h"
#include "support/point.h"
#include "wall/wall_field.h"

namespace offsetgen::step {

struct CellFrame {
  Point mm{1, 1, 1};     // millimetres per cell unit along x, y and z
  Point field{1, 1, 1};  // the wall functions' units per cell unit: 1 (cube cell) or mm (box cell)

  bool distorted() const { return field != Point{1, 1, 1}; }
  // The longest side (mm): a length in cell units is at most this many mm.
  double largest_mm() const;
  double cell_volume() const;  // mm^3
  Point to_field(const Point& cell_units) const;
};

CellFrame cell_frame(const StepRequest& request);

// The wall the request's functions are generated from: request.wall as given for a cube cell; for a
// box cell, composed with the map "x/X; y/Y; z/Z" over the block (mm; the map is linear, so the
// bounds over one whole cell hold everywhere).
wall::WallRequest framed_wall(const StepRequest& request);

// "10" for a cube cell, "10 x 10 x 15" for a box cell (mm).
std::string cell_size_words(const std::array<double, 3>& cell_size);

}  // namespace offsetgen::step
