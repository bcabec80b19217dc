// Whether a body (body_mesh.h) bounds a solid, and the repairs that make the usual defects of exported
// parts good: degenerate and duplicate triangles, inconsistent facing, small holes, an inside-out
// file. A level set needs a closed, consistently oriented surface; the caller refuses the body when
// analyse_topology(mesh).closed() is still false after repair_body.
#pragma once

#include "body/body_mesh.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace offsetgen::body {

// Edges are counted over the triangles with three distinct point indices (the others have no edges).
struct TopologyReport {
  size_t triangles = 0, points = 0;
  size_t open_edges = 0;            // edges used by one triangle
  size_t nonmanifold_edges = 0;     // edges used by more than two triangles
  size_t misoriented_edges = 0;     // edges whose two triangles traverse it in the same direction
  size_t degenerate_triangles = 0;  // repeated index or zero area
  size_t duplicate_triangles = 0;   // same three points as an earlier triangle (any order): the extra copies
  size_t shells = 0;                // connected components (by shared edges) of the triangles with edges
  // Midpoint of the first such edge, "first" in the order of (min index, max index).
  std::optional<std::array<double, 3>> first_open_edge;
  std::optional<std::array<double, 3>> first_nonmanifold_edge, first_misoriented_edge;

  // No open, non-manifold or misoriented edges (a mesh without triangles is closed: check triangles).
  bool closed() const;
  // One sentence: "12 open edges (the first at (10.5, 3, 0) mm), 0 non-manifold edges, 3 misoriented
  // edges (the first at (1, 2, 3) mm), 2 degenerate and 0 duplicate triangles; 1200 triangles in 1 shell".
  std::string describe() const;
};

// O(n) in the triangles (edges are grouped by a counting sort on their smaller point; no hash map, no
// global sort): a million triangles take a few tenths of a second.
TopologyReport analyse_topology(const BodyMesh& mesh);

struct RepairReport {
  size_t removed_degenerate = 0, removed_duplicate = 0, flipped = 0, holes_filled = 0, hole_triangles = 0;
  bool oriented_outward_flipped_all = false;  // every shell faced inward (an inside-out file) and was flipped
  size_t shells_flipped = 0;                  // closed shells turned to face away from the material
  // "removed 2 degenerate and 1 duplicate triangles, flipped 5 to agree with their neighbours, filled 1 hole
  // with 4 triangles"; "nothing to repair" when nothing changed.
  std::string describe() const;
};

// Repairs in place, deterministically, in this order:
//  1. removes triangles with a repeated index; a zero-area triangle whose third point lies on its long
//     edge (a T-junction sliver) is removed and the triangle across that edge split at the point, which
//     changes no geometry; other zero-area triangles are removed;
//  2. removes duplicate triangles: of copies facing the same way one is kept; a pair facing opposite
//     ways (the shared wall of two touching solids) is removed together;
//  3. makes the facing consistent within each shell: breadth-first from its first triangle across edges
//     with two triangles, then the smaller side is flipped;
//  4. fills each hole whose boundary is a simple loop of at most 1000 edges (ear clipping in the plane
//     of the loop, no diagonal that is already an edge), except where the filled shell would enclose no
//     volume (a loose sheet, a stray triangle, an unwelded triangle soup: left open, so refused);
//  5. orients each closed shell away from the material: outward (positive volume) unless it lies inside
//     an odd number of other closed shells (a cavity, then inward). With more than 10000 closed shells
//     every one is made positive;
//  6. drops points no triangle uses (the others keep their order).
// Afterwards analyse_topology(mesh).closed() says whether the repair succeeded.
RepairReport repair_body(BodyMesh& mesh);

// The generalised winding number of the whole mesh around p: about 1 inside a closed outward body,
// 0 outside. O(triangles).
double winding_number(const BodyMesh& mesh, const std::array<double, 3>& p);

}  // namespace offsetgen::body
