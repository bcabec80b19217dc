// The body's signed distance, computed where it is asked for: exact distances to the nearest facet
// within a band, and the inside by the winding number along a ray up the z axis. Each value depends only
// on the voxel and the facets, not on which tile asks or in which order, so the tiles' seams agree and
// nothing of the size of the body's volume (or of its band) is ever held: memory grows with the
// facets alone.
//
// The winding number counts the facets a ray from the point up to z = +inf crosses, +1 for a facet
// facing up and -1 for one facing down: nonzero inside a closed surface, whichever way its facets face,
// zero in an inner void bounded by a facet shell facing the other way. A ray through an edge or a
// vertex meets exactly one of the facets there: each edge is tested in one direction (its ends in
// lexicographic order), and a point on it belongs to the facet on its left (as if moved up by an
// infinitesimal), so no crossing is counted twice or lost.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace offsetgen::body {

using Vec3 = std::array<double, 3>;

// The blocks the distance is computed in: kDistanceBlock^3 voxels, x-major ((x * 8 + y) * 8 + z), the
// sampler's blocks (mesh/narrow_band.h); a layer's blocks are kDistanceBlock^2 pixels, x-major.
inline constexpr int kDistanceBlock = 8;
inline constexpr int distance_block_offset(int x, int y, int z) {
  return (x * kDistanceBlock + y) * kDistanceBlock + z;
}

class BodyDistance {
 public:
  // Points in voxel index coordinates (voxel i centred at i). Distances are exact below
  // `inside_reach` inside and `outside_reach` outside, and capped at those values beyond. Inside, any
  // distance within [free.lo, free.hi] will do (the middle of a skin, where the part is solid whatever
  // the exact value): one there is not made exact.
  struct Interval {
    double lo = 0, hi = 0;
  };
  BodyDistance(std::vector<Vec3> points, const std::vector<std::array<uint32_t, 3>>& triangles, double inside_reach,
               double outside_reach, Interval free);

  // Per-thread scratch space.
  class Query {
   public:
    explicit Query(const BodyDistance& body);

   private:
    friend class BodyDistance;
    std::vector<uint32_t> stamp;
    uint32_t generation = 0;
    std::vector<uint32_t> candidates;
    struct Near {
      double centre_distance;  // from the block's centre
      uint32_t facet;
      Vec3 ball;  // a ball holding the facet: a cheap lower bound of a point's distance to it
      double radius;
      bool operator<(const Near& o) const {
        return centre_distance != o.centre_distance ? centre_distance < o.centre_distance : facet < o.facet;
      }
    };
    std::vector<Near> near;
    std::vector<std::pair<double, int>> crossings;  // (z, +-1)
  };

  // The signed distances (voxels, negative inside) of the kDistanceBlock^3 voxels of the block whose
  // first voxel is `origin`, in block order (distance_block_offset). Returns false, filling nothing, when
  // no facet comes within reach of the block: inside(origin) then tells its side.
  bool block(const std::array<int, 3>& origin, double* d, Query& q) const;
  // The same for a layer at height z (voxel units, any value): the kDistanceBlock^2 points (origin[0] +
  // i, origin[1] + j, z), x-major ((i * 8) + j). False, filling nothing, when no facet comes within
  // reach: inside({origin[0], origin[1], z}) then tells the side of all of them.
  bool plane_block(const std::array<int, 2>& origin, double z, double* d, Query& q) const;
  bool inside(const Vec3& p, Query& q) const;
  // The signed distances at points (voxel coordinates), capped and free as above.
  void distances(const std::vector<Vec3>& points, double* d, Query& q) const;

  size_t memory_bytes() const;

 private:
  // Facets listed by the cells of a uniform grid that their boxes overlap (compressed rows).
  struct CellIndex {
    double cell = 1;               // voxels per cell side
    std::vector<int64_t> keys;     // sorted cell keys
    std::vector<uint32_t> starts;  // keys.size() + 1 offsets into facets
    std::vector<uint32_t> facets;
    void lookup(int64_t key, const uint32_t*& first, const uint32_t*& last) const;
  };
  void gather(const Vec3& lo, const Vec3& hi, Query& q) const;  // facets whose boxes meet [lo, hi]
  // q.near: the facets that may come within reach of a point within `radius` of `centre`, nearest first.
  void prepare(const Vec3& centre, double radius, Query& q) const;
  // The distance from p (at `offset` from the centre q.near was prepared for), on its side.
  double scan(const Vec3& p, bool inside, double offset, const Query& q) const;
  int winding(double x, double y, Query& q) const;  // fills q.crossings for the column
  double facet_distance2(const Vec3& p, uint32_t facet) const;

  std::vector<Vec3> points_;
  std::vector<std::array<uint32_t, 3>> triangles_;
  std::vector<std::pair<Vec3, double>> balls_;  // per facet: its centroid and the farthest corner's distance
  double inside_reach_, outside_reach_;
  Interval free_;
  CellIndex cells_;    // 3D, by facet box
  CellIndex columns_;  // 2D (x, y), by the facet box's projection
};

}  // namespace offsetgen::body
