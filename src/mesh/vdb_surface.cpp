#include "mesh/vdb_surface.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

namespace offsetgen::mesh {

namespace {

openvdb::FloatGrid::Ptr band_grid(const SampledBand& band) {
  openvdb::initialize();
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(band.background);
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  openvdb::FloatTree& tree = grid->tree();
  for (const BandBlock& block : band.blocks) {
    const auto& o = block.origin;
    if (block.solid) {
      // An inactive tile the size of a leaf (level 1): no voxels held, inside throughout.
      tree.addTile(1, openvdb::Coord(o[0], o[1], o[2]), -band.background, false);
      continue;
    }
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
  return grid;
}

// The mesher's polygons as triangles: quads first (split along the shorter diagonal, the
// better-shaped pair), then triangles, pool by pool, as openvdb::tools::volumeToMesh orders them.
TriangleMesh collect(openvdb::tools::VolumeToMesh& mesher) {
  TriangleMesh mesh;
  const openvdb::tools::PointList& points = mesher.pointList();
  mesh.points.reserve(mesher.pointListSize());
  for (size_t i = 0; i < mesher.pointListSize(); ++i) mesh.points.push_back({points[i][0], points[i][1], points[i][2]});
  auto distance2 = [&](openvdb::Index a, openvdb::Index b) { return (points[a] - points[b]).lengthSqr(); };
  openvdb::tools::PolygonPoolList& pools = mesher.polygonPoolList();
  for (size_t n = 0; n < mesher.polygonPoolListSize(); ++n)
    for (size_t i = 0; i < pools[n].numQuads(); ++i) {
      const openvdb::Vec4I& q = pools[n].quad(i);
      if (distance2(q[0], q[2]) <= distance2(q[1], q[3])) {
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
      } else {
        mesh.triangles.push_back({q[0], q[1], q[3]});
        mesh.triangles.push_back({q[1], q[2], q[3]});
      }
    }
  for (size_t n = 0; n < mesher.polygonPoolListSize(); ++n)
    for (size_t i = 0; i < pools[n].numTriangles(); ++i) {
      const openvdb::Vec3I& t = pools[n].triangle(i);
      mesh.triangles.push_back({t[0], t[1], t[2]});
    }
  return mesh;
}

// The blocks on either side of the tile's faces, where polygons are not merged (--adaptivity): the
// points there are computed from the same samples in both tiles, so the seams close. (OpenVDB keeps
// its own side of a surface mask unmerged, not the margin beyond it.) Leaves of voxels, not tiles:
// the mesher reads the mask leaf by leaf.
openvdb::TreeBase::ConstPtr seam_blocks(const VoxelBox& owned) {
  auto mask = std::make_shared<openvdb::BoolTree>(false);
  const openvdb::Coord lo(owned[0][0], owned[0][1], owned[0][2]), hi(owned[1][0] - 1, owned[1][1] - 1, owned[1][2] - 1);
  mask->fill(openvdb::CoordBBox(lo.offsetBy(-kBlock), hi.offsetBy(kBlock)), true, true);
  mask->fill(openvdb::CoordBBox(lo.offsetBy(kBlock), hi.offsetBy(-kBlock)), false, false);
  mask->voxelizeActiveTiles();
  return mask;
}

}  // namespace

TriangleMesh extract_surface(const SampledBand& band, double adaptivity) {
  openvdb::FloatGrid::Ptr grid = band_grid(band);
  openvdb::tools::VolumeToMesh mesher(0.0, adaptivity);
  mesher(*grid);
  return collect(mesher);
}

TriangleMesh extract_surface(const SampledBand& band, double adaptivity, const VoxelBox& owned) {
  openvdb::FloatGrid::Ptr grid = band_grid(band);
  openvdb::BoolGrid::Ptr mask = openvdb::BoolGrid::create(false);
  mask->fill(openvdb::CoordBBox(openvdb::Coord(owned[0][0], owned[0][1], owned[0][2]),
                                openvdb::Coord(owned[1][0] - 1, owned[1][1] - 1, owned[1][2] - 1)),
             true, true);
  openvdb::tools::VolumeToMesh mesher(0.0, adaptivity);
  mesher.setSurfaceMask(mask);
  if (adaptivity > 0) mesher.setAdaptivityMask(seam_blocks(owned));
  mesher(*grid);
  return collect(mesher);
}

}  // namespace offsetgen::mesh
