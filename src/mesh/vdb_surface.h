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

// "OpenVDB 10.0.1", for the summary.
const char* openvdb_version();

}  // namespace offsetgen::mesh
