#include "mesh/body_domain.h"

#include "mesh/narrow_band.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>

namespace offsetgen::mesh {
namespace {

constexpr float kOutsideWidth = 3.0f;  // voxels of band outside the body (>= the sampler's margin of 2)

int align_down(int i) { return i >= 0 ? (i / kBlock) * kBlock : -((-i + kBlock - 1) / kBlock) * kBlock; }

class BodyReader : public DomainReader {
 public:
  explicit BodyReader(const openvdb::FloatGrid& grid) : accessor_(grid.getConstAccessor()) {}

  BlockPlace read_block(const std::array<int, 3>& origin, double margin, double* d) override {
    const openvdb::Coord corner(origin[0], origin[1], origin[2]);
    const auto* leaf = accessor_.probeConstLeaf(corner);
    if (leaf == nullptr) {
      // A tile or the background: the sign flood fill gave it +outside or -inside width.
      return accessor_.getValue(corner) > 0 ? BlockPlace::Outside : BlockPlace::Deep;
    }
    static_assert(openvdb::FloatTree::LeafNodeType::DIM == kBlock, "blocks are OpenVDB leaves");
    double nearest = HUGE_VAL;
    for (openvdb::Index i = 0; i < static_cast<openvdb::Index>(kBlockVoxels); ++i) {
      d[i] = leaf->getValue(i);  // the leaf's linear order is the block order
      nearest = std::min(nearest, d[i]);
    }
    return nearest >= margin ? BlockPlace::Outside : BlockPlace::Mixed;
  }

 private:
  openvdb::FloatGrid::ConstAccessor accessor_;
};

double mesh_volume(const std::vector<openvdb::Vec3s>& points, const std::vector<openvdb::Vec3I>& triangles,
                   const std::vector<openvdb::Vec4I>& quads) {
  auto tet = [&](openvdb::Index a, openvdb::Index b, openvdb::Index c) {
    const openvdb::Vec3d p(points[a]), q(points[b]), r(points[c]);
    return p.dot(q.cross(r)) / 6.0;
  };
  double v = 0;
  for (const auto& t : triangles) v += tet(t[0], t[1], t[2]);
  for (const auto& q : quads) v += tet(q[0], q[1], q[2]) + tet(q[0], q[2], q[3]);
  return std::abs(v);
}

}  // namespace

std::array<double, 3> VoxelFrame::centre_mm(const std::array<double, 3>& index) const {
  return {origin[0] + (index[0] + 0.5) * voxel, origin[1] + (index[1] + 0.5) * voxel,
          origin[2] + (index[2] + 0.5) * voxel};
}

struct BodyDomain::Grid {
  openvdb::FloatGrid::Ptr grid;
};

BodyDomain::BodyDomain(const body::BodyMesh& body, const VoxelFrame& frame, double skin_voxels, double fillet_voxels)
    : grid_(std::make_unique<Grid>()), frame_(frame) {
  openvdb::initialize();
  skin = skin_voxels;
  fillet = fillet_voxels;
  // Index space: voxel i's centre is index i.
  std::vector<openvdb::Vec3s> points;
  points.reserve(body.points.size());
  std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& p : body.points) {
    openvdb::Vec3s q;
    for (int a = 0; a < 3; ++a) {
      const double index = (p[static_cast<size_t>(a)] - frame.origin[static_cast<size_t>(a)]) / frame.voxel - 0.5;
      q[a] = static_cast<float>(index);
      lo[static_cast<size_t>(a)] = std::min(lo[static_cast<size_t>(a)], index);
      hi[static_cast<size_t>(a)] = std::max(hi[static_cast<size_t>(a)], index);
    }
    points.push_back(q);
  }
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(body.triangles.size());
  for (const auto& t : body.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
  // Deep enough inside for the core's surface (d = -skin), its fillet and the sampler's band.
  inside_width_ = skin_voxels + fillet_voxels + kOutsideWidth + 1;
  const auto transform = openvdb::math::Transform::createLinearTransform(1.0);
  grid_->grid = openvdb::tools::meshToVolume<openvdb::FloatGrid>(adapter, *transform, kOutsideWidth,
                                                                 static_cast<float>(inside_width_));
  for (size_t a = 0; a < 3; ++a) {
    range_[0][a] = align_down(static_cast<int>(std::floor(lo[a])) - 4);
    range_[1][a] = align_down(static_cast<int>(std::ceil(hi[a])) + 4) + kBlock;
  }
}

BodyDomain::~BodyDomain() = default;

std::unique_ptr<DomainReader> BodyDomain::reader() const { return std::make_unique<BodyReader>(*grid_->grid); }

double BodyDomain::volume_below(double level) const {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid_->grid, points, triangles, quads, level, 0.0);
  return mesh_volume(points, triangles, quads) * std::pow(frame_.voxel, 3);
}

std::vector<double> BodyDomain::distances(const std::vector<std::array<float, 3>>& points_mm) const {
  std::vector<double> d;
  d.reserve(points_mm.size());
  const auto accessor = grid_->grid->getConstAccessor();
  for (const auto& p : points_mm) {
    openvdb::Vec3d index;
    for (int a = 0; a < 3; ++a)
      index[a] = (double(p[static_cast<size_t>(a)]) - frame_.origin[static_cast<size_t>(a)]) / frame_.voxel - 0.5;
    d.push_back(openvdb::tools::BoxSampler::sample(accessor, index));
  }
  return d;
}

size_t BodyDomain::band_voxels() const { return grid_->grid->activeVoxelCount(); }

size_t BodyDomain::memory_bytes() const { return grid_->grid->memUsage(); }

}  // namespace offsetgen::mesh
