#include "step/body_sampling.h"

#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace offsetgen::step {

SampledPart sample_part_volume(const CadBody& body, double body_volume, double core_volume,
                               const std::function<bool(const Point&)>& in_wall, int per_side) {
  const TopoDS_Shape& core = body.core.IsNull() ? body.solids : body.core;
  std::vector<std::unique_ptr<BRepClass3d_SolidClassifier>> solids;  // each built once, asked per point
  for (TopExp_Explorer e(core, TopAbs_SOLID); e.More(); e.Next())
    solids.push_back(std::make_unique<BRepClass3d_SolidClassifier>(e.Current()));
  Bnd_Box box;
  BRepBndLib::AddOptimal(core, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  double lo[3], hi[3];
  box.Get(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  const double step[3] = {(hi[0] - lo[0]) / per_side, (hi[1] - lo[1]) / per_side, (hi[2] - lo[2]) / per_side};

  std::mt19937_64 random(20261129);  // fixed: a run is repeatable
  const auto jitter = [&random] { return double(random() >> 11) * 0x1.0p-53; };
  long hits = 0;
  SampledPart out;
  for (int i = 0; i < per_side; ++i)
    for (int j = 0; j < per_side; ++j)
      for (int k = 0; k < per_side; ++k, ++out.points) {
        const Point p{lo[0] + (i + jitter()) * step[0], lo[1] + (j + jitter()) * step[1],
                      lo[2] + (k + jitter()) * step[2]};
        if (!in_wall(p)) continue;  // the cheap test first: the wall is a compiled function
        for (const auto& solid : solids) {
          solid->Perform(gp_Pnt(p[0], p[1], p[2]), 1e-7);
          if (solid->State() == TopAbs_IN) {
            ++hits;
            break;
          }
        }
      }
  const double box_volume = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  const double fraction = double(hits) / double(out.points);
  const double skin = body.core.IsNull() ? 0.0 : body_volume - core_volume;
  out.volume = skin + box_volume * fraction;
  out.error = box_volume * std::sqrt(fraction * (1 - fraction) / double(out.points));
  return out;
}

bool part_volume_agrees(double part_volume, const SampledPart& sampled, double body_volume) {
  return std::abs(part_volume - sampled.volume) <= 5 * sampled.error + 2e-3 * body_volume;
}

}  // namespace offsetgen::step
