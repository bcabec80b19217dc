#include "mesh/stl_stream.h"

#include "mesh/mesh_files.h"
#include "surfaces/input_error.h"
#include "validate/share_range.h"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <limits>

namespace offsetgen::mesh {
namespace {

constexpr size_t kHeader = 84, kFacet = 50;

std::string count_bytes(uint64_t facets) {
  if (facets > std::numeric_limits<uint32_t>::max())
    throw std::runtime_error(
        fmt::format("{} facets do not fit binary STL's 32-bit count: use a larger --voxel or "
                    "--adaptivity, or split the part (--tile-range)",
                    facets));
  const auto count = static_cast<uint32_t>(facets);
  std::string bytes(4, '\0');
  std::memcpy(bytes.data(), &count, 4);
  return bytes;
}

struct Part {
  std::string header;  // 80 bytes
  uint64_t facets = 0;
};

Part read_part_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("--merge: cannot read '{}'", path));
  std::string head(kHeader, '\0');
  in.read(head.data(), kHeader);
  in.seekg(0, std::ios::end);
  const auto size = static_cast<uint64_t>(in.tellg());
  uint32_t count = 0;
  if (in.good() && size >= kHeader) std::memcpy(&count, head.data() + 80, 4);
  if (size < kHeader || size != kHeader + uint64_t(kFacet) * count || head.rfind("binary STL: offsetgen mesh", 0) != 0)
    throw InputError(fmt::format("--merge: '{}' is not a binary STL part written by offsetgen mesh", path));
  return {head.substr(0, 80), count};
}

}  // namespace

StlStream::StlStream(const std::string& path, const std::string& description) : file_(path) {
  file_.append(stl_header(description));
}

void StlStream::append(const TriangleMesh& mesh) {
  constexpr size_t kChunk = size_t(1) << 16;  // facets encoded at a time: 3.2 MB, not the tile's whole
  for (size_t first = 0; first < mesh.triangles.size(); first += kChunk)
    file_.append(stl_facets(mesh, first, first + kChunk));
  facets_ += mesh.triangles.size();
}

void StlStream::commit() {
  file_.overwrite(80, count_bytes(facets_));
  file_.commit();
}

MergeReport merge_stl_parts(const std::vector<std::string>& parts, const std::string& output) {
  check_merge_paths(parts, output);
  std::vector<Part> heads;
  for (const auto& path : parts) {
    heads.push_back(read_part_header(path));
    if (heads.back().header != heads.front().header)
      throw InputError(fmt::format("--merge: '{}' comes from another run than '{}' (their STL headers differ)", path,
                                   parts.front()));
  }
  MergeReport report;
  for (const Part& p : heads) report.facets += p.facets;
  StreamedFile out(output);
  out.append(heads.front().header + count_bytes(report.facets));
  std::string buffer(size_t(1) << 24, '\0');
  for (const auto& path : parts) {
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(kHeader));
    while (in) {
      in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      out.append(buffer.substr(0, static_cast<size_t>(in.gcount())));
    }
  }
  report.bytes = out.size();
  out.commit();
  return report;
}

}  // namespace offsetgen::mesh
