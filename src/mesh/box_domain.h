// The block of cells [0, NX] x [0, NY] x [0, NZ] as a domain (domain.h): d is the box's distance
// max over axes of max(-x, x - N), in voxels; its faces cap the walls flat.
#pragma once

#include "mesh/domain.h"

namespace offsetgen::mesh {

class BoxDomain : public Domain {
 public:
  BoxDomain(const std::array<int, 3>& cells, double voxel);  // voxel in cell units
  std::unique_ptr<DomainReader> reader() const override;
  std::array<std::array<int, 3>, 2> block_range() const override;
  double lattice_margin() const override { return 1.0; }

 private:
  std::array<int, 3> cells_;
  double voxel_;
};

}  // namespace offsetgen::mesh
