// 3MF (3D Manufacturing Format), what current slicers prefer: a zip of XML with the unit stated
// (millimetre). Written through lib3mf (Debian lib3mf-dev), the 3MF Consortium's library; only
// mesh_3mf.cpp includes it. Built when lib3mf is found (OFFSETGEN_HAVE_LIB3MF).
#pragma once

#include "mesh/triangle_mesh.h"

#include <string>

namespace offsetgen::mesh {

// Whether this build can write 3MF.
bool can_write_3mf();

// The .3mf file's bytes: one mesh object `name`, in millimetres, one build item. Same mesh, same
// bytes: lib3mf's random UUIDs are replaced by ones derived from the mesh. Throws std::runtime_error
// when lib3mf fails, or when the build has no lib3mf.
std::string encode_3mf(const TriangleMesh& mesh, const std::string& name);

}  // namespace offsetgen::mesh
