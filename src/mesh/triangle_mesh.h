// An indexed triangle mesh and what `mesh` does to it after extraction: closed pieces, their
// volumes, outward orientation, dropping small pieces.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace offsetgen::mesh {

struct TriangleMesh {
  std::vector<std::array<float, 3>> points;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Volume enclosed by the triangles (divergence theorem), positive when they face outward.
double signed_volume(const TriangleMesh& mesh);

struct PieceReport {
  int kept = 0;      // pieces (closed surfaces enclosing material) written
  int dropped = 0;   // pieces below the volume threshold, removed
  int cavities = 0;  // closed surfaces bounding voids inside a piece (negative volume), kept
  double dropped_volume = 0;
  double volume = 0;  // of what is kept
};

// The connected surface (piece) of each point, by triangles sharing a point: the piece's smallest
// point index. Points no triangle uses are pieces of their own.
std::vector<uint32_t> point_pieces(const TriangleMesh& mesh);
// The signed volume of each piece, indexed like the points (zero for indices that are no piece's).
std::vector<double> piece_volumes(const TriangleMesh& mesh, const std::vector<uint32_t>& pieces);

// Merges points at the same position (the seams of tiles), renumbering the triangles; the points
// keep the order of their first occurrence. Returns how many were merged.
size_t weld_points(TriangleMesh& mesh);

// Turns every triangle over.
void flip(TriangleMesh& mesh);

// Removes the pieces that lie inside `inner` (index coordinates; no point outside it) and enclose
// less than `min_volume`; cavities (negative volume) stay. Returns {pieces, volume} removed.
std::pair<int, double> drop_small_inner_pieces(TriangleMesh& mesh, const std::array<std::array<float, 3>, 2>& inner,
                                               double min_volume);

// Orients the whole mesh outward, then removes every connected piece whose volume is below
// `min_fraction` of the largest piece's, and points no triangle uses. Deterministic.
PieceReport keep_large_pieces(TriangleMesh& mesh, double min_fraction);

}  // namespace offsetgen::mesh
