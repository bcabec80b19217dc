#include "mesh/ply_stream.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace offsetgen::mesh {
namespace {

// The counts are written with 10 digits so that the final header has the placeholder's length.
std::string ply_header(const std::string& description, uint64_t vertices, uint64_t faces) {
  std::string comment = description;
  for (char& c : comment)
    if (c == '\n') c = ' ';
  return fmt::format(
      "ply\nformat binary_little_endian 1.0\ncomment {}\nelement vertex {:010d}\nproperty float x\n"
      "property float y\nproperty float z\nelement face {:010d}\nproperty list uchar uint vertex_indices\n"
      "end_header\n",
      comment, vertices, faces);
}

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

size_t PlyStream::PointHash::operator()(const std::array<float, 3>& p) const {
  uint32_t bits[3];
  std::memcpy(bits, p.data(), sizeof(bits));
  uint64_t h = 1469598103934665603ull;
  for (uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
  return static_cast<size_t>(h);
}

PlyStream::PlyStream(const std::string& path, const std::string& description)
    : file_(path), spool_(std::tmpfile(), &std::fclose), header_(ply_header(description, 0, 0)) {
  if (!spool_)
    throw std::runtime_error(
        fmt::format("cannot create a spool file for the faces of '{}': {}", path, std::strerror(errno)));
  file_.append(header_);
}

void PlyStream::append(const TriangleMesh& mesh, const std::vector<uint8_t>& on_seam) {
  std::vector<uint32_t> index(mesh.points.size());
  std::string vertices;
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    if (on_seam[i]) {
      const auto found = seam_points_.find(mesh.points[i]);
      if (found != seam_points_.end()) {
        index[i] = found->second;
        continue;
      }
    }
    if (vertices_ >= std::numeric_limits<uint32_t>::max())
      throw std::runtime_error("more than 2^32 - 1 vertices: PLY's indices here are 32-bit; use a larger --voxel");
    index[i] = static_cast<uint32_t>(vertices_++);
    if (on_seam[i]) seam_points_.emplace(mesh.points[i], index[i]);
    for (float x : mesh.points[i]) put<float>(vertices, x);
  }
  file_.append(vertices);
  std::string faces;
  faces.reserve(13 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    put<uint8_t>(faces, 3);
    for (uint32_t i : t) put<uint32_t>(faces, index[i]);
  }
  if (std::fwrite(faces.data(), 1, faces.size(), spool_.get()) != faces.size())
    throw ResourceError(
        fmt::format("cannot spool the faces of the PLY (temporary directory): {}; free space there "
                    "or set TMPDIR",
                    std::strerror(errno)));
  faces_ += mesh.triangles.size();
}

void PlyStream::commit() {
  const std::string header = ply_header(
      header_.substr(header_.find("comment ") + 8, header_.find("\nelement vertex") - header_.find("comment ") - 8),
      vertices_, faces_);
  file_.overwrite(0, header);
  std::rewind(spool_.get());
  std::string buffer(size_t(1) << 24, '\0');
  for (;;) {
    const size_t n = std::fread(buffer.data(), 1, buffer.size(), spool_.get());
    if (n == 0) break;
    file_.append(buffer.substr(0, n));
  }
  if (std::ferror(spool_.get())) throw std::runtime_error("reading back the PLY's spooled faces failed");
  file_.commit();
}

}  // namespace offsetgen::mesh
