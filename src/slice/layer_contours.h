// The contours of one layer of a block of cells (z fixed): the boundary of the part, {w < 0} inside the
// block's box, as closed polylines whose vertices lie on the exact zero set of the emitted wall (or on
// the box's sides, where the box cuts the wall), placed so that every chord stays within a tolerance of
// the true contour. Steps: the layer sampled in blocks (wall/layer_sampler.h), marching squares on
// G = max(w, box) with saddle cells decided by G at the cell's centre, the crossings near the box's
// sides refined onto G = 0 (batched regula falsi, Brent's method for the rare stragglers) and the
// corners where the wall meets a side found on that side, each loop thinned greedily to half the
// tolerance on the crossings' linear estimates and the crossings kept refined onto G = 0, and every
// chord checked at its midpoint: G must change sign within the tolerance either side along the chord's
// normal (the deviation is where the line through those two values crosses zero); a chord that fails
// gets the contour's point on that normal as a new vertex, and both halves are checked again.
// Loops run with the solid on their left: outer loops counter-clockwise, holes clockwise. Bounded by a
// body instead (LayerSetup::body), G is the part of wall/part_value.h from the body's distance and w.
#pragma once

#include "slice/body_layer.h"
#include "wall/wall_field.h"

#include <array>
#include <cstddef>
#include <vector>

namespace offsetgen::slice {

using Point2 = std::array<double, 2>;

// A closed loop: its vertices once each (the first is not repeated), in millimetres.
struct Loop {
  std::vector<Point2> points;
  double area = 0;  // signed (shoelace), mm^2: > 0 counter-clockwise (an outer boundary)
};

struct LayerSetup {
  std::array<int, 2> cells{1, 1};  // the block's box [0, NX] x [0, NY] in cell units
  // A body instead of the block's box: the part is wall/part_value.h's skin and core, the grid covers
  // the body's box, and the contour has no box sides (its corners are met within the tolerance).
  const BodyLayer* body = nullptr;
  double cell_size = 10;     // mm
  double z = 0.5;            // cell units
  int pixels_per_cell = 64;  // the marching grid
  double tolerance = 0.005;  // mm: the largest chord deviation allowed
  double tiny_area = 0;      // mm^2: loops with less area are dropped (and counted)
  double reach = 0;          // WallExtent::reach
  bool use_field_bound = true;
  int threads = 1;  // for sampling the layer
};

struct LayerContours {
  std::vector<Loop> loops;
  size_t vertices = 0;
  size_t tiny_loops = 0;         // dropped: less area than LayerSetup::tiny_area
  double max_deviation = 0;      // mm: the largest chord-midpoint deviation measured
  size_t unverified_chords = 0;  // chords whose midpoint could not be projected onto the contour
  size_t samples = 0;            // wall evaluations of the sampling, and of refinement and checks
  size_t refine_evaluations = 0;
};

LayerContours layer_contours(const wall::WallField& field, const LayerSetup& setup);

// The signed area of a closed polygon (shoelace): > 0 counter-clockwise.
double polygon_area(const std::vector<Point2>& points);

// A point's kind on the contour, for tests: on a side of the box (|box distance| within eps, cell units).
bool on_box_side(const LayerSetup& setup, const Point2& mm, double eps_mm);

}  // namespace offsetgen::slice
