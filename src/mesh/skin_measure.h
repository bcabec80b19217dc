// The skin of a part, measured on the written mesh: its inner surfaces (the cavities between the
// lattice's walls, closed surfaces of negative volume once the mesh faces outward) lie at depth -d
// below the body's surface, so the thinnest skin is the smallest depth of a cavity's vertex. The
// outer surface should not go deeper than a voxel: deeper, a cavity has broken through the skin.
#pragma once

#include "mesh/triangle_mesh.h"

#include <cstddef>
#include <vector>

namespace offsetgen::mesh {

struct SkinReport {
  size_t cavities = 0;       // closed inner surfaces
  double thinnest = 0;       // mm: the smallest depth of a cavity's vertex below the body's surface
  double outer_deepest = 0;  // mm: the largest depth of a vertex of an outer surface
};

// `depth_voxels[i]`: the body's signed distance at mesh.points[i] (voxels, negative inside); the mesh
// faces outward (keep_large_pieces).
SkinReport measure_skin(const TriangleMesh& mesh, const std::vector<double>& depth_voxels, double voxel_mm);

}  // namespace offsetgen::mesh
