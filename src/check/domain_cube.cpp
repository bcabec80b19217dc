#include "check/domain_cube.h"

#include <algorithm>
#include <memory>

namespace offsetgen::check {

DomainCube domain_cube(const run::FileMetadata& meta) {
  DomainCube cube;
  if (!meta.domain) return cube;
  const auto& box = *meta.domain;
  cube.identity = false;
  cube.side = box[1][0] - box[0][0];
  for (int i = 1; i < meta.dims; ++i)
    cube.side = std::min(cube.side, box[1][static_cast<size_t>(i)] - box[0][static_cast<size_t>(i)]);
  // A margin of 1/8 of the side on each face: the sweep's walls reach 0.1 side (and rays 0.2) from
  // points of the cube, and the bounds the safeguard clamps to hold in the domain only (beyond a face,
  // where the map stretches more, |grad F| may exceed M and the walls move by O(h)).
  cube.side /= 1.25;
  for (int i = 0; i < meta.dims; ++i) {
    const size_t a = static_cast<size_t>(i);
    cube.origin[a] = (box[0][a] + box[1][a] - cube.side) / 2;
  }
  return cube;
}

Probe in_cube(const Probe& probe, const DomainCube& cube, int dims) {
  if (cube.identity) return probe;
  auto at = [cube, dims](const double* unit) {
    std::array<double, 3> p{};
    for (int i = 0; i < dims; ++i) p[static_cast<size_t>(i)] = cube.at(i, unit[i]);
    return p;
  };
  const double side = cube.side;
  Probe out = probe;
  const auto inner = std::make_shared<Probe>(probe);
  out.field = [inner, at](const double* q) { return inner->field(at(q).data()); };
  out.offset = [inner, at, side](const double* q, double h) { return inner->offset(at(q).data(), side * h); };
  out.shell = [inner, at, side](const double* q, double t) { return inner->shell(at(q).data(), side * t); };
  out.normal = [inner, at, side](const double* q, double h, double* n) { inner->normal(at(q).data(), side * h, n); };
  if (probe.graded) out.graded = [inner, at](const double* q) { return inner->graded(at(q).data()); };
  out.graded_wall = nullptr;  // a mapped file's graded wall is not measured (docs/maps.md)
  return out;
}

}  // namespace offsetgen::check
