// libFuzzer target: the body readers (STL, PLY, OBJ; 3MF is lib3mf's own parser) and, on whatever
// parses, the topology analysis and repair. A damaged file must come back as InputError naming the
// problem; any other exception, crash, leak, undefined behaviour or huge allocation is a finding.
#include "body/body_files.h"
#include "body/body_topology.h"
#include "surfaces/input_error.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace offsetgen::body;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  for (BodyFormat format : {BodyFormat::Stl, BodyFormat::Ply, BodyFormat::Obj}) {
    BodyMesh mesh;
    try {
      mesh = parse_body(bytes, format, "fuzz");
    } catch (const offsetgen::InputError&) {
      continue;  // the expected answer to a damaged file
    }
    const TopologyReport before = analyse_topology(mesh);
    (void)before.describe();
    const RepairReport repair = repair_body(mesh);
    (void)repair.describe();
    // What repair leaves is well formed: indices in range, every point used, no degenerate triangle,
    // and a second repair finds none either.
    const TopologyReport after = analyse_topology(mesh);
    if (after.degenerate_triangles != 0) std::abort();
    std::vector<uint8_t> used(mesh.points.size(), 0);
    for (const auto& t : mesh.triangles)
      for (uint32_t i : t) {
        if (i >= mesh.points.size()) std::abort();
        used[i] = 1;
      }
    for (uint8_t u : used)
      if (!u) std::abort();
    if (repair_body(mesh).removed_degenerate != 0) std::abort();
  }
  return 0;
}
