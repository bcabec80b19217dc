// Mesh files: binary STL (what slicers read) and binary little-endian PLY (indexed, about half the
// size). Same mesh, same bytes: no timestamps.
#pragma once

#include "mesh/triangle_mesh.h"

#include <string>

namespace offsetgen::mesh {

enum class MeshFormat { Stl, Ply };

// From the file name's extension (.stl or .ply, any case). Throws InputError otherwise.
MeshFormat format_for_path(const std::string& path);
const char* format_name(MeshFormat format);

// `description` goes into the STL header (80 bytes, cut) or a PLY comment line.
std::string encode_mesh(const TriangleMesh& mesh, MeshFormat format, const std::string& description);

}  // namespace offsetgen::mesh
