#include "body/body_request.h"

#include "body/body_files.h"
#include "body/body_topology.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace offsetgen::body {

void validate_body(const BodyRequest& b, const std::string& output) {
  if (!(b.scale > 0 && std::isfinite(b.scale)))
    throw InputError(fmt::format("--scale {} is not a positive factor", b.scale));
  if (!(b.skin >= 0 && std::isfinite(b.skin)))
    throw InputError(fmt::format("--skin {} is not a thickness >= 0 (mm)", b.skin));
  if (!(b.fillet >= 0 && std::isfinite(b.fillet)))
    throw InputError(fmt::format("--fillet {} is not a radius >= 0 (mm)", b.fillet));
  if (b.fillet > 0 && b.skin == 0) throw InputError("--fillet blends the walls into the skin: it needs --skin > 0");
  if (b.origin)
    for (double x : *b.origin)
      if (!std::isfinite(x)) throw InputError("--origin: the coordinates must be finite numbers (mm)");
  // Never overwrite the part being read.
  std::error_code ec;
  if (!b.box && std::filesystem::equivalent(b.path, output, ec))
    throw InputError(fmt::format("-o {} is the body itself: choose another output file", output));
}

LoadedBody load_body(const BodyRequest& b, const BodyWarning& warn) {
  LoadedBody out;
  BodyMesh& mesh = out.mesh;
  mesh = b.box ? box_body(*b.box) : read_body_file(b.path);
  if (b.scale != 1)
    for (auto& p : mesh.points)
      for (double& x : p) x *= b.scale;
  TopologyReport topology = analyse_topology(mesh);
  if (!topology.closed() && !b.repair)
    throw InputError(fmt::format(
        "{}: the body is not a closed surface, so it has no inside: {}. Close it in your CAD tool, or try --repair",
        b.path, topology.describe()));
  if (b.repair) {
    const RepairReport repair = repair_body(mesh);
    topology = analyse_topology(mesh);
    if (!topology.closed())
      throw InputError(fmt::format("{}: --repair {} but the body is still not closed: {}", b.path, repair.describe(),
                                   topology.describe()));
    out.repaired = repair.describe();
    if (mesh.triangles.empty())
      throw InputError(
          fmt::format("{}: --repair {} and nothing closed is left of the body", b.path, repair.describe()));
  }
  out.box = bounding_box(mesh);
  out.volume = std::abs(signed_volume(mesh));
  double longest = 0;
  for (size_t a = 0; a < 3; ++a) longest = std::max(longest, out.box[1][a] - out.box[0][a]);
  if (warn && longest < 1)
    warn(
        fmt::format("the body is {:.3g} mm across: if it was exported in metres, use --scale 1000 (inches: "
                    "--scale 25.4)",
                    longest));
  if (warn && longest > 2000)
    warn(
        fmt::format("the body is {:.4g} mm across (over 2 m): if it was exported in micrometres, use --scale "
                    "0.001; in tenths of a millimetre, --scale 0.1",
                    longest));
  return out;
}

void check_body_size(const std::array<std::array<double, 3>, 2>& box, double cell_size, double skin) {
  double longest = 0, shortest = HUGE_VAL;
  for (size_t a = 0; a < 3; ++a) {
    longest = std::max(longest, box[1][a] - box[0][a]);
    shortest = std::min(shortest, box[1][a] - box[0][a]);
  }
  if (longest < cell_size)
    throw InputError(fmt::format(
        "the body ({:.4g} mm across) is smaller than one cell ({:g} mm): use a smaller --cell-size, or --scale if "
        "its units are not millimetres",
        longest, cell_size));
  if (2 * skin >= shortest)
    throw InputError(fmt::format(
        "--skin {:g} mm is at least half the body's smallest extent ({:.4g} mm): it leaves no core for the lattice",
        skin, shortest));
}

BodyMesh box_body(const std::array<std::array<double, 3>, 2>& box) {
  BodyMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.points.push_back({box[i & 1][0], box[(i >> 1) & 1][1], box[(i >> 2) & 1][2]});
  // Two triangles per face, counter-clockwise seen from outside (corner index = x + 2y + 4z).
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

}  // namespace offsetgen::body
