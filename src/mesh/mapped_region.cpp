#include "mesh/mapped_region.h"

#include "body/body_topology.h"
#include "lowering/sample_region.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace offsetgen::mesh {

std::string bound_map_to_body(GenerationRequest& request, const body::BodyMesh& body, double margin) {
  const auto box = body::bounding_box(body);
  Surface::Box domain;
  for (size_t a = 0; a < 3; ++a) {
    domain.lo[a] = box[0][a] - margin;
    domain.hi[a] = box[1][a] + margin;
  }
  request.domain = domain;
  request.singular_clearance = 0;
  Surface surface = resolve_surface(request);  // parses the map; cheap next to the build
  SampleRegion region(surface);
  if (!region.has_singular_measures()) return "";

  // Is there a singular point in the box at all? (The region search finds the closest approach.)
  std::vector<double> where;
  const double closest = -maximum_over_region(
      region, [&](const std::vector<double>& p) { return -region.singular_measure(p); }, "the map's singular measure",
      &where);
  double diagonal = 0;
  for (size_t a = 0; a < 3; ++a) diagonal += std::pow(domain.hi[a] - domain.lo[a], 2);
  if (closest > 1e-7 * std::sqrt(diagonal)) return "";  // none: the whole box is regular

  const std::array<double, 3> point{where[0], where[1], where[2]};
  if (std::fabs(body::winding_number(body, point)) > 0.5)
    throw InputError(fmt::format(
        "the map '{}' is singular at {}, inside the body, where the lattice is kept: its lattice coordinates have no "
        "limit there (cells crowd into the axis or centre of the map). Move the map (its formula's origin) or use a "
        "body that keeps clear of it, such as a tube around the axis",
        request.map, point_text(where)));
  // The body's surface: its corners, edge midpoints and centroids, nearest the singular set.
  double nearest = std::numeric_limits<double>::infinity();
  std::vector<double> nearest_at;
  auto visit = [&](const std::array<double, 3>& p) {
    std::vector<double> q(p.begin(), p.end());
    const double m = region.singular_measure(q);
    if (m < nearest) {
      nearest = m;
      nearest_at = q;
    }
  };
  for (const auto& t : body.triangles) {
    const auto& a = body.points[t[0]];
    const auto& b = body.points[t[1]];
    const auto& c = body.points[t[2]];
    std::array<double, 3> mid_ab{}, mid_bc{}, centroid{};
    for (size_t k = 0; k < 3; ++k) {
      mid_ab[k] = (a[k] + b[k]) / 2;
      mid_bc[k] = (b[k] + c[k]) / 2;
      centroid[k] = (a[k] + b[k] + c[k]) / 3;
    }
    for (const auto& p : {a, mid_ab, mid_bc, centroid}) visit(p);
  }
  if (!(nearest > 1e-7 * std::sqrt(diagonal)))
    throw InputError(
        fmt::format("the map '{}' is singular on the body's surface, at {}: move the map or the body so "
                    "that its singular set (the axis or centre of the map) stays clear of the part",
                    request.map, point_text(nearest_at)));
  request.singular_clearance = nearest / 2;
  return fmt::format(
      "the map's singular set (measure 0, e.g. at {}) lies outside the body; its measure on the "
      "body's surface is at least {:.4g}, so samples below {:.4g} are skipped",
      point_text(where), nearest, nearest / 2);
}

}  // namespace offsetgen::mesh
