#include "slice/scan_paths.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>
#include <clipper.hpp>

#include <algorithm>
#include <cmath>

namespace offsetgen::slice {
namespace {

// Clipper works on integers: 1 nm per unit (a 1 m block is 1e9 units, well inside its 64-bit range).
constexpr double kGridPerMm = 1e6;

double parse_number(const std::string& field, const std::string& text, const char* what) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(field, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != field.size() || !std::isfinite(v))
    throw InputError(
        fmt::format("--hatch '{}': {} '{}' is not a number; give SPACING[,ANGLE[,ROTATE]] "
                    "(mm, degrees, degrees), e.g. --hatch 0.1,0,66.67",
                    text, what, field));
  return v;
}

}  // namespace

double HatchPattern::angle_of_layer(size_t layer) const {
  double a = std::fmod(angle + double(layer) * rotation, 180.0);
  if (a < 0) a += 180;
  return a >= 180 ? 0 : a;
}

HatchPattern parse_hatch(const std::string& text) {
  std::vector<std::string> fields;
  size_t at = 0;
  while (true) {
    const size_t comma = text.find(',', at);
    fields.push_back(text.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  if (fields.size() > 3)
    throw InputError(fmt::format("--hatch '{}': give SPACING[,ANGLE[,ROTATE]] (at most three numbers)", text));
  HatchPattern h;
  h.spacing = parse_number(fields[0], text, "the spacing");
  if (fields.size() > 1) h.angle = parse_number(fields[1], text, "the angle");
  if (fields.size() > 2) h.rotation = parse_number(fields[2], text, "the rotation");
  if (!(h.spacing > 0))
    throw InputError(fmt::format("--hatch '{}': the spacing {:g} mm is not positive", text, h.spacing));
  return h;
}

std::vector<Loop> offset_inward(const std::vector<Loop>& loops, double distance, double arc_tolerance,
                                double min_area) {
  ClipperLib::Paths paths;
  paths.reserve(loops.size());
  for (const Loop& loop : loops) {
    ClipperLib::Path path;
    path.reserve(loop.points.size());
    for (const Point2& p : loop.points)
      path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p[0] * kGridPerMm)),
                        static_cast<ClipperLib::cInt>(std::llround(p[1] * kGridPerMm)));
    paths.push_back(std::move(path));
  }
  ClipperLib::ClipperOffset offset(2.0, arc_tolerance * kGridPerMm);
  offset.AddPaths(paths, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::Paths shrunk;
  offset.Execute(shrunk, -distance * kGridPerMm);
  std::vector<Loop> out;
  out.reserve(shrunk.size());
  for (const ClipperLib::Path& path : shrunk) {
    if (path.size() < 3) continue;
    Loop loop;
    loop.points.reserve(path.size());
    for (const ClipperLib::IntPoint& p : path)
      loop.points.push_back({double(p.X) / kGridPerMm, double(p.Y) / kGridPerMm});
    loop.area = polygon_area(loop.points);
    if (std::abs(loop.area) < min_area) continue;
    out.push_back(std::move(loop));
  }
  return out;
}

std::vector<Hatch> hatch_loops(const std::vector<Loop>& loops, double spacing, double angle) {
  const double a = angle * (std::acos(-1.0) / 180);
  const Point2 d{std::cos(a), std::sin(a)}, n{-d[1], d[0]};
  struct Crossing {
    long long line;
    double s;  // along the hatch direction
    Point2 p;
  };
  std::vector<Crossing> crossings;
  // Line j at t = j, t = p . n / spacing - 1/2.
  const auto t_of = [&](const Point2& p) { return (p[0] * n[0] + p[1] * n[1]) / spacing - 0.5; };
  for (const Loop& loop : loops) {
    const size_t m = loop.points.size();
    for (size_t k = 0; k < m; ++k) {
      const Point2& p = loop.points[k];
      const Point2& q = loop.points[(k + 1) % m];
      const double tp = t_of(p), tq = t_of(q);
      if (tp == tq) continue;
      const double lo = std::min(tp, tq), hi = std::max(tp, tq);
      for (auto j = static_cast<long long>(std::ceil(lo)); double(j) < hi; ++j) {
        const double f = (double(j) - tp) / (tq - tp);
        const Point2 c{p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1])};
        crossings.push_back({j, c[0] * d[0] + c[1] * d[1], c});
      }
    }
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& u, const Crossing& v) {
    if (u.line != v.line) return u.line < v.line;
    if (u.s != v.s) return u.s < v.s;
    return u.p < v.p;
  });
  std::vector<Hatch> hatches;
  hatches.reserve(crossings.size() / 2);
  for (size_t first = 0; first < crossings.size();) {
    size_t last = first;
    while (last < crossings.size() && crossings[last].line == crossings[first].line) ++last;
    const size_t begin = hatches.size();
    // Closed loops cross a line an even number of times (half-open rule); pair them in order.
    for (size_t k = first; k + 1 < last; k += 2)
      if (crossings[k + 1].s > crossings[k].s) hatches.push_back({crossings[k].p, crossings[k + 1].p});
    if (crossings[first].line & 1) {  // back the other way
      std::reverse(hatches.begin() + static_cast<std::ptrdiff_t>(begin), hatches.end());
      for (size_t k = begin; k < hatches.size(); ++k) std::swap(hatches[k].start, hatches[k].end);
    }
    first = last;
  }
  return hatches;
}

std::vector<Hatch> scan_layer(const ScanSetup& setup, size_t layer, LayerContours& contours) {
  if (setup.beam_offset > 0) {
    contours.loops = offset_inward(contours.loops, setup.beam_offset, 0.25 * setup.tolerance, setup.min_area);
    contours.vertices = 0;
    for (const Loop& loop : contours.loops) contours.vertices += loop.points.size();
  }
  if (!setup.hatch) return {};
  return hatch_loops(contours.loops, setup.hatch->spacing, setup.hatch->angle_of_layer(layer));
}

}  // namespace offsetgen::slice
