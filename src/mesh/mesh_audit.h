// The part judged as a slicer will read it, before it is kept: the triangles exactly as written
// (float millimetres, welded by position as STL readers weld them), counted tile by tile without
// holding the mesh. An edge must bound exactly two facets, once in each direction; a facet whose
// corners do not differ in the file is degenerate. Edges near a tile's seam are held until the
// neighbouring tile has been counted, so the count is the same as over the whole mesh at once.
#pragma once

#include "mesh/triangle_mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace offsetgen::mesh {

struct AuditReport {
  size_t open_edges = 0;            // bounding one facet
  size_t nonmanifold_edges = 0;     // bounding three or more
  size_t misoriented_edges = 0;     // bounding two facets that cross it the same way
  size_t degenerate_facets = 0;     // two corners at the same position
  size_t unmatched_seam_edges = 0;  // on a seam to tiles this run did not mesh (--tile-range): not judged
  bool closed() const {
    return open_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 && degenerate_facets == 0;
  }
  std::string describe() const;  // "0 open edges, 0 non-manifold edges, ..."
};

class MeshAudit {
 public:
  // Where an edge may continue into another tile's facets: `seam[i]` for each point of `mesh`.
  // `outside_run[i]`: that other tile is not meshed by this run (its edges are left unjudged).
  void add(const TriangleMesh& mesh, const std::vector<uint8_t>& seam, const std::vector<uint8_t>& outside_run);
  // A whole mesh, no seams.
  void add(const TriangleMesh& mesh);
  // Judges the edges still held (those along seams).
  AuditReport finish();

 private:
  using Position = std::array<float, 3>;
  // A seam edge is held by two independent 64-bit hashes of its ends' positions (the smaller position
  // first): 16 bytes, where a chance collision of both is beyond any mesh's count.
  struct EdgeKey {
    uint64_t a = 0, b = 0;
    bool operator==(const EdgeKey& o) const { return a == o.a && b == o.b; }
  };
  struct EdgeHash {
    size_t operator()(const EdgeKey& k) const { return static_cast<size_t>(k.a); }
  };
  struct SeamEdge {
    uint8_t forward = 0, backward = 0;  // facets crossing it from the first end to the second, and back
    bool outside_run = false;
  };
  static EdgeKey edge_key(const Position& first, const Position& second);
  void judge(int forward, int backward);
  AuditReport report_;
  std::unordered_map<EdgeKey, SeamEdge, EdgeHash> seam_edges_;
};

}  // namespace offsetgen::mesh
