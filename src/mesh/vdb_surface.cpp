#include "mesh/vdb_surface.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

namespace offsetgen::mesh {

TriangleMesh extract_surface(const SampledBand& band, double adaptivity) {
  openvdb::initialize();
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(band.background);
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  openvdb::FloatTree& tree = grid->tree();
  for (const BandBlock& block : band.blocks) {
    const auto& o = block.origin;
    openvdb::FloatTree::LeafNodeType* leaf = tree.touchLeaf(openvdb::Coord(o[0], o[1], o[2]));
    // Our block layout is the leaf's linear offset ((x * 8 + y) * 8 + z).
    static_assert(openvdb::FloatTree::LeafNodeType::DIM == kBlock, "blocks are OpenVDB leaves");
    for (openvdb::Index i = 0; i < static_cast<openvdb::Index>(kBlockVoxels); ++i) {
      if (block.active[i]) {
        leaf->setValueOn(i, block.values[i]);
      } else {
        leaf->setValueOff(i, block.values[i]);
      }
    }
  }

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, adaptivity);

  TriangleMesh mesh;
  mesh.points.reserve(points.size());
  for (const auto& p : points) mesh.points.push_back({p[0], p[1], p[2]});
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  // Quads split along the shorter diagonal: the better-shaped pair of triangles.
  auto distance2 = [&](openvdb::Index a, openvdb::Index b) { return (points[a] - points[b]).lengthSqr(); };
  for (const auto& q : quads) {
    if (distance2(q[0], q[2]) <= distance2(q[1], q[3])) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      mesh.triangles.push_back({q[0], q[1], q[3]});
      mesh.triangles.push_back({q[1], q[2], q[3]});
    }
  }
  for (const auto& t : triangles) mesh.triangles.push_back({t[0], t[1], t[2]});
  return mesh;
}

const char* openvdb_version() { return "OpenVDB " OPENVDB_LIBRARY_VERSION_STRING; }

}  // namespace offsetgen::mesh
