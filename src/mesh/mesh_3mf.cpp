#include "mesh/mesh_3mf.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#ifdef OFFSETGEN_HAVE_LIB3MF
#include <Model/COM/NMR_DLLInterfaces.h>
#endif

namespace offsetgen::mesh {

#ifdef OFFSETGEN_HAVE_LIB3MF
namespace {

// FNV-1a over the mesh's bytes, seeded per use: a 128-bit digest for the UUIDs.
uint64_t fnv1a(const TriangleMesh& mesh, uint64_t seed) {
  uint64_t h = 1469598103934665603ull ^ seed;
  auto mix = [&h](const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  };
  mix(mesh.points.data(), mesh.points.size() * sizeof(mesh.points[0]));
  mix(mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
  return h;
}

// A UUID (RFC 9562 version 8, "custom") from the mesh and a role ("object", "build", "item"), so
// the same mesh gives the same file.
std::string mesh_uuid(const TriangleMesh& mesh, uint64_t role) {
  uint64_t hi = fnv1a(mesh, role * 2 + 1), lo = fnv1a(mesh, role * 2 + 2);
  hi = (hi & ~0xF000ull) | 0x8000ull;                  // version 8
  lo = (lo & ~(0xC000ull << 48)) | (0x8000ull << 48);  // variant 10
  return fmt::format("{:08x}-{:04x}-{:04x}-{:04x}-{:012x}", hi >> 32, (hi >> 16) & 0xFFFF, hi & 0xFFFF, lo >> 48,
                     lo & 0xFFFFFFFFFFFFull);
}

// Owns one lib3mf handle.
struct Handle {
  NMR::PLib3MFBase* p = nullptr;
  ~Handle() {
    if (p) NMR::lib3mf_release(p);
  }
};

void require(HRESULT result, const char* what) {
  if (result != LIB3MF_OK) throw std::runtime_error(fmt::format("lib3mf: {} failed (0x{:x})", what, unsigned(result)));
}

}  // namespace

bool can_write_3mf() { return true; }

std::string encode_3mf(const TriangleMesh& mesh, const std::string& name) {
  std::vector<NMR::MODELMESHVERTEX> vertices(mesh.points.size());
  for (size_t i = 0; i < mesh.points.size(); ++i)
    for (int k = 0; k < 3; ++k) vertices[i].m_fPosition[k] = mesh.points[i][static_cast<size_t>(k)];
  std::vector<NMR::MODELMESHTRIANGLE> triangles(mesh.triangles.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) triangles[i].m_nIndices[k] = mesh.triangles[i][static_cast<size_t>(k)];

  Handle model, object, item, writer;
  require(NMR::lib3mf_createmodel(reinterpret_cast<NMR::PLib3MFModel**>(&model.p)), "createmodel");
  require(NMR::lib3mf_model_setunit(model.p, NMR::MODELUNIT_MILLIMETER), "setunit");
  require(NMR::lib3mf_model_addmeshobject(model.p, reinterpret_cast<NMR::PLib3MFModelMeshObject**>(&object.p)),
          "addmeshobject");
  require(NMR::lib3mf_meshobject_setgeometry(object.p, vertices.data(), static_cast<DWORD>(vertices.size()),
                                             triangles.data(), static_cast<DWORD>(triangles.size())),
          "setgeometry");
  require(NMR::lib3mf_object_setnameutf8(object.p, name.c_str()), "setname");
  require(NMR::lib3mf_object_setuuidutf8(object.p, mesh_uuid(mesh, 0).c_str()), "object uuid");
  require(NMR::lib3mf_model_addbuilditem(model.p, object.p, nullptr,
                                         reinterpret_cast<NMR::PLib3MFModelBuildItem**>(&item.p)),
          "addbuilditem");
  require(NMR::lib3mf_builditem_setuuidutf8(item.p, mesh_uuid(mesh, 1).c_str()), "item uuid");
  require(NMR::lib3mf_model_setbuilduuidutf8(model.p, mesh_uuid(mesh, 2).c_str()), "build uuid");
  require(NMR::lib3mf_model_querywriter(model.p, "3mf", reinterpret_cast<NMR::PLib3MFModelWriter**>(&writer.p)),
          "querywriter");
  ULONG64 size = 0;
  require(NMR::lib3mf_writer_getstreamsize(writer.p, &size), "getstreamsize");
  std::string bytes(static_cast<size_t>(size), '\0');
  require(NMR::lib3mf_writer_writetobuffer(writer.p, reinterpret_cast<BYTE*>(bytes.data()), size), "writetobuffer");
  return bytes;
}

#else

bool can_write_3mf() { return false; }

std::string encode_3mf(const TriangleMesh&, const std::string&) {
  throw std::runtime_error("this offsetgen was built without lib3mf: no 3MF output");
}

#endif

}  // namespace offsetgen::mesh
