// Mesh files: binary STL (what slicers read), binary little-endian PLY (indexed, about half the
// size) and 3MF (zipped XML in millimetres, mesh_3mf.h). Same mesh, same bytes: no timestamps.
#pragma once

#include "mesh/triangle_mesh.h"

#include <cstdint>
#include <string>

namespace offsetgen::mesh {

enum class MeshFormat { Stl, Ply, ThreeMf };

// From the file name's extension (.stl, .ply or .3mf, any case). Throws InputError otherwise, and for
// .3mf in a build without lib3mf.
MeshFormat format_for_path(const std::string& path);
const char* format_name(MeshFormat format);

// `description` goes into the STL header (80 bytes, cut), a PLY comment line or the 3MF object's name.
std::string encode_mesh(const TriangleMesh& mesh, MeshFormat format, const std::string& description);

// Binary STL in pieces: the 80-byte header ("binary STL: <description>", never "solid"), then 50
// bytes per facet (normal, three corners, no attributes); the count at byte 80 is the facets'.
std::string stl_header(const std::string& description);
std::string stl_facets(const TriangleMesh& mesh, size_t first = 0, size_t last = SIZE_MAX);  // triangles [first, last)

}  // namespace offsetgen::mesh
