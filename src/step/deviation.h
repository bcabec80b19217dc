// The deviation of a B-rep from the exact wall, measured: points on the exact offset surfaces
// (phi(p, h) = 0, found by bisection along lines parallel to the axes through the whole block, so
// independent of how the faces were fitted), and each point's distance to the B-rep's B-spline faces.
#pragma once

#include "step/bspline_fit.h"
#include "step/level_function.h"

#include <TopoDS_Shape.hxx>

#include <array>
#include <cstdint>
#include <vector>

namespace offsetgen::step {

// Points (cell units) where lines parallel to x, y and z cross g = 0: `lines` lines per axis and
// cell face, on a grid jittered from `seed` (the same points every run with the same seed), scanned at
// `steps` points per cell.
std::vector<Point> exact_surface_points(const LevelFunction& g, const std::array<int, 3>& cells, int lines, int steps,
                                        uint64_t seed);

struct Deviation {
  double max = 0, mean = 0;  // mm
  long points = 0;
  Point worst{};  // mm
};

// The distance of every point (cell units, scaled to mm along each axis by the cell's sides `mm`) to
// the nearest B-spline face of `shape` (the nearest point of the face, its parameter range included).
// Only faces whose bounding box enlarged by `reach` (mm) holds a point are tried; a point with none
// counts as `reach` away.
Deviation measure_deviation(const TopoDS_Shape& shape, const std::vector<Point>& points, const Point& mm, double reach);

}  // namespace offsetgen::step
