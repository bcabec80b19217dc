#include "mesh/mesh_files.h"

#include "mesh/mesh_3mf.h"
#include "surfaces/surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "mesh files are written little-endian by memcpy");

namespace offsetgen::mesh {
namespace {

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string binary_stl(const TriangleMesh& mesh, const std::string& description) {
  std::string out = stl_header(description);
  const uint32_t count = static_cast<uint32_t>(mesh.triangles.size());
  std::memcpy(out.data() + 80, &count, 4);
  out += stl_facets(mesh);
  return out;
}

std::string binary_ply(const TriangleMesh& mesh, const std::string& description) {
  std::string comment = description;
  std::replace(comment.begin(), comment.end(), '\n', ' ');
  std::string out = fmt::format(
      "ply\nformat binary_little_endian 1.0\ncomment {}\nelement vertex {}\nproperty float x\nproperty float y\n"
      "property float z\nelement face {}\nproperty list uchar uint vertex_indices\nend_header\n",
      comment, mesh.points.size(), mesh.triangles.size());
  out.reserve(out.size() + 12 * mesh.points.size() + 13 * mesh.triangles.size());
  for (const auto& p : mesh.points)
    for (float x : p) put<float>(out, x);
  for (const auto& t : mesh.triangles) {
    put<uint8_t>(out, 3);
    for (uint32_t i : t) put<uint32_t>(out, i);
  }
  return out;
}

}  // namespace

MeshFormat format_for_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".3mf" && can_write_3mf()) return MeshFormat::ThreeMf;
  if (ext == ".3mf")
    throw InputError(
        fmt::format("-o '{}': this offsetgen was built without lib3mf, so it cannot write 3MF (apt-get "
                    "install lib3mf-dev and rebuild; .stl and .ply work)",
                    path));
  throw InputError(fmt::format(
      "-o '{}': unknown mesh format '{}' (use .stl for binary STL, .ply for binary PLY or .3mf for 3MF)", path, ext));
}

const char* format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::Stl:
      return "binary STL";
    case MeshFormat::Ply:
      return "binary PLY";
    case MeshFormat::ThreeMf:
      return "3MF";
  }
  return "";
}

std::string stl_header(const std::string& description) {
  // The header must not start with "solid": readers would take the file for ASCII STL.
  std::string header = "binary STL: " + description;
  header.resize(80, ' ');
  header.append(4, '\0');  // the facet count, filled in by the writer
  return header;
}

std::string stl_facets(const TriangleMesh& mesh, size_t first, size_t last) {
  last = std::min(last, mesh.triangles.size());
  first = std::min(first, last);
  std::string out(50 * (last - first), '\0');
  char* facet = out.data();
  for (size_t i = first; i < last; ++i) {
    const auto& t = mesh.triangles[i];
    const auto& a = mesh.points[t[0]];
    const auto& b = mesh.points[t[1]];
    const auto& c = mesh.points[t[2]];
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    float record[12];
    for (int k = 0; k < 3; ++k) record[k] = length > 0 ? static_cast<float>(n[k] / length) : 0.0f;
    for (int k = 0; k < 3; ++k) {
      record[3 + k] = a[static_cast<size_t>(k)];
      record[6 + k] = b[static_cast<size_t>(k)];
      record[9 + k] = c[static_cast<size_t>(k)];
    }
    std::memcpy(facet, record, sizeof(record));  // then 2 bytes of attributes, zero
    facet += 50;
  }
  return out;
}

std::string encode_mesh(const TriangleMesh& mesh, MeshFormat format, const std::string& description) {
  switch (format) {
    case MeshFormat::Stl:
      return binary_stl(mesh, description);
    case MeshFormat::Ply:
      return binary_ply(mesh, description);
    case MeshFormat::ThreeMf:
      return encode_3mf(mesh, description);
  }
  return "";
}

}  // namespace offsetgen::mesh
