// Surface extraction with OpenVDB (volumeToMesh). The only file that includes OpenVDB: one
// translation unit with its headers takes ~40 s to compile, so nothing else should.
#pragma once

#include "mesh/narrow_band.h"
#include "mesh/triangle_mesh.h"

namespace offsetgen::mesh {

// The zero isosurface of the sampled band as triangles, in voxel index coordinates (voxel i at i).
// adaptivity in [0, 1]: 0 keeps every voxel's polygons, larger merges flat regions into fewer, larger
// polygons (OpenVDB keeps the result watertight). Deterministic.
TriangleMesh extract_surface(const SampledBand& band, double adaptivity);

// The same, restricted to the polygons of the voxels in `owned` (OpenVDB's surface mask: a polygon
// belongs to the voxel at the lower end of the grid edge it crosses). The band must hold the samples
// one voxel beyond `owned` on every side. Tiles that partition the grid give, together, exactly the
// polygons of the whole grid at adaptivity 0, with the same points along their seams.
TriangleMesh extract_surface(const SampledBand& band, double adaptivity, const VoxelBox& owned);

}  // namespace offsetgen::mesh
