#include "exact_wall_volume.h"

#include "numeric/volume_fraction.h"

#include <cmath>
#include <string>

namespace offsetgen::test_support {

ExactWallVolume exact_wall_volume(const std::string& surface, const std::string& thickness,
                                  const std::array<int, 3>& cells, double cell_size, int grid) {
  wall::WallRequest request;
  request.generation.surface = surface;
  request.thickness = thickness;
  wall::WallField field(request);
  field.compile();
  wall::WallField::Worker worker(field);
  const double t = std::stod(thickness);
  numeric::VolumeFractionSetup v;
  v.g = [&](const double* p) {
    double value = 0;
    field.walls(1, p, p + 1, p + 2, &value, worker);
    return value;
  };
  v.field = [&](const double* p) { return field.field(p[0], p[1], p[2]); };
  v.field_slope_bound = field.field_lipschitz();
  v.band = field.field_lipschitz() * 0.5 * t * (1 + 1e-9);
  v.scan_step = t / 4;
  numeric::VolumeFractionOptions options;
  options.seed = 7;  // not the tools'
  options.grid = grid;
  const numeric::VolumeFraction fraction = numeric::measure_volume_fraction(v, options);
  const double scale = double(cells[0]) * cells[1] * cells[2] * std::pow(cell_size, 3);
  return {fraction.value * scale, fraction.standard_error * scale};
}

}  // namespace offsetgen::test_support
