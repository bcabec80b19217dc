// Binary STL written tile by tile with bounded memory (mesh_files.h's layout): facets are appended as
// tiles finish and the count is fixed up at the end, in a temporary file renamed over the target
// (emit/file_writer.h). Partial files of a split run (--tile-range I/N) are joined by merge_stl_parts
// into the bytes the single run writes.
#pragma once

#include "emit/file_writer.h"
#include "mesh/triangle_mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace offsetgen::mesh {

class StlStream {
 public:
  StlStream(const std::string& path, const std::string& description);
  void append(const TriangleMesh& mesh);
  uint64_t facets() const { return facets_; }
  size_t bytes() const { return file_.size(); }
  // Throws std::runtime_error past 2^32 - 1 facets (binary STL's count is 32 bits).
  void commit();

 private:
  StreamedFile file_;
  uint64_t facets_ = 0;
};

struct MergeReport {
  uint64_t facets = 0;
  size_t bytes = 0;
};

// Joins binary STL parts in the order given: the header of the first (all must share it: parts of
// one split run), the sum of their counts, their facets. Throws InputError naming a part that is not
// a binary STL of this run; writes nothing then.
MergeReport merge_stl_parts(const std::vector<std::string>& parts, const std::string& output);

}  // namespace offsetgen::mesh
