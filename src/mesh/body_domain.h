// A body (the user's part) as the domain of domain.h: its signed distance d, computed block by block as
// the sampler asks for it (body_distance.h): exact within a band that reaches skin + fillet + 4 voxels
// inside and 3 outside, the inside by winding number. Nothing of the size of the body's volume or band
// is held, so a body of any size is meshed in the memory of its facets and one tile.
#pragma once

#include "body/body_distance.h"
#include "body/body_mesh.h"
#include "mesh/domain.h"

#include <array>
#include <memory>
#include <vector>

namespace offsetgen::mesh {

using body::BodyDistance;
using body::Vec3;

// Voxel i of an axis is centred at origin + (i + 0.5) * voxel, in millimetres.
struct VoxelFrame {
  std::array<double, 3> origin{0, 0, 0};
  double voxel = 1;
  std::array<double, 3> centre_mm(const std::array<double, 3>& index) const;
};

class BodyDomain : public Domain {
 public:
  // skin and fillet in voxels.
  BodyDomain(const body::BodyMesh& body, const VoxelFrame& frame, double skin, double fillet);

  std::unique_ptr<DomainReader> reader() const override;
  std::array<std::array<int, 3>, 2> block_range() const override { return range_; }
  double lattice_margin() const override { return 2.0; }

  // d (voxels) at points given in millimetres, exact within the band, +-its width beyond; on `threads`
  // threads.
  std::vector<double> distances(const std::vector<std::array<float, 3>>& points_mm, int threads) const;
  size_t memory_bytes() const { return distance_.memory_bytes(); }

 private:
  VoxelFrame frame_;
  BodyDistance distance_;
  std::array<std::array<int, 3>, 2> range_{};
};

}  // namespace offsetgen::mesh
