#include "step/measurement.h"

#include "numeric/volume_fraction.h"
#include "step/cell_frame.h"
#include "step/deviation.h"
#include "step/exact_walls.h"
#include "step/wall_brep.h"
#include "support/stopwatch.h"

#include <fmt/format.h>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace offsetgen::step {
namespace {

// The jitter of the deviation's lines: fixed, so a run is repeatable.
constexpr uint64_t kSeed = 20261126;

// A uniform wall's volume fraction in one cell times the cells (the block is whole cells of a periodic
// wall); a graded wall's, cell by cell. Measured in cell units, whatever units the field takes: a box
// cell's fraction is the same in cell units as in mm (a linear map keeps ratios of volumes), and the
// quadrature's steps and weights are tuned to cell units. There the composed field is F itself; its
// slope is at most the field's (per mm) times the longest side, and a wall t mm thick spans at least
// t / longest side of a cell along a column.
ExactVolume exact_wall_volume(const wall::WallField& field, const StepRequest& r, std::array<double, 2> thickness,
                              bool graded) {
  const auto t0 = Clock::now();
  const CellFrame frame = cell_frame(r);
  const double stretch = std::max({frame.field[0], frame.field[1], frame.field[2]});  // 1 for a cube cell
  wall::WallField::Worker worker(field);
  numeric::VolumeFractionSetup v;
  v.g = [&field, &worker, &frame](const double* p) {
    return wall_at(field, worker, frame.to_field({p[0], p[1], p[2]}).data());
  };
  v.field = [&field, &frame](const double* p) {
    const Point q = frame.to_field({p[0], p[1], p[2]});
    return field.field(q[0], q[1], q[2]);
  };
  v.field_slope_bound = field.field_lipschitz() * stretch;
  v.band = field.field_lipschitz() * 0.5 * thickness[1] * (1 + 1e-9);
  v.scan_step = thickness[0] / stretch / 4;
  const double cell = frame.cell_volume();
  std::vector<std::array<int, 3>> cells{{0, 0, 0}};
  if (graded) {
    v.periodic = false;
    cells.clear();
    for (int i = 0; i < r.cells[0]; ++i)
      for (int j = 0; j < r.cells[1]; ++j)
        for (int k = 0; k < r.cells[2]; ++k) cells.push_back({i, j, k});
  }
  const double copies = graded ? 1.0 : double(r.cells[0]) * r.cells[1] * r.cells[2];
  double variance = 0;
  ExactVolume out;
  for (const auto& at : cells) {
    v.origin = {double(at[0]), double(at[1]), double(at[2])};
    const numeric::VolumeFraction fraction = numeric::measure_volume_fraction(v, numeric::VolumeFractionOptions{});
    out.volume += fraction.value * cell * copies;
    variance += std::pow(fraction.standard_error * cell * copies, 2);
  }
  out.error = std::sqrt(variance);
  out.seconds = seconds_since(t0);
  return out;
}

// B-spline faces and their control points, counted on a shape.
void count_bspline_faces(const TopoDS_Shape& shape, StepSummary& s) {
  s.bspline_faces = 0;
  s.control_points = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const Handle(Geom_BSplineSurface) b =
        Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(e.Current())));
    if (b.IsNull()) continue;
    ++s.bspline_faces;
    s.control_points += long(b->NbUPoles()) * b->NbVPoles();
  }
}

}  // namespace

std::future<ExactVolume> start_exact_wall_volume(const wall::WallField& field, const StepRequest& r,
                                                 const StepSummary& s) {
  return std::async(std::launch::async, exact_wall_volume, std::cref(field), std::cref(r), s.thickness_range, s.graded);
}

bool volume_agrees(const StepSummary& s) {
  return std::abs(s.volume - s.exact_volume) <= kVolumeTolerance * s.exact_volume + 3 * s.exact_volume_error;
}

void measure_solid(const TopoDS_Shape& shape, const StepRequest& r, wall::WallField& field,
                   wall::WallField::Worker& worker, std::future<ExactVolume>& exact_volume, StepSummary& s) {
  auto t0 = Clock::now();
  const ShapeCheck c = check_shape(shape);
  s.seconds_check = seconds_since(t0);
  t0 = Clock::now();
  s.valid = c.valid;
  s.closed = c.closed && c.shells == c.solids;
  s.solids = c.solids;
  s.volume = c.volume;
  const long control_points = s.control_points;
  count_bspline_faces(shape, s);
  if (control_points > 0) s.control_points = control_points;  // export: the solid's own count
  s.control_points_per_cell = double(s.control_points) / (double(r.cells[0]) * r.cells[1] * r.cells[2]);
  s.planar_faces = c.faces - s.bspline_faces;

  // The exact wall points: lines along each axis, 12 per cell side, scanned at t/4 (the thinnest t, in
  // cell units: a box cell's wall t mm thick spans at least t / max(X, Y, Z) of a cell along any line).
  const CellFrame frame = cell_frame(r);
  const LevelFunction plus = offset_sheet(field, worker, frame, 1), minus = offset_sheet(field, worker, frame, -1);
  const double thinnest = s.thickness_range[0] / std::max({frame.field[0], frame.field[1], frame.field[2]});
  const int steps = std::max(16, static_cast<int>(std::ceil(4 / thinnest)));
  std::vector<Point> points = exact_surface_points(plus, r.cells, 12, steps, kSeed);
  const std::vector<Point> more = exact_surface_points(minus, r.cells, 12, steps, kSeed + 1);
  points.insert(points.end(), more.begin(), more.end());
  // Only faces within twice the tolerance of a point are tried: a point with none is beyond the tolerance.
  const Deviation d = measure_deviation(shape, points, frame.mm, 2 * r.tolerance);
  s.max_deviation = d.max;
  s.mean_deviation = d.mean;
  s.deviation_points = d.points;
  s.worst_point = d.worst;
  s.seconds_deviation = seconds_since(t0);

  const ExactVolume exact = exact_volume.get();
  s.exact_volume = exact.volume;
  s.exact_volume_error = exact.error;
  s.seconds_volume = exact.seconds;

  if (!s.valid || !s.closed || s.solids != s.expected_solids)
    s.failure = fmt::format("the shape is not {} valid closed solid{} (valid {}, solids {}, closed {})",
                            s.expected_solids, s.expected_solids == 1 ? "" : "s", s.valid, s.solids, s.closed);
  else if (!(s.max_deviation <= r.tolerance))
    s.failure = fmt::format("the measured deviation {:.3g} mm exceeds --tolerance {} mm", s.max_deviation, r.tolerance);
  // The fit's small signed error adds up over the faces: it matters for thin walls (a 0.2 mm gyroid
  // wall at 0.01 mm is off by +0.086%, at 0.003 mm by -0.02%).
  else if (!volume_agrees(s))
    s.failure = fmt::format(
        "the solid's volume {:.6f} mm^3 differs from the exact wall's {:.6f} mm^3 by more than {}% (a smaller "
        "--tolerance brings the faces, and their volume, closer)",
        s.volume, s.exact_volume, 100 * kVolumeTolerance);
}

}  // namespace offsetgen::step
