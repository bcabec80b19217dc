#include "validate/map_checks.h"

#include "field/atom_table.h"
#include "lowering/point_program.h"
#include "lowering/sample_region.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace offsetgen {
namespace {

// One program of natural coordinates with the given outputs.
class NaturalFunction {
 public:
  NaturalFunction(int dims, const std::vector<GiNaC::ex>& outputs)
      : program_(point_program(dims, outputs, AtomTable())), evaluate_(std::make_unique<Evaluator>(program_)) {}
  const std::vector<double>& operator()(const std::vector<double>& p) { return (*evaluate_)(p); }

 private:
  Program program_;
  std::unique_ptr<Evaluator> evaluate_;
};

double box_diagonal(SampleRegion& region) {
  double d2 = 0;
  for (int i = 0; i < region.dims(); ++i) d2 += std::pow(region.hi(i) - region.lo(i), 2);
  return std::sqrt(d2);
}

// The closest the region comes to where `measure` vanishes, and the point.
double smallest(SampleRegion& region, const std::function<double(const std::vector<double>&)>& measure,
                std::vector<double>& where) {
  return -maximum_over_region(
      region, [&](const std::vector<double>& p) { return -measure(p); }, "the map's measure", &where);
}

void require_no_singular_point(const Surface& surface, SampleRegion& region) {
  if (!region.has_singular_measures() || surface.singular_clearance > 0) return;
  std::vector<double> where;
  const double closest = smallest(
      region, [&](const std::vector<double>& p) { return region.singular_measure(p); }, where);
  if (closest <= 1e-7 * box_diagonal(region))
    throw InputError(fmt::format(
        "the map '{}' is singular at {}, inside {}: its lattice coordinates (an angle atan2, a root or a logarithm of "
        "a vanishing argument) have no limit or no derivative there, so cells crowd into that point and no bound of "
        "|grad F| exists. Choose a --domain that stays clear of it (for the cylindrical and spherical maps, of the z "
        "axis), or mesh inside a --body that does",
        surface.map, point_text(where), region.describe()));
}

// Each atan2(b, a) of F wraps by 2 pi across its cut {b = 0, a < 0}. Where the region meets the cut,
// F must not change when the angle moves by 2 pi, i.e. the angle's multiple is a whole number of cells.
void require_single_valued(const Surface& surface, SampleRegion& region) {
  std::vector<GiNaC::ex> angles;
  for (auto it = surface.field.preorder_begin(); it != surface.field.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::function>(*it) && GiNaC::ex_to<GiNaC::function>(*it).get_name() == "atan2") {
      bool seen = false;
      for (const auto& a : angles) seen = seen || a.is_equal(*it);
      if (!seen) angles.push_back(*it);
    }
  for (const auto& angle : angles) {
    NaturalFunction cut(surface.dims, {GiNaC::abs(angle.op(0)) + (angle.op(1) + GiNaC::abs(angle.op(1))) / 2});
    std::vector<double> where;
    const double distance = smallest(
        region, [&](const std::vector<double>& p) { return cut(p)[0]; }, where);
    if (distance > 1e-7 * box_diagonal(region)) continue;  // the domain does not reach the cut
    NaturalFunction both(surface.dims, {surface.field, surface.field.subs(angle == angle + 2 * GiNaC::Pi)});
    const std::vector<double>& v = both(where);
    if (std::fabs(v[0] - v[1]) > 1e-6 * (1 + std::fabs(v[0])))
      throw InputError(
          fmt::format("the map '{}' makes F jump across the cut of atan2 (where the angle wraps from pi to -pi), met "
                      "at {}: F is {:.6g} "
                      "on one side and {:.6g} on the other. Make the angle's multiple a whole number of cells (N in "
                      "cylindrical:N,...), so the cells close up",
                      surface.map, point_text(where), v[0], v[1]));
  }
}

}  // namespace

void require_regular_map(const Surface& surface) {
  if (!surface.mapped()) return;
  if (!surface.domain)
    throw InputError(
        "a mapped lattice (--map) needs a domain: --domain X0,Y0,Z0:X1,Y1,Z1, the box where its walls "
        "are built and checked (a mapped field is not periodic, so one cell says nothing)");
  SampleRegion region(surface);
  require_no_singular_point(surface, region);
  require_single_valued(surface, region);
}

}  // namespace offsetgen
