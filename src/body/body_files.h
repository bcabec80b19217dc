// Reading a body (the part to fill, `offsetgen mesh --body part.stl`): STL (binary or ASCII), PLY
// (ASCII, binary little- or big-endian), OBJ and 3MF (through lib3mf, when the build has it). Every
// format comes back as one welded triangle mesh in millimetres (body_mesh.h); nothing is repaired here
// (body_topology.h does that).
#pragma once

#include "body/body_mesh.h"

#include <string>

namespace offsetgen::body {

enum class BodyFormat { Stl, Ply, Obj, ThreeMf };

// From the extension (.stl .ply .obj .3mf, any case). Throws offsetgen::InputError naming the
// extension and the accepted ones.
BodyFormat body_format_for_path(const std::string& path);

// Whether this build reads 3MF (lib3mf was found).
bool can_read_3mf();

// Parses a file's bytes. Every malformed input throws offsetgen::InputError (surfaces/input_error.h)
// whose message starts with `name_for_messages` and says where: "part.stl: line 12: expected 'vertex
// x y z'", "part.ply: byte 1234: ...", "part.obj: line 7: face vertex 9 out of range (8 vertices)".
// So do a mesh without triangles, non-finite coordinates and counts the bytes cannot hold; no input
// makes it allocate much more than the input's size.
//   STL: binary when the size is exactly 84 + 50 n for the count n at byte 80 (even if the header
//        starts with "solid"), ASCII when it starts with "solid" otherwise; several solids are one body.
//   PLY: the vertex element's x y z (any scalar type; other properties skipped) and the face element's
//        vertex_indices or vertex_index list; other elements skipped.
//   OBJ: `v` and `f` lines (v, v/vt, v//vn and v/vt/vn, negative = relative); other lines ignored.
//   3MF: every mesh object of the build items, through components, with their transforms, scaled from
//        the model's unit to millimetres; triangles of mirrored objects are reversed to keep their
//        facing. Throws InputError in a build without lib3mf (can_read_3mf()).
// Polygons with more than three corners are split into a fan. Points are welded by exact position
// (-0 and +0 are one) and numbered in order of first use; points no triangle uses are dropped.
// Triangles are kept as they are: degenerate, duplicate or open ones are for body_topology.h.
BodyMesh parse_body(const std::string& bytes, BodyFormat format, const std::string& name_for_messages);

// Reads and parses `path` (its format from the extension). A missing or unreadable file is an
// InputError naming it.
BodyMesh read_body_file(const std::string& path);

}  // namespace offsetgen::body
