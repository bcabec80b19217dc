// A body (the user's part, `slice --body`) as what bounds a layer's lattice: its signed distance d
// (body/body_distance.h: exact within a band, the inside by winding number) on the marching grid's
// pixels block by block, and at any points of the layer for refining and checking the contour. The
// part is wall/part_value.h's skin and core from d and the wall. Nothing of the body's volume is held:
// memory grows with its facets and one layer.
#pragma once

#include "body/body_distance.h"
#include "body/body_mesh.h"

#include <array>
#include <vector>

namespace offsetgen::slice {

// Coordinates are the lattice's cell units, (mm - origin) / cell_size; pixel k of an axis (any integer)
// is centred at (k + 1/2) / pixels_per_cell.
class BodyLayer {
 public:
  enum class Place { Outside, Deep, Mixed };  // as mesh's domains: Deep lies beyond skin + fillet + margin

  // skin and fillet in mm; origin: the lattice's origin, mm.
  BodyLayer(const body::BodyMesh& mesh, const std::array<double, 3>& origin, double cell_size, int pixels_per_cell,
            double skin, double fillet);

  // The first pixel and the pixel count on x and y that cover the body's box with a margin.
  std::array<int, 2> first_pixel() const { return first_pixel_; }
  std::array<int, 2> pixels() const { return pixels_; }
  double skin() const { return skin_; }  // cell units
  double fillet() const { return fillet_; }
  double margin() const { return kMargin; }  // pixels of band beyond the body's surface

  class Query {
   public:
    explicit Query(const BodyLayer& layer) : query(layer.distance_) {}

   private:
    friend class BodyLayer;
    body::BodyDistance::Query query;
    std::vector<body::Vec3> points;
    std::vector<double> values;
  };
  // d in pixels, capped at the band, of the 8 x 8 pixels from `pixel` (x-major), at height z (cells);
  // filled for Mixed only.
  Place block(const std::array<int, 2>& pixel, double z, double* d, Query& q) const;
  // d in cell units at the points (cell units) at height z.
  void distances(const std::vector<std::array<double, 2>>& points, double z, double* d, Query& q) const;

 private:
  static constexpr double kMargin = 3;  // pixels: the band outside the body, as mesh's
  double per_cell_;                     // pixels per cell
  double skin_, fillet_;
  body::BodyDistance distance_;
  std::array<int, 2> first_pixel_{}, pixels_{};
};

}  // namespace offsetgen::slice
