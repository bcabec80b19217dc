// A body (the user's part) as the domain of domain.h: its signed distance d, built by OpenVDB's
// meshToVolume in a narrow band on the lattice's voxels. Insideness comes from OpenVDB's sign flood
// fill from the exterior, which ignores the facets' orientation and survives self-intersections.
#pragma once

#include "body/body_mesh.h"
#include "mesh/domain.h"

#include <array>
#include <memory>
#include <vector>

namespace offsetgen::mesh {

// Voxel i of an axis is centred at origin + (i + 0.5) * voxel, in millimetres.
struct VoxelFrame {
  std::array<double, 3> origin{0, 0, 0};
  double voxel = 1;
  std::array<double, 3> centre_mm(const std::array<double, 3>& index) const;
};

class BodyDomain : public Domain {
 public:
  // skin and fillet in voxels. The band reaches skin + fillet + 3 voxels inside, 3 outside.
  BodyDomain(const body::BodyMesh& body, const VoxelFrame& frame, double skin, double fillet);
  ~BodyDomain() override;
  BodyDomain(const BodyDomain&) = delete;
  BodyDomain& operator=(const BodyDomain&) = delete;

  std::unique_ptr<DomainReader> reader() const override;
  std::array<std::array<int, 3>, 2> block_range() const override { return range_; }
  double lattice_margin() const override { return 2.0; }

  // The volume where d < level (voxels), from the mesh of that level set (OpenVDB volumeToMesh), mm^3.
  double volume_below(double level) const;
  // d (voxels) at points given in millimetres, trilinear; +-the band's width beyond it.
  std::vector<double> distances(const std::vector<std::array<float, 3>>& points_mm) const;
  size_t band_voxels() const;
  size_t memory_bytes() const;

 private:
  struct Grid;
  std::unique_ptr<Grid> grid_;
  VoxelFrame frame_;
  std::array<std::array<int, 3>, 2> range_{};
  double inside_width_ = 0;
};

}  // namespace offsetgen::mesh
