#include "mesh/body_domain.h"

#include "mesh/narrow_band.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace offsetgen::mesh {
namespace {

static_assert(kBlock == body::kDistanceBlock, "the body's distance blocks are the sampler's");

constexpr double kOutsideWidth = 3.0;  // voxels of band outside the body (>= the sampler's margin of 2)

int align_down(int i) { return i >= 0 ? (i / kBlock) * kBlock : -((-i + kBlock - 1) / kBlock) * kBlock; }

// The body's points in voxel index coordinates: voxel i's centre is index i.
std::vector<Vec3> index_points(const body::BodyMesh& body, const VoxelFrame& frame) {
  std::vector<Vec3> points;
  points.reserve(body.points.size());
  for (const auto& p : body.points) {
    Vec3 q{};
    for (size_t a = 0; a < 3; ++a) q[a] = (p[a] - frame.origin[a]) / frame.voxel - 0.5;
    points.push_back(q);
  }
  return points;
}

// Depths inside the skin where the part is solid whatever the exact depth, one voxel clear of the
// values that matter: the outer surface's band (3 voxels, the values clamped there) and the core's
// surface at the skin's depth with its band and fillet (domain.h).
BodyDistance::Interval free_depths(double skin, double fillet) { return {4, skin - fillet - 4}; }

class BodyReader : public DomainReader {
 public:
  explicit BodyReader(const BodyDistance& distance) : distance_(distance), query_(distance) {}

  BlockPlace read_block(const std::array<int, 3>& origin, double margin, double* d) override {
    if (!distance_.block(origin, d, query_)) {
      // No facet within the band: the whole block is on one side, beyond the skin if inside.
      const Vec3 corner = {double(origin[0]), double(origin[1]), double(origin[2])};
      return distance_.inside(corner, query_) ? BlockPlace::Deep : BlockPlace::Outside;
    }
    const double nearest = *std::min_element(d, d + kBlockVoxels);
    return nearest >= margin ? BlockPlace::Outside : BlockPlace::Mixed;
  }

 private:
  const BodyDistance& distance_;
  BodyDistance::Query query_;
};

}  // namespace

std::array<double, 3> VoxelFrame::centre_mm(const std::array<double, 3>& index) const {
  return {origin[0] + (index[0] + 0.5) * voxel, origin[1] + (index[1] + 0.5) * voxel,
          origin[2] + (index[2] + 0.5) * voxel};
}

BodyDomain::BodyDomain(const body::BodyMesh& body, const VoxelFrame& frame, double skin_voxels, double fillet_voxels)
    : frame_(frame),
      // Deep enough inside for the core's surface (d = -skin), its fillet and the sampler's band.
      distance_(index_points(body, frame), body.triangles, skin_voxels + fillet_voxels + kOutsideWidth + 1,
                kOutsideWidth, free_depths(skin_voxels, fillet_voxels)) {
  skin = skin_voxels;
  fillet = fillet_voxels;
  const auto box = body::bounding_box(body);
  for (size_t a = 0; a < 3; ++a) {
    const double lo = (box[0][a] - frame.origin[a]) / frame.voxel - 0.5;
    const double hi = (box[1][a] - frame.origin[a]) / frame.voxel - 0.5;
    range_[0][a] = align_down(static_cast<int>(std::floor(lo)) - 4);
    range_[1][a] = align_down(static_cast<int>(std::ceil(hi)) + 4) + kBlock;
  }
}

std::unique_ptr<DomainReader> BodyDomain::reader() const { return std::make_unique<BodyReader>(distance_); }

std::vector<double> BodyDomain::distances(const std::vector<std::array<float, 3>>& points_mm, int threads) const {
  std::vector<double> d(points_mm.size());
  const size_t count = std::max(1, threads), chunk = (points_mm.size() + count - 1) / count;
  auto work = [&](size_t first, size_t last) {
    BodyDistance::Query query(distance_);
    constexpr size_t kBatch = size_t(1) << 16;  // points at a time: the scratch stays small
    std::vector<Vec3> index;
    for (size_t from = first; from < last; from += kBatch) {
      const size_t to = std::min(last, from + kBatch);
      index.resize(to - from);
      for (size_t i = from; i < to; ++i)
        for (size_t a = 0; a < 3; ++a)
          index[i - from][a] = (double(points_mm[i][a]) - frame_.origin[a]) / frame_.voxel - 0.5;
      distance_.distances(index, d.data() + from, query);
    }
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < count; ++t)
    pool.emplace_back(work, std::min(points_mm.size(), t * chunk), std::min(points_mm.size(), (t + 1) * chunk));
  work(0, std::min(points_mm.size(), chunk));
  for (auto& t : pool) t.join();
  return d;
}

}  // namespace offsetgen::mesh
