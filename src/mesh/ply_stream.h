// Binary little-endian PLY written tile by tile (mesh_files.h's layout): the vertices go to the
// output's temporary file as tiles finish, the faces to a spool file; at the end the faces follow the
// vertices and the header's counts (written with a fixed width) are filled in. The points of a tile's
// seams are welded by position with those its neighbours wrote, so the mesh is one indexed surface;
// only seam points are remembered, so memory grows with the seams' area, not the part's volume.
#pragma once

#include "emit/file_writer.h"
#include "mesh/triangle_mesh.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace offsetgen::mesh {

class PlyStream {
 public:
  PlyStream(const std::string& path, const std::string& description);
  // `on_seam[i]`: point i may be shared with another tile (it lies within reach of a tile face).
  void append(const TriangleMesh& mesh, const std::vector<uint8_t>& on_seam);
  uint64_t vertices() const { return vertices_; }
  uint64_t faces() const { return faces_; }
  size_t bytes() const { return file_.size(); }
  void commit();

 private:
  struct PointHash {
    size_t operator()(const std::array<float, 3>& p) const;
  };
  StreamedFile file_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> spool_;
  std::string header_;
  std::unordered_map<std::array<float, 3>, uint32_t, PointHash> seam_points_;
  uint64_t vertices_ = 0, faces_ = 0;
};

}  // namespace offsetgen::mesh
