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
  bool by_pieces = true;     // from the closed surfaces; false: vertices deeper than a voxel (tiles)
  size_t cavities = 0;       // closed inner surfaces
  double thinnest = 0;       // mm: the smallest depth of a cavity's vertex below the body's surface
  double outer_deepest = 0;  // mm: the largest depth of a vertex of an outer surface
};

// `depth_voxels[i]`: the body's signed distance at mesh.points[i] (voxels, negative inside); the mesh
// faces outward (keep_large_pieces).
SkinReport measure_skin(const TriangleMesh& mesh, const std::vector<double>& depth_voxels, double voxel_mm);

// Tile by tile, without the closed surfaces: every vertex deeper than kOuterSurfaceDepth below the
// body's surface belongs to an inner surface; the thinnest skin is the smallest such depth. Merges into
// `report` (by_pieces false). The outer surface's vertices lie within a voxel of the body's exact
// surface: at a sharp crease the mesh cuts the corner by up to about half a voxel (0.52 voxel on the
// bunny's ears).
inline constexpr double kOuterSurfaceDepth = 1.0;  // voxels
void measure_skin_by_depth(const std::vector<double>& depth_voxels, double voxel_mm, SkinReport& report);

}  // namespace offsetgen::mesh
